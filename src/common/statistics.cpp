#include "common/statistics.h"

#include <cmath>

namespace echoplan {

double student_t_975(int df) {
  // t(0.975, df) for df = 1..30, from the standard tables.
  static constexpr double kTable[30] = {
      12.706204736, 4.302652730, 3.182446305, 2.776445105, 2.570581836, 2.446911851,
      2.364624252,  2.306004135, 2.262157163, 2.228138852, 2.200985160, 2.178812830,
      2.160368656,  2.144786688, 2.131449546, 2.119905299, 2.109815578, 2.100922040,
      2.093024054,  2.085963447, 2.079613845, 2.073873068, 2.068657610, 2.063898562,
      2.059538553,  2.055529439, 2.051829142, 2.048407142, 2.045229642, 2.042272456};
  if (df < 1) df = 1;
  if (df <= 30) return kTable[df - 1];
  // Cornish-Fisher expansion of the t quantile in powers of 1/df (Abramowitz & Stegun 26.7.5).
  const double z = 1.959963984540054, v = df;
  const double z2 = z * z, z3 = z2 * z, z5 = z3 * z2, z7 = z5 * z2, z9 = z7 * z2;
  return z + (z3 + z) / (4 * v) + (5 * z5 + 16 * z3 + 3 * z) / (96 * v * v) +
         (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384 * v * v * v) +
         (79 * z9 + 776 * z7 + 1482 * z5 - 1920 * z3 - 945 * z) / (92160 * v * v * v * v);
}

MeanInterval mean_ci95(const std::vector<double>& values) {
  MeanInterval m;
  m.n = static_cast<int>(values.size());
  if (m.n == 0) return m;
  double sum = 0.0;
  for (double x : values) sum += x;
  m.mean = sum / m.n;
  if (m.n < 2) return m;
  double squares = 0.0;
  for (double x : values) squares += (x - m.mean) * (x - m.mean);
  m.sd = std::sqrt(squares / (m.n - 1));
  m.half_width = student_t_975(m.n - 1) * m.sd / std::sqrt(static_cast<double>(m.n));
  return m;
}

}  // namespace echoplan
