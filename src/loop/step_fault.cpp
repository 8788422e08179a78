#include "loop/step_fault.h"

#include <fmt/format.h>

namespace echoplan::loop {

std::string fault_text(int trial, int step, const std::string& action, const StepFault& fault) {
  const char* effect = fault.effect == FaultEffect::observation_skipped
                           ? "the observation is skipped and the planner re-plans"
                           : "the trial ends as failed";
  return fmt::format("trial {}, step {} ({}): {}: {}; {}", trial, step + 1, action, fault.kind,
                     fault.detail, effect);
}

}  // namespace echoplan::loop
