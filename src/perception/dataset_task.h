// What a recorded dataset is used to recognise, and how trials are held out from training
// (docs/feature-sets.md, "Planning on feature sets").
//
// A feature set names objects and sessions; a task says what the hidden state is (the object
// itself, or its group) and into which bins the robot sorts it. Two kinds of hold-out:
//  - session: a trial is a new session of a known object. The hidden state is the object (every
//    object has its own training rows); the robot sorts into the groups when a groups file is
//    given, else into the objects themselves.
//  - object: a trial is an object never seen in training. The hidden state can only be its group
//    (a classifier cannot name an object it never heard), so a groups file is required; the robot
//    sorts into the groups.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "perception/feature_set.h"

namespace echoplan::perception {

enum class HoldOut { session, object };

// "session" or "object"; InputError("", 0, ...) naming both otherwise.
HoldOut parse_hold_out(std::string_view text);
std::string hold_out_name(HoldOut hold_out);

// What is classified and how it is sorted.
struct DatasetTask {
  HoldOut hold_out = HoldOut::session;
  // The hidden state's values, the classifiers' classes and the observation symbols: the set's
  // objects in set order (hold_out session), or the groups in order of their first object in the
  // set (hold_out object).
  std::vector<std::string> classes;
  // The sorting actions: the groups (in order of their first object in the set) when a groups
  // file is given, else the objects.
  std::vector<std::string> bins;
  std::vector<int> bin_of_class;     // [class] -> bin
  std::vector<int> class_of_object;  // [FeatureSet object] -> class
};

// The task of `set` for `hold_out`. `groups` may be null (then bins are the objects; hold_out
// object needs groups). Objects listed in the groups file but absent from the set are ignored.
// Throws InputError(groups_file, 0, ...) for an object of the set missing from the groups, and
// InputError for hold_out object without groups.
DatasetTask make_dataset_task(const FeatureSet& set, const ObjectGroups* groups, HoldOut hold_out,
                              const std::string& groups_file = "");

}  // namespace echoplan::perception
