// A discrete POMDP held as dense tables, usable both as explicit tables (TabularModel: exact
// belief, offline solver) and as a generative model (Model: online solvers, particle belief).
//
// As a Model: the state is discrete[0] = state index (no continuous part); observations are
// symbol indices; step() samples s' from T(s, a, .) and o from O(a, s', .) and returns the
// expected reward R(s, a); it is terminal when s' is absorbing (every action leaves it unchanged
// at zero reward, the rule Cassandra files use for goal states).
#pragma once

#include <string>
#include <vector>

#include "pomdp/model.h"

namespace echoplan::pomdp {

// The tables, sized S, A, O. Invariants (checked by TabularPomdp's constructor): every T row and
// O row is a distribution (within 1e-6), the start belief is a distribution, 0 < discount < 1.
struct TabularPomdpData {
  std::string name;
  std::vector<std::string> state_names;        // S names
  std::vector<std::string> action_names;       // A names
  std::vector<std::string> observation_names;  // O names
  double discount = 0.95;
  std::vector<double> transition;   // [(a * S + s) * S + s'] = P(s' | s, a)
  std::vector<double> observation;  // [(a * S + s') * O + o] = P(o | s', a)
  std::vector<double> reward;       // [s * A + a] = expected immediate reward R(s, a)
  std::vector<double> start;        // S initial probabilities
};

class TabularPomdp final : public Model, public TabularModel {
 public:
  // Throws std::invalid_argument when the invariants above do not hold.
  explicit TabularPomdp(TabularPomdpData data);

  // Model
  const ModelSpec& spec() const override { return spec_; }
  State sample_initial_state(Rng& rng) const override;
  StepResult step(const State& state, int action, Rng& rng) const override;
  double observation_likelihood(const State& next_state, int action,
                                const Observation& observation) const override;
  // The MDP value of the state (as if it were observed from now on), computed by value iteration
  // at construction; an upper bound on the value of any belief concentrated on that state.
  double heuristic_value(const State& state) const override;
  const TabularModel* tabular() const override { return this; }

  // TabularModel
  int num_states() const override { return num_states_; }
  int num_actions() const override { return num_actions_; }
  int num_observations() const override { return num_observations_; }
  double transition(int s, int a, int s_next) const override {
    return data_.transition[(static_cast<std::size_t>(a) * num_states_ + s) * num_states_ + s_next];
  }
  double observation(int a, int s_next, int o) const override {
    return data_
        .observation[(static_cast<std::size_t>(a) * num_states_ + s_next) * num_observations_ + o];
  }
  double reward(int s, int a) const override {
    return data_.reward[static_cast<std::size_t>(s) * num_actions_ + a];
  }
  bool terminal(int s) const override { return absorbing_[s]; }
  double discount() const override { return data_.discount; }
  std::vector<double> initial_belief() const override { return data_.start; }

  const TabularPomdpData& data() const { return data_; }

 private:
  TabularPomdpData data_;
  ModelSpec spec_;
  int num_states_, num_actions_, num_observations_;
  std::vector<bool> absorbing_;
  std::vector<double> mdp_value_;
};

}  // namespace echoplan::pomdp
