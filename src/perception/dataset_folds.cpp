#include "perception/dataset_folds.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "common/error.h"

namespace echoplan::perception {
namespace {

std::vector<int> listed_or_all(const FeatureSet& set, std::span<const int> sessions) {
  if (!sessions.empty()) return {sessions.begin(), sessions.end()};
  std::vector<int> all(set.sessions.size());
  std::iota(all.begin(), all.end(), 0);
  return all;
}

// [object] -> its listed sessions, in set order.
std::vector<std::vector<int>> sessions_by_object(const FeatureSet& set,
                                                 const std::vector<int>& sessions) {
  std::vector<std::vector<int>> by_object(set.objects.size());
  std::vector<int> sorted = sessions;
  std::sort(sorted.begin(), sorted.end());
  for (int s : sorted) by_object[static_cast<std::size_t>(set.sessions[s].object)].push_back(s);
  return by_object;
}

std::vector<Fold> session_folds(const FeatureSet& set,
                                const std::vector<std::vector<int>>& by_object) {
  std::size_t most = 0;
  for (std::size_t o = 0; o < by_object.size(); ++o) {
    if (by_object[o].size() == 1)
      throw InputError(set.root, 0,
                       fmt::format("object '{}' has one session: holding out a session needs at "
                                   "least 2 per object (or hold out objects)",
                                   set.objects[o]));
    most = std::max(most, by_object[o].size());
  }
  std::vector<Fold> folds(most);
  for (const auto& sessions : by_object)
    for (std::size_t f = 0; f < sessions.size(); ++f) folds[f].test_sessions.push_back(sessions[f]);
  return folds;
}

std::vector<Fold> object_folds(const FeatureSet& set, const DatasetTask& task,
                               const std::vector<std::vector<int>>& by_object) {
  // [class] -> its objects that have listed sessions, set order.
  std::vector<std::vector<int>> objects_of(task.classes.size());
  for (std::size_t o = 0; o < by_object.size(); ++o)
    if (!by_object[o].empty())
      objects_of[static_cast<std::size_t>(task.class_of_object[o])].push_back(static_cast<int>(o));
  std::size_t k = 10;
  for (std::size_t c = 0; c < objects_of.size(); ++c) {
    if (objects_of[c].size() < 2)
      throw InputError(set.root, 0,
                       fmt::format("class '{}' has {} object(s): holding out an object needs at "
                                   "least 2 objects per class",
                                   task.classes[c], objects_of[c].size()));
    k = std::min(k, objects_of[c].size());
  }
  std::vector<Fold> folds(k);
  std::size_t next = 0;
  for (const auto& objects : objects_of)
    for (int o : objects) {
      auto& test = folds[next++ % k].test_sessions;
      test.insert(test.end(), by_object[static_cast<std::size_t>(o)].begin(),
                  by_object[static_cast<std::size_t>(o)].end());
    }
  for (Fold& fold : folds) std::sort(fold.test_sessions.begin(), fold.test_sessions.end());
  return folds;
}

}  // namespace

std::vector<Fold> make_folds(const FeatureSet& set, const DatasetTask& task,
                             std::span<const int> sessions) {
  const auto by_object = sessions_by_object(set, listed_or_all(set, sessions));
  if (task.hold_out == HoldOut::session) {
    // Objects without listed sessions take no part (a subset of the set, e.g. inner folds).
    return session_folds(set, by_object);
  }
  return object_folds(set, task, by_object);
}

std::vector<int> training_sessions(const FeatureSet& set, const Fold& fold,
                                   std::span<const int> sessions) {
  std::vector<int> training;
  for (int s : listed_or_all(set, sessions))
    if (!std::binary_search(fold.test_sessions.begin(), fold.test_sessions.end(), s))
      training.push_back(s);
  std::sort(training.begin(), training.end());
  return training;
}

}  // namespace echoplan::perception
