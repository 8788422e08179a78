// The object-identification problem behind a model, for the parts of the loop that need named
// objects, sensing and sorting actions (the robot world, the calibrated table).
#pragma once

#include <map>
#include <string>

#include "pomdp/model.h"
#include "pomdp/object_identification_model.h"
#include "sim/catalogue.h"

namespace echoplan::loop {

// `model`'s object-identification view; InputError naming the problem when it is another kind (a
// tabular .pomdp problem has no objects to hear).
const pomdp::ObjectIdentificationModel& object_problem(const pomdp::Model& model);

// The true object a user names, and what the world holds for it.
struct TrueObject {
  int index = 0;      // in the problem's objects
  std::string world;  // the object itself, or a catalogue variant of it (coffee_mug_weighted)
};

// `name` as one of `problem`'s objects, or a catalogue variant standing in for its original (the
// report's section 5.4). InputError naming the problem's objects when it is neither.
TrueObject resolve_true_object(const std::string& name, const pomdp::ObjectProblemData& problem,
                               const sim::Catalogue& catalogue);

// The loop's world_objects for `truth`: empty when the world holds the problem's object itself.
std::map<std::string, std::string> world_objects_for(const TrueObject& truth,
                                                     const pomdp::ObjectProblemData& problem);

}  // namespace echoplan::loop
