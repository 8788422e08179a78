// The planner's problem with the trained classifier's calibrated observation table in place of the
// hand-tuned one: the planner then plans with what the classifier really does (issue 7's
// calibration, seed report section 3.3 for the table it replaces).
#pragma once

#include "perception/observation_model.h"
#include "pomdp/object_identification_model.h"

namespace echoplan::experiment {

// `base` with observation_symbols = model.observation_symbols() (the classes, then `unknown` when
// the model's reject option is on) and observation_table[a][k] = the model's P(symbol | object k,
// action a), rows matched to `base`'s objects by name. Everything else (objects, prior, actions,
// rewards, kinematics) is kept. Throws InputError when a sensing action of `base` has no classifier
// in the model or an object of `base` is not one of the model's classes.
pomdp::ObjectProblemData calibrated_problem(const pomdp::ObjectProblemData& base,
                                            const perception::ObservationModel& model);

}  // namespace echoplan::experiment
