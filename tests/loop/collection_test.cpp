// loop::collect with a robot that has no microphone (its performances are their signals alone) and
// with performances lost to a transient fault (not written; a rerun performs them). The collection
// with the simulated arm and microphone is tested end to end by tests/apps/collect_cli_test.sh.
#include "loop/collection.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>

#include "../common/test_folder.h"
#include "common/error.h"
#include "common/file_io.h"
#include "robot/transient_error.h"

namespace echoplan::loop {
namespace {

namespace fs = std::filesystem;

// An arm that performs every action it is asked to, and counts them.
class CountingArm final : public robot::Robot {
 public:
  void begin_trial(const robot::TrialContext& /*context*/) override {}
  robot::ActionReport execute(const std::string& action) override {
    ++performed;
    return {action, robot::ActionStatus::done, "", 0.5};
  }
  int performed = 0;
};

// A joint-effort series whose values name the performance (object index, session, behaviour).
signal::Series effort(double value) {
  return {{"j1"}, {0.0, 0.01, 0.02}, {{value, value + 1, value + 2}}};
}

std::string text_of(const fs::path& path) { return read_text_file(path.string(), "the file"); }

class Collection : public TestFolder {
 protected:
  CollectionPlan plan() const {
    CollectionPlan p;
    p.objects = {"cup", "mug"};
    p.behaviours = {"lift", "press"};
    p.sessions = 2;
    p.output_dir = dir_.string();
    return p;
  }
  // Signals of every performance but those `lost_on` names, which throw TransientError.
  PerformanceSignals signals(std::string lost_on = "") {
    return [lost_on](const std::string& object, int session, const std::string& behaviour) {
      if (object + ' ' + std::to_string(session) + ' ' + behaviour == lost_on)
        throw robot::TransientError("/joint_states: no message during '" + behaviour + "'");
      const double value = (object == "mug" ? 100 : 0) + 10 * session + (behaviour == "press");
      return std::vector<std::pair<std::string, signal::Series>>{{"effort", effort(value)}};
    };
  }
  std::atomic<bool> stop_{false};
};

TEST_F(Collection, WithoutAMicrophoneEachPerformanceIsItsSignalsAndTheManifestNamesThem) {
  CountingArm arm;
  const CollectionSummary s = collect(arm, nullptr, plan(), signals(), {}, stop_);
  EXPECT_EQ(s.performed, 8);
  EXPECT_EQ(arm.performed, 8);
  EXPECT_FALSE(fs::exists(dir_ / "mug/press/s002.wav"));
  const signal::Series mug = signal::read_series_csv((dir_ / "mug/press/s002.effort.csv").string());
  EXPECT_EQ(mug.values[0], (std::vector<double>{121, 122, 123}));
  EXPECT_NE(text_of(dir_ / "manifest.csv").find("mug/press/s002.effort.csv,mug,press,2,done\n"),
            std::string::npos)
      << text_of(dir_ / "manifest.csv");
}

TEST_F(Collection, APerformanceLostToATransientFaultIsNotWrittenAndARerunPerformsItAlone) {
  CountingArm arm;
  std::vector<CollectionStep> steps;
  const CollectionSummary first = collect(
      arm, nullptr, plan(), signals("cup 2 press"),
      [&](const CollectionStep& step) { steps.push_back(step); }, stop_);
  EXPECT_EQ(first.performed, 7);
  EXPECT_EQ(first.lost, 1);
  ASSERT_EQ(steps.size(), 8u);
  EXPECT_EQ(steps[3].behaviour, "press");
  EXPECT_EQ(steps[3].session, 2);
  EXPECT_EQ(steps[3].lost, "/joint_states: no message during 'press'");
  EXPECT_EQ(steps[3].done, 3);  // the lost one is not counted as done
  EXPECT_FALSE(fs::exists(dir_ / "cup/press/s002.effort.csv"));
  EXPECT_EQ(text_of(dir_ / "manifest.csv").find("cup/press/s002"), std::string::npos);

  const CollectionSummary again = collect(arm, nullptr, plan(), signals(), {}, stop_);
  EXPECT_EQ(again.kept, 7);
  EXPECT_EQ(again.performed, 1);
  EXPECT_EQ(arm.performed, 8 + 1);
  EXPECT_TRUE(fs::exists(dir_ / "cup/press/s002.effort.csv"));
}

TEST_F(Collection, NoMicrophoneAndNoSignalIsAnError) {
  CountingArm arm;
  const PerformanceSignals none = [](const std::string&, int, const std::string&) {
    return std::vector<std::pair<std::string, signal::Series>>{};
  };
  EXPECT_THROW(collect(arm, nullptr, plan(), none, {}, stop_), InputError);
  EXPECT_THROW(collect(arm, nullptr, plan(), {}, {}, stop_), InputError);
}

}  // namespace
}  // namespace echoplan::loop
