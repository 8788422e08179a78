// A checker in the spirit of POMDPs.jl's model tests: finds things in a problem that load fine
// but are probably mistakes, each reported with a message that says how to fix it.
//
// Checks (on the tables when the model has them):
//   - an action that never changes the state and whose observations are the same in every state
//     (it can never help), unless another action requires it (Model::prerequisites);
//   - a start belief with probability on a terminal state;
//   - states that cannot be reached from the start belief, observations that can never occur;
//   - for object problems: objects with zero prior, objects with no sorting action that pays
//     more than the worst outcome, and pairs of objects that sound identical under every sensing
//     action yet belong in different places.
#pragma once

#include <string>
#include <vector>

#include "pomdp/problem.h"

namespace echoplan::pomdp {

// Each finding is one sentence naming what is wrong and the fix. Empty when nothing was found.
std::vector<std::string> check_problem(const Problem& problem);

}  // namespace echoplan::pomdp
