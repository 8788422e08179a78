#include "perception/dataset_folds.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "common/error.h"

namespace echoplan::perception {
namespace {

// objects[i] gets sessions[i] sessions, added object by object.
FeatureSet set_with_sessions(const std::vector<int>& sessions) {
  FeatureSet set;
  set.root = "set";
  for (std::size_t o = 0; o < sessions.size(); ++o) {
    const int object = set.add_object("o" + std::to_string(o));
    for (int s = 0; s < sessions[o]; ++s) set.add_session(object, "s" + std::to_string(s));
  }
  return set;
}

// Every session in exactly one fold.
void expect_partition(const std::vector<Fold>& folds, std::size_t sessions) {
  std::vector<int> seen(sessions, 0);
  for (const Fold& f : folds)
    for (int s : f.test_sessions) ++seen.at(static_cast<std::size_t>(s));
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(sessions));
}

TEST(DatasetFolds, SessionFoldsHoldTheFthSessionOfEveryObject) {
  const FeatureSet set = set_with_sessions({3, 2, 3});  // sessions 0-2, 3-4, 5-7
  DatasetTask task;
  task.class_of_object = {0, 1, 2};
  task.classes = {"o0", "o1", "o2"};
  const auto folds = make_folds(set, task);
  ASSERT_EQ(folds.size(), 3u);
  EXPECT_EQ(folds[0].test_sessions, (std::vector<int>{0, 3, 5}));
  EXPECT_EQ(folds[1].test_sessions, (std::vector<int>{1, 4, 6}));
  EXPECT_EQ(folds[2].test_sessions, (std::vector<int>{2, 7}));
  expect_partition(folds, set.sessions.size());
  EXPECT_EQ(training_sessions(set, folds[2]), (std::vector<int>{0, 1, 3, 4, 5, 6}));
}

TEST(DatasetFolds, SessionFoldsOfASubsetUseOnlyItsSessions) {
  const FeatureSet set = set_with_sessions({3, 3});
  DatasetTask task;
  task.class_of_object = {0, 1};
  task.classes = {"o0", "o1"};
  const std::vector<int> subset{1, 2, 4, 5};
  const auto folds = make_folds(set, task, subset);
  ASSERT_EQ(folds.size(), 2u);
  EXPECT_EQ(folds[0].test_sessions, (std::vector<int>{1, 4}));
  EXPECT_EQ(training_sessions(set, folds[0], subset), (std::vector<int>{2, 5}));
}

TEST(DatasetFolds, OneSessionPerObjectCannotHoldOutSessions) {
  DatasetTask task;
  task.class_of_object = {0, 1};
  task.classes = {"o0", "o1"};
  EXPECT_THROW(make_folds(set_with_sessions({2, 1}), task), InputError);
}

TEST(DatasetFolds, ObjectFoldsAreStratifiedByClassAndKeepSessionsTogether) {
  // Class 0: objects 0-3, class 1: objects 4-6; two sessions each; k = min(10, 3) = 3.
  const FeatureSet set = set_with_sessions({2, 2, 2, 2, 2, 2, 2});
  DatasetTask task;
  task.hold_out = HoldOut::object;
  task.classes = {"a", "b"};
  task.class_of_object = {0, 0, 0, 0, 1, 1, 1};
  const auto folds = make_folds(set, task);
  ASSERT_EQ(folds.size(), 3u);
  expect_partition(folds, set.sessions.size());
  // Round robin continuing across classes: the folds of objects 0-6 are 0,1,2,0 then 1,2,0.
  EXPECT_EQ(folds[0].test_sessions, (std::vector<int>{0, 1, 6, 7, 12, 13}));
  EXPECT_EQ(folds[1].test_sessions, (std::vector<int>{2, 3, 8, 9}));
  EXPECT_EQ(folds[2].test_sessions, (std::vector<int>{4, 5, 10, 11}));
  for (const Fold& f : folds) {  // every class keeps training objects
    const auto train = training_sessions(set, f);
    std::vector<bool> has(2, false);
    for (int s : train) has[task.class_of_object[set.sessions[s].object]] = true;
    EXPECT_TRUE(has[0] && has[1]);
  }
}

TEST(DatasetFolds, ObjectFoldsAreAtMostTen) {
  const FeatureSet set = set_with_sessions(std::vector<int>(30, 1));
  DatasetTask task;
  task.hold_out = HoldOut::object;
  task.classes = {"a", "b"};
  task.class_of_object.assign(30, 0);
  for (int o = 15; o < 30; ++o) task.class_of_object[o] = 1;
  const auto folds = make_folds(set, task);
  EXPECT_EQ(folds.size(), 10u);
  expect_partition(folds, 30);
}

TEST(DatasetFolds, AClassOfOneObjectCannotHoldOutObjects) {
  DatasetTask task;
  task.hold_out = HoldOut::object;
  task.classes = {"a", "b"};
  task.class_of_object = {0, 0, 1};
  EXPECT_THROW(make_folds(set_with_sessions({1, 1, 1}), task), InputError);
}

}  // namespace
}  // namespace echoplan::perception
