// The model itself as the world: for planner studies, the environment steps the true state with
// the same generative model the planner plans on.
#pragma once

#include "pomdp/environment.h"

namespace echoplan::pomdp {

class ModelEnvironment final : public Environment {
 public:
  explicit ModelEnvironment(ModelPtr model) : model_(std::move(model)) {}

  void reset(const State& true_state, Rng& rng) override;
  // Steps the true state. Throws std::logic_error after the episode has ended (call reset()).
  Outcome execute(int action, Rng& rng) override;
  const State& true_state() const override { return state_; }

 private:
  ModelPtr model_;
  State state_;
  bool ended_ = true;  // until the first reset()
};

}  // namespace echoplan::pomdp
