#include "loop/object_problem.h"

#include <fmt/format.h>

#include "common/error.h"

namespace echoplan::loop {

const pomdp::ObjectIdentificationModel& object_problem(const pomdp::Model& model) {
  const auto* problem = model.object_identification();
  if (!problem)
    throw InputError(fmt::format(
        "problem '{}' is not an object-identification problem (a YAML file with objects, "
        "sensing and sorting actions, as in problems/audio_objects.yaml); a tabular .pomdp "
        "problem has no objects to hear",
        model.spec().name));
  return *problem;
}

}  // namespace echoplan::loop
