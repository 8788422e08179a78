// Which child of an action node an observation leads to.
//
// Discrete observations branch by symbol: one child per index. Continuous observations (feature
// vectors) never repeat exactly, so they branch by distance: an observation joins the first
// existing child whose representative observation lies within `continuous_threshold` (Euclidean
// distance, in the observation's own units); otherwise it opens a new child and becomes that
// child's representative. A threshold of 0 gives one child per distinct vector.
#pragma once

#include "pomdp/model.h"

namespace echoplan::solvers {

struct ObservationBranching {
  double continuous_threshold = 0.0;  // >= 0, in observation units

  // True when `observation` belongs to the child represented by `representative`.
  bool same_branch(const pomdp::Observation& representative,
                   const pomdp::Observation& observation) const;
};

}  // namespace echoplan::solvers
