#include "perception/dataset_task.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace echoplan::perception {
namespace {

FeatureSet three_objects() {
  FeatureSet set;
  set.root = "set";
  for (const char* o : {"mug", "bowl", "cup"}) set.add_session(set.add_object(o), "1");
  return set;
}

ObjectGroups groups() {
  // File order differs from the set's: groups are named in order of their first object in the set.
  return {{"cup", "bowl", "mug", "unused"}, {"ceramic", "plastic", "ceramic", "metal"}};
}

TEST(DatasetTask, SessionHoldOutWithoutGroupsSortsIntoTheObjects) {
  const DatasetTask task = make_dataset_task(three_objects(), nullptr, HoldOut::session);
  EXPECT_EQ(task.classes, (std::vector<std::string>{"mug", "bowl", "cup"}));
  EXPECT_EQ(task.bins, task.classes);
  EXPECT_EQ(task.bin_of_class, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(task.class_of_object, (std::vector<int>{0, 1, 2}));
}

TEST(DatasetTask, SessionHoldOutWithGroupsClassifiesObjectsAndSortsIntoGroups) {
  const ObjectGroups g = groups();
  const DatasetTask task = make_dataset_task(three_objects(), &g, HoldOut::session);
  EXPECT_EQ(task.classes, (std::vector<std::string>{"mug", "bowl", "cup"}));
  EXPECT_EQ(task.bins, (std::vector<std::string>{"ceramic", "plastic"}));
  EXPECT_EQ(task.bin_of_class, (std::vector<int>{0, 1, 0}));
  EXPECT_EQ(task.class_of_object, (std::vector<int>{0, 1, 2}));
}

TEST(DatasetTask, ObjectHoldOutClassifiesGroups) {
  const ObjectGroups g = groups();
  const DatasetTask task = make_dataset_task(three_objects(), &g, HoldOut::object);
  EXPECT_EQ(task.classes, (std::vector<std::string>{"ceramic", "plastic"}));
  EXPECT_EQ(task.bins, task.classes);
  EXPECT_EQ(task.bin_of_class, (std::vector<int>{0, 1}));
  EXPECT_EQ(task.class_of_object, (std::vector<int>{0, 1, 0}));
}

TEST(DatasetTask, ObjectHoldOutNeedsGroups) {
  EXPECT_THROW(make_dataset_task(three_objects(), nullptr, HoldOut::object), InputError);
}

TEST(DatasetTask, AnObjectMissingFromTheGroupsIsAnErrorNamingIt) {
  const ObjectGroups g{{"mug", "bowl"}, {"ceramic", "plastic"}};
  try {
    make_dataset_task(three_objects(), &g, HoldOut::session, "groups.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "groups.csv");
    EXPECT_NE(e.problem().find("'cup'"), std::string::npos) << e.what();
  }
}

TEST(DatasetTask, ParsesHoldOutNames) {
  EXPECT_EQ(parse_hold_out("session"), HoldOut::session);
  EXPECT_EQ(parse_hold_out("object"), HoldOut::object);
  EXPECT_EQ(hold_out_name(HoldOut::object), "object");
  EXPECT_THROW(parse_hold_out("group"), InputError);
}

}  // namespace
}  // namespace echoplan::perception
