// Small models for the solver and experiment tests, written against pomdp/model.h so these tests do
// not depend on the problem loader.
//
//   ToyTiger          Kaelbling, Littman & Cassandra's tiger (discount 0.95, listening accuracy
//   0.85);
//                     opening a door resets the tiger uniformly. V*(uniform) = 19.371.
//   ToyAudioObjects   the seed's problem (section 3.3): 4 objects, slide / strike / move_to_A /
//                     move_to_B, the observation table exactly, discount 0.99. V*(b0) = 2.9534.
//   ToyParticleBelief a plain SIR particle filter over any model (the tests' stand-in for the
//                     pomdp module's beliefs).
//   ToyEnvironment    the model as the world.
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "pomdp/belief.h"
#include "pomdp/environment.h"
#include "pomdp/model.h"

namespace echoplan::testing {

inline int sample_index(const double* probabilities, int n, Rng& rng) {
  double u = uniform01(rng);
  for (int i = 0; i < n - 1; ++i) {
    if (u < probabilities[i]) return i;
    u -= probabilities[i];
  }
  return n - 1;
}

class ToyAudioObjects final : public pomdp::Model {
 public:
  static constexpr int slide = 0, strike = 1, move_to_A = 2, move_to_B = 3;
  // P(o | object, action) for the sensing actions, seed section 3.3.
  static constexpr double table[2][4][4] = {{{0.5, 0.3, 0.15, 0.05},
                                             {0.11, 0.67, 0.11, 0.11},
                                             {0.11, 0.11, 0.67, 0.11},
                                             {0.01, 0.01, 0.48, 0.5}},
                                            {{0.6, 0.05, 0.3, 0.05},
                                             {0.05, 0.6, 0.3, 0.05},
                                             {0.11, 0.11, 0.67, 0.11},
                                             {0.11, 0.11, 0.11, 0.67}}};

  ToyAudioObjects() {
    spec_.name = "toy_audio_objects";
    spec_.action_names = {"slide", "strike", "move_to_A", "move_to_B"};
    spec_.state.discrete_names = {"object"};
    spec_.state.discrete_value_names = {
        {"pringles_can", "coffee_mug", "plastic_cup", "paper_base"}};
    spec_.observation.names = {"O0", "O1", "O2", "O3"};
    spec_.discount = 0.99;
    spec_.min_reward = -100;
    spec_.max_reward = 10;
  }
  const pomdp::ModelSpec& spec() const override { return spec_; }
  pomdp::State sample_initial_state(Rng& rng) const override {
    return {{}, {static_cast<int>(uniform01(rng) * 4)}};
  }
  pomdp::StepResult step(const pomdp::State& s, int a, Rng& rng) const override {
    pomdp::StepResult r;
    r.next = s;
    const int object = s.discrete[0];
    if (a == slide || a == strike) {
      r.reward = -1;
      r.observation.index = sample_index(table[a][object], 4, rng);
    } else {
      const bool goes_to_A = object == 0 || object == 2;
      r.reward = (goes_to_A == (a == move_to_A)) ? 10 : -100;
      r.terminal = true;
      r.observation.index = 0;
    }
    return r;
  }
  double observation_likelihood(const pomdp::State& s, int a,
                                const pomdp::Observation& o) const override {
    if (a == slide || a == strike) return table[a][s.discrete[0]][o.index];
    return o.index == 0 ? 1.0 : 0.0;
  }
  // Perfect information: sort correctly now.
  double heuristic_value(const pomdp::State&) const override { return 10.0; }

 private:
  pomdp::ModelSpec spec_;
};

class ToyTiger final : public pomdp::Model {
 public:
  static constexpr int listen = 0, open_left = 1, open_right = 2;
  ToyTiger() {
    spec_.name = "toy_tiger";
    spec_.action_names = {"listen", "open-left", "open-right"};
    spec_.state.discrete_names = {"state"};
    spec_.state.discrete_value_names = {{"tiger-left", "tiger-right"}};
    spec_.observation.names = {"tiger-left", "tiger-right"};
    spec_.discount = 0.95;
    spec_.min_reward = -100;
    spec_.max_reward = 10;
  }
  const pomdp::ModelSpec& spec() const override { return spec_; }
  pomdp::State sample_initial_state(Rng& rng) const override {
    return {{}, {uniform01(rng) < 0.5 ? 0 : 1}};
  }
  pomdp::StepResult step(const pomdp::State& s, int a, Rng& rng) const override {
    pomdp::StepResult r;
    const int tiger = s.discrete[0];
    if (a == listen) {
      r.next = s;
      r.reward = -1;
      r.observation.index = uniform01(rng) < 0.85 ? tiger : 1 - tiger;
    } else {
      const int opened = a == open_left ? 0 : 1;
      r.reward = opened == tiger ? -100 : 10;
      r.next = sample_initial_state(rng);
      r.observation.index = uniform01(rng) < 0.5 ? 0 : 1;
    }
    return r;
  }
  double observation_likelihood(const pomdp::State& s, int a,
                                const pomdp::Observation& o) const override {
    if (a == listen) return o.index == s.discrete[0] ? 0.85 : 0.15;
    return 0.5;
  }

 private:
  pomdp::ModelSpec spec_;
};

class ToyParticleBelief final : public pomdp::Belief {
 public:
  ToyParticleBelief(std::shared_ptr<const pomdp::Model> model, int particles, Rng& rng)
      : model_(std::move(model)) {
    for (int i = 0; i < particles; ++i) particles_.push_back(model_->sample_initial_state(rng));
  }
  pomdp::State sample(Rng& rng) const override {
    return particles_[static_cast<std::size_t>(uniform01(rng) * particles_.size())];
  }
  bool update(int action, const pomdp::Observation& o, Rng& rng) override {
    std::vector<pomdp::State> next;
    std::vector<double> weights;
    double total = 0;
    for (const auto& s : particles_) {
      next.push_back(model_->step(s, action, rng).next);
      weights.push_back(model_->observation_likelihood(next.back(), action, o));
      total += weights.back();
    }
    if (total <= 0) return false;
    std::vector<pomdp::State> resampled;
    for (std::size_t i = 0; i < particles_.size(); ++i) {
      double u = uniform01(rng) * total;
      std::size_t k = 0;
      while (k + 1 < next.size() && u >= weights[k]) u -= weights[k++];
      resampled.push_back(next[k]);
    }
    particles_ = std::move(resampled);
    return true;
  }
  std::vector<double> discrete_marginal(int variable) const override {
    std::vector<double> m(model_->spec().state.discrete_value_names[variable].size(), 0.0);
    for (const auto& s : particles_) m[s.discrete[variable]] += 1.0 / particles_.size();
    return m;
  }
  std::unique_ptr<pomdp::Belief> clone() const override {
    return std::make_unique<ToyParticleBelief>(*this);
  }

 private:
  std::shared_ptr<const pomdp::Model> model_;
  std::vector<pomdp::State> particles_;
};

class ToyEnvironment final : public pomdp::Environment {
 public:
  explicit ToyEnvironment(std::shared_ptr<const pomdp::Model> model) : model_(std::move(model)) {}
  void reset(const pomdp::State& true_state, Rng&) override { state_ = true_state; }
  pomdp::Outcome execute(int action, Rng& rng) override {
    pomdp::StepResult r = model_->step(state_, action, rng);
    state_ = r.next;
    return {r.observation, r.reward, r.terminal, r.collision, std::nullopt};
  }
  const pomdp::State& true_state() const override { return state_; }

 private:
  std::shared_ptr<const pomdp::Model> model_;
  pomdp::State state_;
};

}  // namespace echoplan::testing
