#include "solvers/entropy_kernels.h"

#include <cmath>

// The loader runs the resolver that picks a clone before ThreadSanitizer's runtime is ready (the
// program crashes at start): a TSan build has the plain x86-64 build alone.
#if defined(__SANITIZE_THREAD__)
#define ECHOPLAN_KERNEL_CLONES
#else
#define ECHOPLAN_KERNEL_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#endif

namespace echoplan::solvers {

ECHOPLAN_KERNEL_CLONES double sum_x_log_x(const double* x, std::size_t n) {
  double sum = 0.0;
  // log 1 = 0, so a term x <= 0 is 0 without a branch.
#pragma omp simd reduction(+ : sum)
  for (std::size_t i = 0; i < n; ++i) sum += x[i] * std::log(x[i] > 0.0 ? x[i] : 1.0);
  return sum;
}

ECHOPLAN_KERNEL_CLONES double dot(const double* x, const double* y, std::size_t n) {
  double sum = 0.0;
#pragma omp simd reduction(+ : sum)
  for (std::size_t i = 0; i < n; ++i) sum += x[i] * y[i];
  return sum;
}

ECHOPLAN_KERNEL_CLONES void add_scaled(double* y, double scale, const double* x, std::size_t n) {
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) y[i] += scale * x[i];
}

namespace {
// sum_scaled_rows() on `width` columns from column i, held in registers while the rows are added
// to them in order.
template <std::size_t width>
inline void sum_scaled_columns(double* y, std::size_t n, std::size_t i, double start,
                               const double* scales, const double* rows, std::size_t count,
                               double* totals, const int* total_of) {
  double sum[width];
  for (double& s : sum) s = start;
  for (std::size_t r = 0; r < count; ++r) {
    const double scale = scales[r], *row = rows + r * n + i;
#pragma omp simd
    for (std::size_t j = 0; j < width; ++j) sum[j] += scale * row[j];
  }
  for (std::size_t j = 0; j < width; ++j) {
    y[i + j] = sum[j];
    totals[total_of[i + j]] += sum[j] - start;
  }
}
}  // namespace

ECHOPLAN_KERNEL_CLONES void sum_scaled_rows(double* y, std::size_t n, double start,
                                            const double* scales, const double* rows,
                                            std::size_t count, double* totals,
                                            const int* total_of) {
  // Eight columns at a time, then four, then one.
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
    sum_scaled_columns<8>(y, n, i, start, scales, rows, count, totals, total_of);
  for (; i + 4 <= n; i += 4)
    sum_scaled_columns<4>(y, n, i, start, scales, rows, count, totals, total_of);
  for (; i < n; ++i) sum_scaled_columns<1>(y, n, i, start, scales, rows, count, totals, total_of);
}

}  // namespace echoplan::solvers
