#include "loop/object_problem.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

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

TrueObject resolve_true_object(const std::string& name, const pomdp::ObjectProblemData& problem,
                               const sim::Catalogue& catalogue) {
  const auto& objects = problem.objects;
  auto it = std::find(objects.begin(), objects.end(), name);
  if (it != objects.end()) return {static_cast<int>(it - objects.begin()), name};
  const auto entry = catalogue.objects.find(name);
  if (entry != catalogue.objects.end()) {
    it = std::find(objects.begin(), objects.end(), entry->second.base_object);
    if (it != objects.end()) return {static_cast<int>(it - objects.begin()), name};
  }
  throw InputError(
      fmt::format("--object {}: not an object of problem '{}' ({}) nor a catalogue variant of one",
                  name, problem.name, fmt::join(objects, ", ")));
}

std::map<std::string, std::string> world_objects_for(const TrueObject& truth,
                                                     const pomdp::ObjectProblemData& problem) {
  const std::string& object = problem.objects.at(truth.index);
  if (truth.world == object) return {};
  return {{object, truth.world}};
}

}  // namespace echoplan::loop
