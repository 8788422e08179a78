// The sample mean and its 95% confidence interval, the one place the project computes them (trial
// summaries, certify, benchmarks), so every reported "± x" means the same thing.
#pragma once

#include <vector>

namespace echoplan {

// The 0.975 quantile of Student's t distribution with `degrees_of_freedom` >= 1: the factor that
// turns a standard error into a two-sided 95% half-width. Exact to 9 digits for 1-30 degrees of
// freedom (tabulated), within 1e-6 beyond (Cornish-Fisher expansion around the normal 1.959964).
double student_t_975(int degrees_of_freedom);

struct MeanInterval {
  int n = 0;
  double mean = 0.0;
  double sd = 0.0;          // sample standard deviation (n - 1); 0 when n < 2
  double half_width = 0.0;  // t(0.975, n - 1) · sd / sqrt(n); 0 when n < 2 (no interval)
};

// Mean and 95% CI half-width of `values` (empty: all zero).
MeanInterval mean_ci95(const std::vector<double>& values);

}  // namespace echoplan
