#include "robot/replay_recorder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "../common/test_folder.h"
#include "audio/io.h"
#include "common/error.h"

namespace echoplan::robot {
namespace {

namespace fs = std::filesystem;

// A recordings folder of short tones: DIR/<object>/strike/<i>.wav, each file its own frequency so
// a test can tell which one was played.
class ReplayFolder : public TestFolder {
 protected:
  void SetUp() override {
    TestFolder::SetUp();
    int tone = 0;
    for (const char* object : {"cup", "mug"}) {
      for (int i = 0; i < kFiles; ++i) {
        fs::create_directories(dir_ / object / "strike");
        audio::AudioClip clip;
        clip.sample_rate = 8000;
        clip.channels = 1;
        const double hz = 200.0 + 50.0 * tone++;
        for (int n = 0; n < 800; ++n)
          clip.samples.push_back(static_cast<float>(0.5 * std::sin(2 * M_PI * hz * n / 8000.0)));
        audio::write_audio((dir_ / object / "strike" / (std::to_string(i) + ".wav")).string(),
                           clip);
      }
    }
  }
  // The file whose content `clip` is.
  std::string which_file(const audio::AudioClip& clip) const {
    for (const auto& entry : fs::recursive_directory_iterator(dir_))
      if (entry.is_regular_file() &&
          audio::read_audio(entry.path().string()).samples == clip.samples)
        return fs::relative(entry.path(), dir_).string();
    return "";
  }

  static constexpr int kFiles = 3;
};

TEST_F(ReplayFolder, PlaysRecordingsOfTheTrueObjectDealtFromTheSeed) {
  ReplayRecorder recorder(dir_);
  recorder.begin_trial({0, "mug", 42});
  std::vector<std::string> played;
  for (int i = 0; i < kFiles; ++i) {
    recorder.start("strike");
    const std::string file = which_file(recorder.stop());
    EXPECT_EQ(file.rfind("mug/strike/", 0), 0u) << file;  // the true object's, of this action
    EXPECT_EQ(fs::path(recorder.current_file()).lexically_relative(dir_).string(), file);
    played.push_back(file);
  }
  // A deal: each file once before any repeats.
  EXPECT_EQ(std::set<std::string>(played.begin(), played.end()).size(),
            static_cast<std::size_t>(kFiles));

  // The same seed deals the same files in the same order; other seeds deal other orders.
  ReplayRecorder again(dir_);
  again.begin_trial({5, "mug", 42});
  for (int i = 0; i < kFiles; ++i) {
    again.start("strike");
    EXPECT_EQ(which_file(again.stop()), played[i]);
  }
  std::set<std::vector<std::string>> orders;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    again.begin_trial({0, "mug", seed});
    std::vector<std::string> order;
    for (int i = 0; i < kFiles; ++i) {
      again.start("strike");
      order.push_back(again.current_file().string());
    }
    orders.insert(order);
  }
  EXPECT_GT(orders.size(), 1u);
}

TEST_F(ReplayFolder, MissingObjectOrActionIsAnErrorNamingTheFolder) {
  ReplayRecorder recorder(dir_);
  try {
    recorder.begin_trial({0, "teapot", 1});
    FAIL() << "no error for an object with no recordings";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir_ / "teapot").string());
  }
  try {
    recorder.check("cup", "slide");
    FAIL() << "no error for an action with no recordings";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir_ / "cup" / "slide").string());
    EXPECT_NE(e.problem().find("'slide'"), std::string::npos) << e.what();
  }
  recorder.begin_trial({0, "cup", 1});
  EXPECT_THROW(recorder.start("slide"), InputError);
  EXPECT_THROW(recorder.stop(), std::logic_error);  // nothing started
  EXPECT_THROW(ReplayRecorder(dir_ / "nowhere"), InputError);
}

TEST(ReplayRobot, ReportsKnownActionsDoneAndRejectsOthers) {
  ReplayRobot robot({"slide", "strike", "move_to_A"});
  const ActionReport r = robot.execute("move_to_A");
  EXPECT_EQ(r.status, ActionStatus::done);
  EXPECT_EQ(r.action, "move_to_A");
  EXPECT_THROW(robot.execute("shake"), InputError);
}

TEST(ActionStatus, NamesEveryStatus) {
  EXPECT_STREQ(to_string(ActionStatus::done), "done");
  EXPECT_STREQ(to_string(ActionStatus::collision), "collision");
  EXPECT_STREQ(to_string(ActionStatus::failed), "failed");
}

}  // namespace
}  // namespace echoplan::robot
