// libFuzzer target: arbitrary bytes as the two files `echoplan` reads from users for experiments: a
// steps.csv (what `certify` and the belief plots read back, checked against the report's problem's
// action and observation names) and a campaign file (`echoplan experiment --config`). Bad input
// must end in echoplan::InputError; anything else (a crash, a sanitizer report, another exception,
// a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "common/error.h"
#include "experiment/campaign_config.h"
#include "experiment/trial_log.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace echoplan;
  const std::string text(reinterpret_cast<const char*>(data), size);
  pomdp::ModelSpec spec;
  spec.action_names = {"slide", "strike", "move_to_A", "move_to_B"};
  spec.observation.names = {"pringles_can", "coffee_mug", "plastic_cup", "paper_base", "none"};
  try {
    std::istringstream in(text);
    for (const experiment::LoggedTrial& trial : experiment::read_steps_csv(in, "fuzz.csv", spec)) {
      for (const experiment::LoggedStep& step : trial.steps) {
        if (step.action < 0 || step.action >= 4 || step.observation < 0 || step.observation >= 5)
          __builtin_trap();
      }
    }
  } catch (const InputError&) {
  }
  try {
    (void)experiment::parse_campaign_config(text, "fuzz.yaml");
  } catch (const InputError&) {
  }
  return 0;
}
