#include "solvers/offline/point_based_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "solvers/offline/belief_expansion.h"
#include "solvers/offline/initial_bounds.h"

namespace echoplan::solvers::offline {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

PointBasedSolver::PointBasedSolver(std::shared_ptr<const FlatPomdp> pomdp, SolverOptions options)
    : pomdp_(std::move(pomdp)),
      options_(options),
      upper_(fast_informed_bound(*pomdp_), value_span(*pomdp_)),
      rng_(derive_seed(options.seed, {0x0ff1})) {
  for (AlphaVector& v : blind_policy_vectors(*pomdp_)) lower_.add(std::move(v));
}

Bounds PointBasedSolver::bounds(const BeliefVector& belief) const {
  return {lower_.value(belief), upper_.value(belief)};
}

std::vector<Bounds> PointBasedSolver::action_bounds(const BeliefVector& belief) const {
  const FlatPomdp& m = *pomdp_;
  std::vector<Bounds> out(m.num_actions);
  for (int a = 0; a < m.num_actions; ++a) {
    const BeliefExpansion children = expand(m, belief, a);
    double lower = 0.0, upper = 0.0;
    for (int o = 0; o < m.num_observations; ++o) {
      const double p = children.observation_probability[o];
      if (p == 0.0) continue;
      lower += p * lower_.value(children.next_belief[o]);
      upper += p * upper_.value(children.next_belief[o]);
    }
    const double r = expected_reward(m, belief, a);
    out[a] = {r + m.discount * lower, r + m.discount * upper};
  }
  return out;
}

bool PointBasedSolver::backup(const BeliefVector& belief) {
  const FlatPomdp& m = *pomdp_;
  const int S = m.num_states, O = m.num_observations;
  double best_upper = -std::numeric_limits<double>::infinity();
  double best_lower = -std::numeric_limits<double>::infinity();
  AlphaVector best_vector;
  std::vector<int> chosen(O);
  for (int a = 0; a < m.num_actions; ++a) {
    const BeliefExpansion children = expand(m, belief, a);
    // Upper: Bellman backup of the upper bound's values at the children.
    double upper_future = 0.0;
    for (int o = 0; o < O; ++o) {
      const double p = children.observation_probability[o];
      if (p > 0.0) upper_future += p * upper_.value(children.next_belief[o]);
      // Lower: the best vector at each child (for impossible observations, at the prediction).
      chosen[o] = lower_.best_index(children.next_belief[o]);
    }
    best_upper = std::max(best_upper, expected_reward(m, belief, a) + m.discount * upper_future);

    // The backed-up vector: alpha(s) = R(s,a) + g sum_s' P(s'|s,a) sum_o P(o|s',a) alpha_o(s').
    AlphaVector candidate{a, std::vector<double>(S, 0.0)};
    for (int s = 0; s < S; ++s) {
      if (m.terminal[s]) continue;  // exactly 0
      double future = 0.0;
      for (const Successor& n : m.successors_of(s, a)) {
        const double* z = m.observation_row(a, n.state);
        double expected = 0.0;
        for (int o = 0; o < O; ++o) {
          if (z[o] != 0.0) expected += z[o] * lower_.vectors()[chosen[o]].values[n.state];
        }
        future += n.probability * expected;
      }
      candidate.values[s] = m.reward_at(s, a) + m.discount * future;
    }
    const double v = dot(candidate.values, belief);
    if (v > best_lower) {
      best_lower = v;
      best_vector = std::move(candidate);
    }
  }
  // Keep the new vector only when it raises the bound at this belief (beyond rounding).
  bool improved = false;
  if (best_lower > lower_.value(belief) + 1e-12) improved = lower_.add(std::move(best_vector));
  improved |= upper_.add(belief, best_upper);
  ++backups_;
  return improved;
}

double PointBasedSolver::target_gap() const {
  const Bounds b = bounds(pomdp_->initial_belief);
  return options_.epsilon * std::max({1.0, std::abs(b.lower), std::abs(b.upper)});
}

void PointBasedSolver::trial(double target_gap) {
  const FlatPomdp& m = *pomdp_;
  std::vector<BeliefVector> path{m.initial_belief};
  // HSVI's width test: at depth t the gap needed shrinks with gamma^t, i.e. the allowance grows.
  double allowance = target_gap;
  // gamma^t P(path): how much this belief's gap counts at the root.
  double weight = 1.0;
  while (static_cast<int>(path.size()) <= options_.max_depth) {
    const BeliefVector& b = path.back();
    const Bounds here = bounds(b);
    const double gap = here.upper - here.lower;
    if (gap <= allowance || weight * gap <= path_weight_fraction_ * target_gap) break;

    // The action that looks best under the upper bound (optimism drives exploration).
    int action = 0;
    double best_q = -std::numeric_limits<double>::infinity();
    std::vector<BeliefExpansion> expansions;
    expansions.reserve(m.num_actions);
    for (int a = 0; a < m.num_actions; ++a) {
      expansions.push_back(expand(m, b, a));
      double q = expected_reward(m, b, a);
      for (int o = 0; o < m.num_observations; ++o) {
        const double p = expansions[a].observation_probability[o];
        if (p > 0.0) q += m.discount * p * upper_.value(expansions[a].next_belief[o]);
      }
      if (q > best_q) {
        best_q = q;
        action = a;
      }
    }
    // The observation: drawn in proportion to the probability-weighted excess uncertainty of its
    // child; when no child has excess left, the one closest to having some.
    const double next_allowance = allowance / m.discount;
    int observation = -1;
    double best_excess = 0.0, total_excess = 0.0;
    std::vector<double> excess(m.num_observations, 0.0);
    for (int o = 0; o < m.num_observations; ++o) {
      const double p = expansions[action].observation_probability[o];
      if (p == 0.0) continue;
      const Bounds child = bounds(expansions[action].next_belief[o]);
      const double e = p * (child.upper - child.lower - next_allowance);
      if (e > 0.0) {
        excess[o] = e;
        total_excess += e;
      }
      if (observation < 0 || e > best_excess) {
        best_excess = e;
        observation = o;
      }
    }
    if (total_excess > 0.0) {
      double u = uniform01(rng_) * total_excess;
      for (int o = 0; o < m.num_observations; ++o) {
        if (excess[o] == 0.0) continue;
        observation = o;
        if (u < excess[o]) break;
        u -= excess[o];
      }
    }
    weight *= m.discount * expansions[action].observation_probability[observation];
    path.push_back(std::move(expansions[action].next_belief[observation]));
    allowance = next_allowance;
  }
  // Back up from the deepest belief to the root so improvements travel upward in one pass.
  bool improved = false;
  for (auto it = path.rbegin(); it != path.rend(); ++it) improved |= backup(*it);
  // A trial that improved nothing stopped too shallow: let later trials go deeper. Down to 0 this
  // is HSVI's own rule, so the solver keeps its convergence guarantee.
  if (!improved) path_weight_fraction_ /= 4.0;
  ++trials_;
}

SolverProgress PointBasedSolver::progress() const {
  SolverProgress p;
  p.root = bounds(pomdp_->initial_belief);
  p.target_gap = target_gap();
  p.trials = trials_;
  p.backups = backups_;
  p.alpha_vectors = lower_.size();
  p.upper_points = upper_.num_points();
  p.seconds = seconds_;
  p.converged = p.root.upper - p.root.lower <= p.target_gap;
  return p;
}

SolverProgress PointBasedSolver::solve(const ProgressCallback& on_progress) {
  const Clock::time_point start = Clock::now();
  const double seconds_before = seconds_;
  const long trials_before = trials_;
  double next_report = options_.progress_interval_seconds;
  while (true) {
    const double gap = target_gap();
    const Bounds root = bounds(pomdp_->initial_belief);
    seconds_ = seconds_before + seconds_since(start);
    if (root.upper - root.lower <= gap) break;
    if (options_.time_limit_seconds > 0.0 && seconds_since(start) >= options_.time_limit_seconds)
      break;
    if (options_.max_trials > 0 && trials_ - trials_before >= options_.max_trials) break;
    trial(gap);
    if (on_progress && seconds_since(start) >= next_report) {
      seconds_ = seconds_before + seconds_since(start);
      on_progress(progress());
      next_report += options_.progress_interval_seconds;
    }
  }
  return progress();
}

}  // namespace echoplan::solvers::offline
