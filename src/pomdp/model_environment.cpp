#include "pomdp/model_environment.h"

#include <stdexcept>

namespace echoplan::pomdp {

void ModelEnvironment::reset(const State& true_state, Rng& /*rng*/) {
  state_ = true_state;
  ended_ = false;
}

Outcome ModelEnvironment::execute(int action, Rng& rng) {
  if (ended_)
    throw std::logic_error("ModelEnvironment::execute after the episode ended; call reset()");
  if (action < 0 || action >= model_->num_actions())
    throw std::out_of_range("ModelEnvironment: no such action");
  StepResult r = model_->step(state_, action, rng);
  state_ = std::move(r.next);
  ended_ = r.terminal;
  return Outcome{
      std::move(r.observation), r.reward, r.terminal, r.collision, std::nullopt, std::nullopt};
}

}  // namespace echoplan::pomdp
