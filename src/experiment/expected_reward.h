// A trial's reward in expectation given what it heard: the low-variance measure of a planner on the
// model as the world (`echoplan trials`).
//
// Why: with the model as the world and an exact belief, the belief b_t an action was chosen from is
// the true state's distribution given the trial so far. Replacing each reward by its expectation
// under that belief,
//   Σ_t γ^t Σ_s b_t(s) R(s, a_t),
// keeps the mean over trials (the law of total expectation, step by step, whatever the policy) and
// removes the noise of the draw of the state: a sort at belief 0.9 counts 0.9 · right + 0.1 · wrong
// instead of right or wrong. On an identification problem whose sorts earn +10 or -100 this is most
// of a trial's variance (measured on a 40-state problem: the paired CI of two solvers' difference
// much narrower at the same trials; docs/BENCHMARKS.md, "Under its own model"). It says nothing
// about a world other than the model: in a campaign's dataset or simulated world the belief is the
// planner's opinion, not the truth's distribution.
#pragma once

#include <optional>
#include <vector>

#include "experiment/trial_records.h"
#include "pomdp/model.h"

namespace echoplan::experiment {

// Σ_t γ^t Σ_s b_t(s) R(s, a_t) over a trial's `steps` (their beliefs: one probability per state of
// `model`, or per live state when the absorbing ones are left out at the end). nullopt when a
// step's belief is empty or longer than the model's states.
std::optional<double> expected_discounted_reward(const std::vector<StepRecord>& steps,
                                                 const pomdp::TabularModel& model);

}  // namespace echoplan::experiment
