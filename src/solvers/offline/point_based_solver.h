// HSVI2-style offline point-based solver (Smith & Simmons 2005) for small discrete POMDPs.
//
// It keeps a lower bound (alpha vectors, from the blind policy up) and an upper bound (sawtooth
// over belief points, from the fast informed bound down) on the optimal value V*, and tightens both
// by depth-first trials from b0: each step takes the action that is best under the upper bound and
// an observation drawn in proportion to its probability-weighted excess uncertainty (HSVI takes the
// largest; drawing keeps trials from retracing one path, as SARSOP's sampling does), then backs
// both bounds up along the path. Trials also stop where a belief can hardly matter at b0 (see
// below). It stops when the gap at b0 is at most epsilon * max(1, |V|) or at the time limit.
//
// Units: values are expected discounted rewards in the model's reward units; times are seconds.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "common/rng.h"
#include "solvers/alpha_vector_set.h"
#include "solvers/bounds.h"
#include "solvers/offline/flat_pomdp.h"
#include "solvers/sawtooth_upper_bound.h"

namespace echoplan::solvers::offline {

struct SolverOptions {
  // Target gap at b0, relative: stop when upper - lower <= epsilon * max(1, |lower|, |upper|).
  double epsilon = 1e-4;
  // Wall-clock limit in seconds for solve(); <= 0 means none.
  double time_limit_seconds = 60.0;
  // Stop after this many trials in one solve() call; <= 0 means no limit. Unlike the time limit,
  // this gives the same result on every machine.
  long max_trials = 0;
  // A trial never goes deeper than this many steps (a guard against very long trials).
  int max_depth = 5000;
  // Seconds between progress reports.
  double progress_interval_seconds = 1.0;
  // Seed of the solver's own random stream (which observation a trial follows). The same seed and
  // the same stopping point give the same bounds and policy.
  std::uint64_t seed = 1;
};

// A snapshot of the solver, reported while it runs and returned at the end.
struct SolverProgress {
  Bounds root;              // at b0
  double target_gap = 0.0;  // the absolute gap solve() aims for
  long trials = 0;
  long backups = 0;
  std::size_t alpha_vectors = 0;
  std::size_t upper_points = 0;
  double seconds = 0.0;
  bool converged = false;  // root gap <= target gap
};

class PointBasedSolver {
 public:
  using ProgressCallback = std::function<void(const SolverProgress&)>;

  // Initialises the bounds (blind policy, fast informed bound). The tables are shared, never
  // changed.
  PointBasedSolver(std::shared_ptr<const FlatPomdp> pomdp, SolverOptions options = {});

  // Runs trials until the target gap or the time limit. May be called again to continue.
  SolverProgress solve(const ProgressCallback& on_progress = {});

  Bounds bounds(const BeliefVector& belief) const;
  // Per action a: bounds on Q*(b, a) = R(b, a) + g sum_o P(o | b, a) V*(b_ao), by one-step
  // lookahead on the current bounds. Used to measure the loss of a decision against the optimum.
  std::vector<Bounds> action_bounds(const BeliefVector& belief) const;
  // The first action of the best lower-bound plan at `belief`: acting on it earns at least
  // bounds(belief).lower.
  int best_action(const BeliefVector& belief) const { return lower_.best_action(belief); }

  const AlphaVectorSet& lower_bound() const { return lower_; }
  const SawtoothUpperBound& upper_bound() const { return upper_; }
  const FlatPomdp& pomdp() const { return *pomdp_; }
  SolverProgress progress() const;

 private:
  // One HSVI trial from b0 aiming at `target_gap`; backs up every belief on its path.
  void trial(double target_gap);
  // Bellman backups of both bounds at `belief`; true when either bound improved.
  bool backup(const BeliefVector& belief);
  double target_gap() const;

  std::shared_ptr<const FlatPomdp> pomdp_;
  SolverOptions options_;
  AlphaVectorSet lower_;
  SawtoothUpperBound upper_;
  // A trial also stops where gamma^t P(path) * gap <= this fraction of the target gap: beliefs that
  // hardly matter at b0 (long runs of contradicting observations) are not refined. Lowered whenever
  // a trial improves nothing.
  double path_weight_fraction_ = 0.1;
  // Draws the observation each trial step follows (see trial()).
  Rng rng_;
  long trials_ = 0;
  long backups_ = 0;
  double seconds_ = 0.0;
};

}  // namespace echoplan::solvers::offline
