// libFuzzer target: arbitrary bytes as an offline policy file (JSON alpha vectors, the file
// `echoplan solve --out` writes and `trials --policy` reads), checked against a problem of tiger's
// shape (2 states, 3 actions, discount 0.95). Bad input must end in echoplan::InputError; a policy
// that loads must give an action and a value at a belief without any other failure.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "solvers/offline/policy_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace echoplan::solvers::offline;
  FlatPomdp tiger_shape;
  tiger_shape.num_states = 2;
  tiger_shape.num_actions = 3;
  tiger_shape.num_observations = 2;
  tiger_shape.discount = 0.95;
  try {
    const echoplan::solvers::AlphaVectorSet policy = parse_policy(
        std::string(reinterpret_cast<const char*>(data), size), "fuzz.json", tiger_shape);
    const echoplan::solvers::BeliefVector belief{0.3, 0.7};
    const int action = policy.best_action(belief);
    if (action < 0 || action >= tiger_shape.num_actions) __builtin_trap();
    (void)policy.value(belief);
  } catch (const echoplan::InputError&) {
    // A malformed policy: the documented outcome.
  }
  return 0;
}
