// The grouped expected entropy's inner loops (sensing_policy.cpp), in a file of their own so that
// they alone are compiled for speed: vectorised (OpenMP simd) with glibc's vector log (libmvec),
// which the compiler only calls under -ffast-math, and each built for AVX-512, AVX2 and any
// x86-64, the fastest the machine has picked when the program loads (GCC's target_clones; not under
// ThreadSanitizer, entropy_kernels.cpp says why).
//
// add_scaled() and sum_scaled_rows() are bit for bit the scalar loops' results on every machine
// (one multiply and one add per element, rows in order: the file is compiled with
// -ffp-contract=off and -fno-associative-math, so no build fuses or reorders them). sum_x_log_x()
// and dot() are not: the sum's order (and the last bits of each log) differ from a scalar loop's
// and between the builds, so their callers compare results with a margin (sensing_policy.cpp:
// 1e-12 between entropies, 1e-9 for a bound).
#pragma once

#include <cstddef>

namespace echoplan::solvers {

// Σ_i x[i] log x[i] over the x[i] > 0 (0 log 0 = 0; a probability a rounding error below 0 counts
// 0 too); finite.
double sum_x_log_x(const double* x, std::size_t n);
// Σ_i x[i] y[i], in an order of its own (as sum_x_log_x's).
double dot(const double* x, const double* y, std::size_t n);
// y[i] += scale * x[i] for i < n.
void add_scaled(double* y, double scale, const double* x, std::size_t n);
// y[i] = start + scales[0] * rows[i] + scales[1] * rows[n + i] + ... over `count` rows, added in
// that order, and totals[total_of[i]] += y[i] − start (the total_of[i] distinct): one call for a
// small block, whose rows are too short for a call each.
void sum_scaled_rows(double* y, std::size_t n, double start, const double* scales,
                     const double* rows, std::size_t count, double* totals, const int* total_of);

}  // namespace echoplan::solvers
