#include "solvers/offline/dense_pomdp.h"

#include <fmt/core.h>

#include <cmath>

#include "common/error.h"

namespace echoplan::solvers::offline {

namespace {

// Rows written by hand in problem files carry a few decimals; 1e-6 accepts rounding, not mistakes.
constexpr double kRowSumTolerance = 1e-6;

void check_row(const std::string& source, double sum, const std::string& what) {
  if (std::abs(sum - 1.0) > kRowSumTolerance) {
    throw InputError(source, 0, fmt::format("{} sums to {:.9g}, not 1", what, sum));
  }
}

void check_probability(const std::string& source, double p, const std::string& what) {
  if (!(p >= 0.0 && p <= 1.0 + kRowSumTolerance)) {
    throw InputError(source, 0, fmt::format("{} is {:.9g}, not a probability", what, p));
  }
}

}  // namespace

DensePomdp make_dense_pomdp(const pomdp::TabularModel& model, const std::string& source) {
  DensePomdp d;
  d.num_states = model.num_states();
  d.num_actions = model.num_actions();
  d.num_observations = model.num_observations();
  d.discount = model.discount();
  if (d.num_states <= 0 || d.num_actions <= 0 || d.num_observations <= 0) {
    throw InputError(source, 0,
                     fmt::format("the model needs at least one state, action and observation "
                                 "(has {}, {}, {})",
                                 d.num_states, d.num_actions, d.num_observations));
  }
  if (!(d.discount > 0.0 && d.discount < 1.0)) {
    throw InputError(source, 0,
                     fmt::format("discount {} is outside (0, 1); the offline solver needs a "
                                 "discount below 1",
                                 d.discount));
  }
  const int S = d.num_states, A = d.num_actions, O = d.num_observations;

  d.terminal.resize(S);
  for (int s = 0; s < S; ++s) d.terminal[s] = model.terminal(s) ? 1 : 0;

  // Rewards and transitions; terminal states are forced absorbing at zero reward (see header).
  d.reward.assign(static_cast<std::size_t>(S) * A, 0.0);
  d.successors.resize(static_cast<std::size_t>(S) * A);
  for (int s = 0; s < S; ++s) {
    for (int a = 0; a < A; ++a) {
      auto& row = d.successors[s * A + a];
      if (d.terminal[s]) {
        row.push_back({s, 1.0});
        continue;
      }
      d.reward[s * A + a] = model.reward(s, a);
      if (!std::isfinite(d.reward[s * A + a])) {
        throw InputError(source, 0,
                         fmt::format("reward of state {} action {} is not finite", s, a));
      }
      double sum = 0.0;
      for (int s2 = 0; s2 < S; ++s2) {
        const double p = model.transition(s, a, s2);
        check_probability(source, p, fmt::format("P(s'={} | s={}, a={})", s2, s, a));
        if (p > 0.0) row.push_back({s2, p});
        sum += p;
      }
      check_row(source, sum, fmt::format("the transition row of state {} action {}", s, a));
    }
  }

  // Observations: every (a, s') row must be a distribution, even for terminal s' (the filter uses
  // it).
  d.observation.resize(static_cast<std::size_t>(A) * S * O);
  for (int a = 0; a < A; ++a) {
    for (int s2 = 0; s2 < S; ++s2) {
      double sum = 0.0;
      for (int o = 0; o < O; ++o) {
        const double p = model.observation(a, s2, o);
        check_probability(source, p, fmt::format("P(o={} | s'={}, a={})", o, s2, a));
        d.observation[(static_cast<std::size_t>(a) * S + s2) * O + o] = p;
        sum += p;
      }
      check_row(source, sum, fmt::format("the observation row of action {} state {}", a, s2));
    }
  }

  d.initial_belief = model.initial_belief();
  if (static_cast<int>(d.initial_belief.size()) != S) {
    throw InputError(
        source, 0,
        fmt::format("the initial belief has {} entries for {} states", d.initial_belief.size(), S));
  }
  double sum = 0.0;
  for (int s = 0; s < S; ++s) {
    check_probability(source, d.initial_belief[s], fmt::format("initial belief of state {}", s));
    sum += d.initial_belief[s];
  }
  check_row(source, sum, "the initial belief");
  return d;
}

}  // namespace echoplan::solvers::offline
