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

ECHOPLAN_KERNEL_CLONES void add_scaled(double* y, double scale, const double* x, std::size_t n) {
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) y[i] += scale * x[i];
}

ECHOPLAN_KERNEL_CLONES void sum_scaled_rows(double* y, std::size_t n, double start,
                                            const double* scales, const double* rows,
                                            std::size_t count, double* totals,
                                            const int* total_of) {
  // Eight columns at a time, held in registers while the rows are added to them in order.
  constexpr std::size_t kWidth = 8;
  std::size_t i = 0;
  for (; i + kWidth <= n; i += kWidth) {
    double sum[kWidth];
    for (double& s : sum) s = start;
    for (std::size_t r = 0; r < count; ++r) {
      const double scale = scales[r], *row = rows + r * n + i;
#pragma omp simd
      for (std::size_t j = 0; j < kWidth; ++j) sum[j] += scale * row[j];
    }
    for (std::size_t j = 0; j < kWidth; ++j) {
      y[i + j] = sum[j];
      totals[total_of[i + j]] += sum[j] - start;
    }
  }
  for (; i < n; ++i) {
    double sum = start;
    for (std::size_t r = 0; r < count; ++r) sum += scales[r] * rows[r * n + i];
    y[i] = sum;
    totals[total_of[i]] += sum - start;
  }
}

}  // namespace echoplan::solvers
