// The planner's problem with the trained classifier's calibrated observation table in place of the
// hand-tuned one: the planner then plans with what the classifier really does (the
// report's section 3.3 for the table it replaces).
#pragma once

#include <memory>
#include <string>

#include "perception/observation_model.h"
#include "pomdp/object_identification_model.h"
#include "pomdp/problem.h"

namespace echoplan::loop {

// `base` with observation_symbols = model.observation_symbols(kind) (the classes, or the graded
// symbols; then `unknown` when the model's reject option is on) and observation_table[a][k] = the
// model's P(symbol | object k, action a) of that kind, rows matched to `base`'s objects by name.
// Everything else (objects, prior, actions, rewards, kinematics) is kept. Throws InputError when a
// sensing action of `base` has no classifier in the model, an object of `base` is not one of the
// model's classes, or `kind` is graded and the model has no grades.
pomdp::ObjectProblemData calibrated_problem(
    const pomdp::ObjectProblemData& base, const perception::ObservationModel& model,
    perception::ObservationKind kind = perception::ObservationKind::labels);

// The loaded problem `base` planning with `model`'s calibrated table (calibrated_problem() on its
// data; belief and planner settings kept). `source_path` names where it will be saved for the user
// (or is empty). InputError naming `base`'s file when the model does not fit it.
std::shared_ptr<const pomdp::Problem> calibrate_problem(
    const pomdp::Problem& base, const perception::ObservationModel& model,
    const std::string& source_path = "",
    perception::ObservationKind kind = perception::ObservationKind::labels);

// Writes an object-identification problem as YAML for the user (never read back by the loop),
// after `header` (comment lines, each starting with "# "), in one atomic step.
void save_problem(const pomdp::Problem& problem, const std::string& path,
                  const std::string& header = "");

}  // namespace echoplan::loop
