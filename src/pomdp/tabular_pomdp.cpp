#include "pomdp/tabular_pomdp.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pomdp/distribution.h"

namespace echoplan::pomdp {

namespace {

void check_distribution(const double* p, int n, const std::string& what) {
  const RowCheck c = check_row(p, static_cast<std::size_t>(n));
  if (!c.in_range) throw std::invalid_argument(what + " has an entry outside [0, 1]");
  if (!c.ok()) throw std::invalid_argument(what + " does not sum to 1");
}

}  // namespace

TabularPomdp::TabularPomdp(TabularPomdpData data)
    : data_(std::move(data)),
      num_states_(static_cast<int>(data_.state_names.size())),
      num_actions_(static_cast<int>(data_.action_names.size())),
      num_observations_(static_cast<int>(data_.observation_names.size())) {
  const std::size_t s = num_states_, a = num_actions_, o = num_observations_;
  if (s == 0 || a == 0 || o == 0)
    throw std::invalid_argument("a POMDP needs states, actions and observations");
  if (!(data_.discount > 0.0 && data_.discount < 1.0))
    throw std::invalid_argument("discount must be in (0, 1)");
  if (data_.transition.size() != a * s * s || data_.observation.size() != a * s * o ||
      data_.reward.size() != s * a || data_.start.size() != s) {
    throw std::invalid_argument("POMDP tables have the wrong sizes");
  }
  for (int ai = 0; ai < num_actions_; ++ai) {
    for (int si = 0; si < num_states_; ++si) {
      check_distribution(&data_.transition[(ai * s + si) * s], num_states_,
                         "T row (" + data_.action_names[ai] + ", " + data_.state_names[si] + ")");
      check_distribution(&data_.observation[(ai * s + si) * o], num_observations_,
                         "O row (" + data_.action_names[ai] + ", " + data_.state_names[si] + ")");
    }
  }
  check_distribution(data_.start.data(), num_states_, "start belief");

  spec_.name = data_.name;
  spec_.action_names = data_.action_names;
  spec_.state.discrete_names = {"state"};
  spec_.state.discrete_value_names = {data_.state_names};
  spec_.observation.discrete = true;
  spec_.observation.names = data_.observation_names;
  spec_.discount = data_.discount;
  spec_.min_reward = *std::min_element(data_.reward.begin(), data_.reward.end());
  spec_.max_reward = *std::max_element(data_.reward.begin(), data_.reward.end());

  // Absorbing states: every action keeps the state with probability 1 and pays nothing.
  absorbing_.assign(s, false);
  for (int si = 0; si < num_states_; ++si) {
    bool absorbing = true;
    for (int ai = 0; ai < num_actions_ && absorbing; ++ai) {
      absorbing = transition(si, ai, si) == 1.0 && reward(si, ai) == 0.0;
    }
    absorbing_[si] = absorbing;
  }

  // MDP value iteration for the heuristic, to 1e-6 in sup norm (the contraction bound gives the
  // stopping rule); problems this format holds are small enough for dense sweeps.
  mdp_value_.assign(s, 0.0);
  std::vector<double> next(s);
  const double stop = 1e-6 * (1.0 - data_.discount) / data_.discount;
  for (int iter = 0; iter < 100000; ++iter) {
    double change = 0.0;
    for (int si = 0; si < num_states_; ++si) {
      double best = -1e300;
      for (int ai = 0; ai < num_actions_; ++ai) {
        double q = 0.0;
        for (int sj = 0; sj < num_states_; ++sj) q += transition(si, ai, sj) * mdp_value_[sj];
        best = std::max(best, reward(si, ai) + data_.discount * q);
      }
      next[si] = absorbing_[si] ? 0.0 : best;
      change = std::max(change, std::abs(next[si] - mdp_value_[si]));
    }
    mdp_value_.swap(next);
    if (change <= stop) break;
  }
}

State TabularPomdp::sample_initial_state(Rng& rng) const {
  return State{{}, {sample_index(data_.start.data(), num_states_, uniform01(rng))}};
}

StepResult TabularPomdp::step(const State& state, int action, Rng& rng) const {
  const int s = state.discrete[0];
  StepResult r;
  const double* t_row =
      &data_.transition[(static_cast<std::size_t>(action) * num_states_ + s) * num_states_];
  const int s_next = sample_index(t_row, num_states_, uniform01(rng));
  const double* o_row =
      &data_.observation[(static_cast<std::size_t>(action) * num_states_ + s_next) *
                         num_observations_];
  r.next.discrete = {s_next};
  r.observation.index = sample_index(o_row, num_observations_, uniform01(rng));
  r.reward = reward(s, action);
  r.terminal = absorbing_[s_next];
  return r;
}

double TabularPomdp::observation_likelihood(const State& next_state, int action,
                                            const Observation& observation) const {
  const int o = observation.index;
  if (o < 0 || o >= num_observations_ || action < 0 || action >= num_actions_) return 0.0;
  return TabularPomdp::observation(action, next_state.discrete[0], o);
}

double TabularPomdp::heuristic_value(const State& state) const {
  return mdp_value_[state.discrete[0]];
}

}  // namespace echoplan::pomdp
