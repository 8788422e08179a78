// Where the bounds start: the blind-policy lower bound and the fast informed upper bound
// (Hauskrecht 2000). Both are iterated from a trivially valid start, monotonically, so every
// iterate is itself a valid bound; iteration only tightens them.
#pragma once

#include <vector>

#include "solvers/alpha_vector_set.h"
#include "solvers/offline/flat_pomdp.h"

namespace echoplan::solvers::offline {

struct InitialBoundOptions {
  // Stop iterating when no entry moves by more than this (reward units).
  double tolerance = 1e-9;
  int max_iterations = 100000;
};

// For each action a, the value of repeating a forever (terminal states 0): alpha_a <= R_a + g T_a
// alpha_a, so a greedy policy on these vectors earns at least their value.
std::vector<AlphaVector> blind_policy_vectors(const FlatPomdp& pomdp,
                                              const InitialBoundOptions& options = {});

// The fast informed bound Q_FIB[a][s] >= Q*(b, a) restricted to corners, and max_a Q_FIB[a] . b >=
// V*(b):
//   Q(s,a) = R(s,a) + g sum_o max_a' sum_s' P(s'|s,a) P(o|s',a) Q(s',a').
std::vector<std::vector<double>> fast_informed_bound(const FlatPomdp& pomdp,
                                                     const InitialBoundOptions& options = {});

// An upper bound on max_s alpha(s) - min_s alpha(s) for the value vector of any policy:
// (max(0, R_max) - min(0, R_min)) / (1 - discount), terminal states earning 0.
double value_span(const FlatPomdp& pomdp);

}  // namespace echoplan::solvers::offline
