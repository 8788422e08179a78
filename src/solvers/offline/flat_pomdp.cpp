#include "solvers/offline/flat_pomdp.h"

#include <fmt/core.h>

#include <cmath>

#include "common/error.h"
#include "pomdp/distribution.h"

namespace echoplan::solvers::offline {

namespace {

// One probability row checked by the project's rule (pomdp/distribution.h), reported with what it
// is.
void require_distribution(const std::string& source, const std::vector<double>& row,
                          const std::string& what, const std::string& entry_name) {
  const pomdp::RowCheck check = pomdp::check_row(row.data(), row.size());
  if (check.ok()) return;
  if (!check.in_range) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (!(row[i] >= 0.0 && row[i] <= 1.0 + pomdp::kProbabilityTolerance)) {
        throw InputError(source, 0,
                         fmt::format("{} of {} is {:.9g}, not a probability",
                                     fmt::format(fmt::runtime(entry_name), i), what, row[i]));
      }
    }
  }
  throw InputError(source, 0, fmt::format("{} sums to {:.9g}, not 1", what, check.sum));
}

}  // namespace

FlatPomdp make_flat_pomdp(const pomdp::TabularModel& model, const std::string& source) {
  FlatPomdp d;
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
      std::vector<double> probabilities(S);
      for (int s2 = 0; s2 < S; ++s2) {
        probabilities[s2] = model.transition(s, a, s2);
        if (probabilities[s2] > 0.0) row.push_back({s2, probabilities[s2]});
      }
      require_distribution(source, probabilities,
                           fmt::format("the transition row of state {} action {}", s, a),
                           "P(s'={})");
    }
  }

  // Observations: every (a, s') row must be a distribution, even for terminal s' (the filter uses
  // it).
  d.observation.resize(static_cast<std::size_t>(A) * S * O);
  for (int a = 0; a < A; ++a) {
    for (int s2 = 0; s2 < S; ++s2) {
      std::vector<double> probabilities(O);
      for (int o = 0; o < O; ++o) {
        probabilities[o] = model.observation(a, s2, o);
        d.observation[(static_cast<std::size_t>(a) * S + s2) * O + o] = probabilities[o];
      }
      require_distribution(source, probabilities,
                           fmt::format("the observation row of action {} state {}", a, s2),
                           "P(o={})");
    }
  }

  d.initial_belief = model.initial_belief();
  if (static_cast<int>(d.initial_belief.size()) != S) {
    throw InputError(
        source, 0,
        fmt::format("the initial belief has {} entries for {} states", d.initial_belief.size(), S));
  }
  require_distribution(source, d.initial_belief, "the initial belief", "the entry of state {}");
  return d;
}

}  // namespace echoplan::solvers::offline
