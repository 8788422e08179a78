// Tests of the feature-set loader: a small set of two actions and two modalities (3 objects x 2
// sessions) as it loads, every malformed file's file:line error, and groups files.
#include "perception/feature_set.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "../common/input_error_message.h"
#include "../common/test_folder.h"

namespace echoplan::perception {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// Rows of one modality: 3 objects x 2 sessions, one performance each; feature values from `base`.
std::string modality_csv(const std::string& header, int base) {
  std::string text = "object,session," + header + "\n";
  int k = base;
  for (const char* object : {"mug", "cup", "bowl"})
    for (const char* session : {"s1", "s2"}) {
      text += std::string(object) + "," + session + "," + std::to_string(k) + ".5,-" +
              std::to_string(k) + "e-1\n";
      ++k;
    }
  return text;
}

class FeatureSetTest : public TestFolder {
 protected:
  void SetUp() override {
    TestFolder::SetUp();
    for (const char* action : {"strike", "press"}) {
      write_text(dir_ / action / "audio.csv", modality_csv("a0,a1", 0));
      write_text(dir_ / action / "haptic.csv", modality_csv("force,stiffness", 10));
    }
  }
  std::string load_error() {
    return input_error_message([&] { load_feature_set(dir_.string()); });
  }
  std::string file(const std::string& relative) const { return (dir_ / relative).string(); }
};

TEST_F(FeatureSetTest, LoadsActionsModalitiesRowsObjectsAndSessions) {
  write_text(dir_ / "groups.csv", "object,group\n");  // files beside the actions are ignored
  const FeatureSet set = load_feature_set(dir_.string());
  EXPECT_EQ(set.objects, (std::vector<std::string>{"mug", "cup", "bowl"}));
  ASSERT_EQ(set.sessions.size(), 6u);  // session names are per object
  EXPECT_EQ(set.sessions[3].object, 1);
  EXPECT_EQ(set.sessions[3].name, "s2");
  ASSERT_EQ(set.actions.size(), 2u);
  EXPECT_EQ(set.actions[0].name, "press");  // sorted by folder name
  const ActionData* strike = set.action("strike");
  ASSERT_NE(strike, nullptr);
  EXPECT_EQ(set.action("push"), nullptr);
  ASSERT_EQ(strike->rows.size(), 6u);
  EXPECT_EQ(strike->rows[5].object, 2);
  EXPECT_EQ(strike->rows[5].session, 5);
  ASSERT_EQ(strike->modalities.size(), 2u);
  const Modality& haptic = strike->modalities[1];
  EXPECT_EQ(haptic.name, "haptic");
  EXPECT_EQ(haptic.feature_names, (std::vector<std::string>{"force", "stiffness"}));
  ASSERT_EQ(haptic.rows.size(), 6u);
  EXPECT_EQ(haptic.rows[2], (std::vector<double>{12.5, -1.2}));
  EXPECT_EQ(strike->modalities[0].rows[0], (std::vector<double>{0.5, -0.0}));
}

TEST_F(FeatureSetTest, RepeatedPerformancesOfASessionAreRows) {
  for (const char* modality : {"audio", "haptic"})
    write_text(dir_ / "strike" / (std::string(modality) + ".csv"),
               "object,session,x\nmug,1,1\nmug,1,2\ncup,1,3\nbowl,1,4\n");
  const FeatureSet set = load_feature_set(dir_.string());
  EXPECT_EQ(set.action("strike")->rows.size(), 4u);
  EXPECT_EQ(set.action("strike")->rows[0].session, set.action("strike")->rows[1].session);
}

TEST_F(FeatureSetTest, MissingFolderOrNoActions) {
  EXPECT_THAT(input_error_message([&] { load_feature_set((dir_ / "nope").string()); }),
              HasSubstr("does not exist"));
  fs::remove_all(dir_ / "strike");
  fs::remove_all(dir_ / "press");
  EXPECT_THAT(load_error(), HasSubstr("no action folders"));
}

TEST_F(FeatureSetTest, WrongHeader) {
  write_text(dir_ / "strike" / "audio.csv", "session,object,a0\nmug,s1,1\n");
  EXPECT_THAT(load_error(), HasSubstr(file("strike/audio.csv") + ":1: the header must be"));
  write_text(dir_ / "strike" / "audio.csv", "object,session\nmug,s1\n");
  EXPECT_THAT(load_error(), HasSubstr(file("strike/audio.csv") + ":1: the header must be"));
  write_text(dir_ / "strike" / "audio.csv", "");
  EXPECT_THAT(load_error(), HasSubstr(file("strike/audio.csv") + ":1: no header"));
}

TEST_F(FeatureSetTest, DuplicateOrEmptyFeatureName) {
  write_text(dir_ / "strike" / "audio.csv", "object,session,a,b,a\nmug,s1,1,2,3\n");
  EXPECT_THAT(load_error(), HasSubstr(file("strike/audio.csv") + ":1: feature name 'a' appears"));
  write_text(dir_ / "strike" / "audio.csv", "object,session,a,,c\nmug,s1,1,2,3\n");
  EXPECT_THAT(load_error(), HasSubstr(file("strike/audio.csv") + ":1: feature name 2"));
}

TEST_F(FeatureSetTest, RaggedRow) {
  write_text(dir_ / "press" / "haptic.csv", "object,session,f,g\nmug,s1,1,2\n\nmug,s2,1\n");
  EXPECT_THAT(load_error(),
              HasSubstr(file("press/haptic.csv") + ":4: 3 cells, but the header has 4 columns"));
}

TEST_F(FeatureSetTest, EmptyObjectOrSession) {
  write_text(dir_ / "press" / "haptic.csv", "object,session,f\nmug,s1,1\nmug,,2\n");
  EXPECT_THAT(load_error(), HasSubstr(file("press/haptic.csv") + ":3: the session is empty"));
  write_text(dir_ / "press" / "haptic.csv", "object,session,f\n,s1,1\n");
  EXPECT_THAT(load_error(), HasSubstr(file("press/haptic.csv") + ":2: the object is empty"));
}

TEST_F(FeatureSetTest, FeatureThatIsNotAFiniteNumber) {
  for (const std::string bad : {"abc", "1.5x", "", " 1", "nan", "inf", "-inf", "1e999"}) {
    write_text(dir_ / "press" / "haptic.csv", "object,session,f\nmug,s1,1\nmug,s2," + bad + "\n");
    EXPECT_THAT(load_error(), HasSubstr(file("press/haptic.csv") + ":3: feature 'f' is '" + bad))
        << bad;
  }
}

TEST_F(FeatureSetTest, ModalityWithOtherRowsThanItsSibling) {
  std::string haptic = modality_csv("force,stiffness", 10);
  haptic.replace(haptic.find("cup,s2"), 6, "cup,s3");  // line 5
  write_text(dir_ / "strike" / "haptic.csv", haptic);
  const std::string message = load_error();
  EXPECT_THAT(message, HasSubstr(file("strike/haptic.csv") + ":5: row (cup, s3) differs from " +
                                 file("strike/audio.csv") + ":5, which has (cup, s2)"));
  // One row short: the longer file's extra line is named.
  write_text(dir_ / "strike" / "haptic.csv", "object,session,f\nmug,s1,1\n");
  EXPECT_THAT(load_error(),
              HasSubstr(file("strike/audio.csv") + ":3: row 2 has no counterpart in " +
                        file("strike/haptic.csv")));
}

TEST_F(FeatureSetTest, ModalityWithNoRows) {
  write_text(dir_ / "strike" / "haptic.csv", "object,session,f\n");
  EXPECT_THAT(load_error(), HasSubstr(file("strike/haptic.csv") + ": no rows"));
}

TEST_F(FeatureSetTest, ActionFolderWithNoCsvOrOtherFiles) {
  fs::create_directories(dir_ / "slide");
  EXPECT_THAT(load_error(), HasSubstr(file("slide") + ": no modality files"));
  write_text(dir_ / "slide" / "notes.txt", "x");
  EXPECT_THAT(load_error(), HasSubstr(file("slide/notes.txt") + ": expected only modality files"));
}

TEST_F(FeatureSetTest, ObjectMissingFromAnAction) {
  for (const char* modality : {"audio", "haptic"})
    write_text(dir_ / "strike" / (std::string(modality) + ".csv"),
               "object,session,x\nmug,s1,1\ncup,s1,2\n");
  EXPECT_THAT(load_error(), HasSubstr(file("strike") + ": no rows of object 'bowl'"));
}

TEST_F(FeatureSetTest, Groups) {
  write_text(dir_ / "groups.csv", "object,group\nmug,ceramic\r\ncup,ceramic\n\nbowl,plastic\n");
  const ObjectGroups groups = load_groups(file("groups.csv"));
  EXPECT_EQ(groups.objects, (std::vector<std::string>{"mug", "cup", "bowl"}));
  EXPECT_EQ(groups.groups, (std::vector<std::string>{"ceramic", "ceramic", "plastic"}));
  ASSERT_NE(groups.group_of("bowl"), nullptr);
  EXPECT_EQ(*groups.group_of("bowl"), "plastic");
  EXPECT_EQ(groups.group_of("plate"), nullptr);
}

TEST_F(FeatureSetTest, BadGroupsFiles) {
  const std::string path = file("groups.csv");
  auto error_for = [&](const std::string& text) {
    write_text(path, text);
    return input_error_message([&] { load_groups(path); });
  };
  EXPECT_THAT(input_error_message([&] { load_groups(file("none.csv")); }),
              HasSubstr("cannot open"));
  EXPECT_THAT(error_for("group,object\nmug,a\n"), HasSubstr(path + ":1: the header must be"));
  EXPECT_THAT(error_for("object,group\nmug,a,b\n"), HasSubstr(path + ":2: 3 cells"));
  EXPECT_THAT(error_for("object,group\nmug,\n"), HasSubstr(path + ":2: the group is empty"));
  EXPECT_THAT(error_for("object,group\n,a\n"), HasSubstr(path + ":2: the object is empty"));
  EXPECT_THAT(error_for("object,group\nmug,a\ncup,a\nmug,b\n"),
              HasSubstr(path + ":4: object 'mug' is listed twice"));
}

}  // namespace
}  // namespace echoplan::perception
