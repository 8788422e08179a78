// The object-identification problem behind a model, for the parts of the loop that need named
// objects, sensing and sorting actions (the robot world, the calibrated table).
#pragma once

#include "pomdp/model.h"
#include "pomdp/object_identification_model.h"

namespace echoplan::loop {

// `model`'s object-identification view; InputError naming the problem when it is another kind (a
// tabular .pomdp problem has no objects to hear).
const pomdp::ObjectIdentificationModel& object_problem(const pomdp::Model& model);

}  // namespace echoplan::loop
