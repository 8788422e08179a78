// Each arm's trials by the level measured from their own recordings: the median of the steps'
// heard_ebr_db picks the band, and per band the share right, the belief at the sort, the
// recordings heard, the behaviours and their cost per trial (values worked by hand below).
#include "experiment/noise_levels.h"

#include <gtest/gtest.h>

namespace echoplan::experiment {
namespace {

// A trial that heard recordings at `levels` (one sensing step each) and then sorted with `action`
// from `belief`; truth `truth`.
JournalEntry heard(const std::string& arm, const std::vector<double>& levels, int truth, int action,
                   std::vector<double> belief) {
  JournalEntry e;
  e.arm = arm;
  e.result.record.true_state = truth;
  for (double level : levels) {
    StepRecord sense;
    sense.step = static_cast<int>(e.result.steps.size());
    sense.belief = {0.5, 0.5};
    sense.heard_ebr_db = level;
    e.result.steps.push_back(sense);
  }
  StepRecord sort;
  sort.step = static_cast<int>(e.result.steps.size());
  sort.action = action;
  sort.belief = std::move(belief);
  e.result.steps.push_back(sort);
  e.result.record.steps = static_cast<int>(e.result.steps.size());
  e.result.record.action_counts = {static_cast<int>(levels.size()), 0, 0, 0};
  e.result.record.action_counts[static_cast<std::size_t>(action)] += 1;
  return e;
}

// Two classes; action 2 sorts class 0 right, action 3 class 1 (actions 0-1 sense, at 1.5 and 4).
const RightShares kRight{{0, 0, 1, 0}, {0, 0, 0, 1}};
const std::vector<double> kCosts{1.5, 4.0, 0.0, 0.0};

TEST(NoiseLevels, ATrialsLevelIsTheMedianOfWhatItsRecordingsMeasured) {
  EXPECT_DOUBLE_EQ(*trial_heard_level(heard("a", {30, -2, 5}, 0, 2, {1, 0}).result), 5.0);
  EXPECT_DOUBLE_EQ(*trial_heard_level(heard("a", {3, 9}, 0, 2, {1, 0}).result), 6.0);
  EXPECT_FALSE(trial_heard_level(heard("a", {}, 0, 2, {1, 0}).result));  // heard nothing
}

TEST(NoiseLevels, EachBandHoldsTheSharesOfItsTrials) {
  const std::vector<JournalEntry> entries{
      heard("a", {-3}, 0, 2, {0.8, 0.2}),         // < 0 dB: right at 0.8
      heard("a", {-1, -5, 2}, 1, 2, {0.6, 0.4}),  // < 0 dB (median -1): wrong at 0.6
      heard("a", {6}, 1, 3, {0.1, 0.9}),          // 6 to 12 dB (6 is its low edge): right
      heard("a", {40, 50}, 0, 2, {1.0, 0.0}),     // >= 24 dB: right at 1
      heard("b", {3}, 0, 3, {0.3, 0.7}),          // another arm's: 0 to 6, wrong at 0.7
      heard("a", {}, 0, 2, {1.0, 0.0}),           // heard no recording: in no band
  };
  const std::vector<ArmNoiseBands> arms = arm_noise_bands({"a", "b"}, entries, kRight, kCosts);
  ASSERT_EQ(arms.size(), 2u);
  const std::vector<NoiseBand>& a = arms[0].bands;
  ASSERT_EQ(a.size(), 5u);
  EXPECT_EQ(a[0].label(), "< 0 dB");
  EXPECT_EQ(a[1].label(), "0 to 6 dB");
  EXPECT_EQ(a[4].label(), ">= 24 dB");
  EXPECT_EQ(a[0].trials, 2);
  EXPECT_DOUBLE_EQ(a[0].share_right, 0.5);
  EXPECT_DOUBLE_EQ(a[0].mean_belief, 0.7);
  EXPECT_DOUBLE_EQ(a[0].mean_heard, 2.0);       // 1 and 3 recordings
  EXPECT_DOUBLE_EQ(a[0].mean_behaviours, 2.0);  // 1 and 3 slides before the sort
  EXPECT_DOUBLE_EQ(a[0].mean_cost, 3.0);        // at 1.5 each
  EXPECT_EQ(a[1].trials, 0);
  EXPECT_EQ(a[2].trials, 1);
  EXPECT_DOUBLE_EQ(a[2].mean_belief, 0.9);
  EXPECT_EQ(a[3].trials, 0);
  EXPECT_EQ(a[4].trials, 1);
  EXPECT_DOUBLE_EQ(a[4].mean_heard, 2.0);
  EXPECT_EQ(arms[1].bands[1].trials, 1);
  EXPECT_DOUBLE_EQ(arms[1].bands[1].share_right, 0.0);
  EXPECT_DOUBLE_EQ(arms[1].bands[1].mean_belief, 0.7);
}

TEST(NoiseLevels, ACappedTrialCountsButNeverSorted) {
  JournalEntry e = heard("a", {10}, 0, 2, {1.0, 0.0});
  e.result.record.capped = true;
  const std::vector<ArmNoiseBands> arms = arm_noise_bands({"a"}, {e}, kRight, kCosts);
  const NoiseBand& band = arms[0].bands[2];
  EXPECT_EQ(band.trials, 1);
  EXPECT_EQ(band.sorts, 0);
  EXPECT_DOUBLE_EQ(band.share_right, 0.0);
}

// Per table: each arm's trials on it, in the order the journal first names the tables; none when
// no world chose a table.
TEST(NoiseLevels, EachTableHoldsTheSharesOfItsTrials) {
  std::vector<JournalEntry> entries{
      heard("a", {10}, 0, 2, {0.9, 0.1}),      // steel: right at 0.9
      heard("a", {10, 20}, 1, 2, {0.7, 0.3}),  // oak: wrong at 0.7
      heard("a", {5}, 1, 3, {0.2, 0.8}),       // steel: right at 0.8
      heard("b", {5}, 1, 2, {0.6, 0.4}),       // b on oak: wrong at 0.6
  };
  EXPECT_TRUE(arm_surfaces({"a", "b"}, entries, kRight, kCosts).empty());  // the lab's table
  for (std::size_t i : {0u, 2u}) entries[i].result.record.surface = "steel_bench";
  for (std::size_t i : {1u, 3u}) entries[i].result.record.surface = "oak_top";
  const std::vector<ArmSurfaces> arms = arm_surfaces({"a", "b"}, entries, kRight, kCosts);
  ASSERT_EQ(arms.size(), 2u);
  ASSERT_EQ(arms[0].surfaces.size(), 2u);
  EXPECT_EQ(arms[0].surfaces[0].surface, "steel_bench");
  EXPECT_EQ(arms[0].surfaces[0].trials, 2);
  EXPECT_DOUBLE_EQ(arms[0].surfaces[0].share_right, 1.0);
  EXPECT_DOUBLE_EQ(arms[0].surfaces[0].mean_belief, 0.85);
  EXPECT_EQ(arms[0].surfaces[1].surface, "oak_top");
  EXPECT_DOUBLE_EQ(arms[0].surfaces[1].share_right, 0.0);
  EXPECT_DOUBLE_EQ(arms[0].surfaces[1].mean_heard, 2.0);
  EXPECT_DOUBLE_EQ(arms[0].surfaces[1].mean_cost, 3.0);
  EXPECT_EQ(arms[1].surfaces[0].trials, 0);  // b never stood on steel
  EXPECT_DOUBLE_EQ(arms[1].surfaces[1].mean_belief, 0.6);
}

}  // namespace
}  // namespace echoplan::experiment
