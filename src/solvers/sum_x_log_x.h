// Σ x log x over an array (0 log 0 = 0): the grouped expected entropy's inner loop
// (sensing_policy.cpp), in a file of its own so that it alone is compiled for speed: vectorised,
// with glibc's vector log (libmvec), which the compiler only calls under -ffast-math. The sum's
// order and the last bits of each log differ from a scalar loop's; the values are finite and >= 0.
#pragma once

#include <cstddef>

namespace echoplan::solvers {

double sum_x_log_x(const double* x, std::size_t n);

}  // namespace echoplan::solvers
