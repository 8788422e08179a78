// The problem's own tables as the world: each observation is drawn from the model, as a planner
// study without sound (`echoplan trials`, a campaign's `world: {type: model}`).
#pragma once

#include "loop/world.h"
#include "pomdp/model_environment.h"

namespace echoplan::loop {

class TableWorld final : public World {
 public:
  explicit TableWorld(pomdp::ModelPtr model) : environment_(std::move(model)) {}
  void reset(const pomdp::State& true_state, Rng& rng) override {
    environment_.reset(true_state, rng);
  }
  WorldStep execute(int action, Rng& rng) override {
    return {environment_.execute(action, rng), {}};
  }

 private:
  pomdp::ModelEnvironment environment_;
};

}  // namespace echoplan::loop
