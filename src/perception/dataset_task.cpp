#include "perception/dataset_task.h"

#include <fmt/format.h>

#include <algorithm>

#include "common/error.h"

namespace echoplan::perception {
namespace {

int index_of(std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it != names.end()) return static_cast<int>(it - names.begin());
  names.push_back(name);
  return static_cast<int>(names.size()) - 1;
}

// [object] -> group index, groups named in order of their first object in the set.
std::vector<int> group_of_objects(const FeatureSet& set, const ObjectGroups& groups,
                                  const std::string& groups_file, std::vector<std::string>& names) {
  std::vector<int> group_of;
  for (const std::string& object : set.objects) {
    const std::string* group = groups.group_of(object);
    if (group == nullptr)
      throw InputError(groups_file, 0,
                       fmt::format("object '{}' of the feature set {} has no group; every object "
                                   "needs a row object,group",
                                   object, set.root));
    group_of.push_back(index_of(names, *group));
  }
  return group_of;
}

}  // namespace

HoldOut parse_hold_out(std::string_view text) {
  if (text == "session") return HoldOut::session;
  if (text == "object") return HoldOut::object;
  throw InputError(fmt::format("hold-out '{}': expected session or object", text));
}

std::string hold_out_name(HoldOut hold_out) {
  return hold_out == HoldOut::session ? "session" : "object";
}

DatasetTask make_dataset_task(const FeatureSet& set, const ObjectGroups* groups, HoldOut hold_out,
                              const std::string& groups_file) {
  DatasetTask task;
  task.hold_out = hold_out;
  if (hold_out == HoldOut::object && groups == nullptr)
    throw InputError(
        "hold-out object needs a groups file: a novel object can only be recognised by its group");
  if (groups == nullptr) {
    task.classes = set.objects;
    task.bins = set.objects;
    for (int o = 0; o < static_cast<int>(set.objects.size()); ++o) {
      task.bin_of_class.push_back(o);
      task.class_of_object.push_back(o);
    }
    return task;
  }
  const std::vector<int> group_of = group_of_objects(set, *groups, groups_file, task.bins);
  if (hold_out == HoldOut::object) {
    task.classes = task.bins;
    task.class_of_object = group_of;
    for (int g = 0; g < static_cast<int>(task.bins.size()); ++g) task.bin_of_class.push_back(g);
  } else {
    task.classes = set.objects;
    task.bin_of_class = group_of;
    for (int o = 0; o < static_cast<int>(set.objects.size()); ++o)
      task.class_of_object.push_back(o);
  }
  return task;
}

}  // namespace echoplan::perception
