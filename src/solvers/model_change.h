// A change of the planning model announced to a running solver: "these observation rows changed".
//
// What echoplan's models can change while a robot runs is the observation table (the classifier
// retrained on new recordings, its confusion recalibrated: loop/calibrated_problem.h); the
// objects, actions, kinematics and rewards stay what the problem file says. A ModelChange names
// the new model and the rows P(. | s', a) that differ from the old one, so that a solver keeping
// sampled episodes (AbtSolver::revise) re-samples the observations of the steps that used those
// rows and leaves every other step alone.
#pragma once

#include <vector>

#include "pomdp/model.h"
#include "pomdp/object_identification_model.h"

namespace echoplan::solvers {

// One observation row: P(o | s', action) for the next states s' whose discrete variable 0 (the
// object) equals `object`; object = -1 means every next state.
struct ObservationRow {
  int action = 0;
  int object = -1;
  friend bool operator==(const ObservationRow&, const ObservationRow&) = default;
};

struct ModelChange {
  // The model to plan with from now on: same actions, observations, discount and dynamics as the
  // old one (the solver checks what it can: action and observation names, discount).
  pomdp::ModelPtr model;
  std::vector<ObservationRow> rows;  // the observation rows that changed

  // True when a step that took `action` and reached `next` drew its observation from a changed
  // row.
  bool affects(const pomdp::State& next, int action) const;
};

// The change from `before` to `after` for two object-identification models that differ in their
// observation tables only (the rows whose probabilities differ at all). Throws InputError naming
// the first other difference (objects, actions, symbols, rewards, kinematics, discount, prior).
ModelChange observation_table_change(const pomdp::ObjectIdentificationModel& before,
                                     std::shared_ptr<const pomdp::ObjectIdentificationModel> after);

}  // namespace echoplan::solvers
