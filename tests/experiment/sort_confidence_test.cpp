// How sure an arm was when it sorted: the belief at the sorting decision in what it chose, beside
// whether the sort was right, per trial and per arm (values worked by hand below).
#include "experiment/sort_confidence.h"

#include <gtest/gtest.h>

namespace echoplan::experiment {
namespace {

// A trial that sorted with `action` from `belief` (after one sensing step), truth `truth`.
JournalEntry sorted(const std::string& arm, int truth, int action, std::vector<double> belief) {
  JournalEntry e;
  e.arm = arm;
  e.result.record.true_state = truth;
  e.result.record.believed_state =
      static_cast<int>(std::max_element(belief.begin(), belief.end()) - belief.begin());
  StepRecord sense;
  sense.action = 0;
  sense.belief = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  StepRecord sort;
  sort.step = 1;
  sort.action = action;
  sort.belief = std::move(belief);
  e.result.steps = {sense, sort};
  e.result.record.steps = 2;
  return e;
}

// Three classes; classes 0 and 2 go to the bin of action 3, class 1 to that of action 4 (actions
// 0-2 sense).
const RightShares kRightAction{
    {0, 0, 0, 1, 0},
    {0, 0, 0, 0, 1},
    {0, 0, 0, 1, 0},
};

TEST(SortConfidence, BinSortsCountTheBeliefOfEveryClassInTheChosenBin) {
  const auto right = sort_confidence(sorted("a", 2, 3, {0.2, 0.5, 0.3}).result, kRightAction);
  ASSERT_TRUE(right);
  EXPECT_DOUBLE_EQ(right->belief, 0.5);  // 0.2 + 0.3: classes 0 and 2 share action 3's bin
  EXPECT_TRUE(right->right);
  const auto wrong = sort_confidence(sorted("a", 1, 3, {0.6, 0.1, 0.3}).result, kRightAction);
  ASSERT_TRUE(wrong);
  EXPECT_DOUBLE_EQ(wrong->belief, 0.9);
  EXPECT_FALSE(wrong->right);
}

TEST(SortConfidence, ALookalikeCountsTheShareOfItsOtherClassesInTheChosenBin) {
  // State 3 sounds like class 0 and is class 1 or 2: sorted with action 3 it is right half the
  // time (class 2 is in action 3's bin, class 1 is not).
  RightShares shares = kRightAction;
  shares.push_back({0, 0, 0, 0.5, 0.5});
  const auto c = sort_confidence(sorted("a", 0, 3, {0.6, 0.0, 0.0, 0.4}).result, shares);
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->belief, 0.6 + 0.4 * 0.5);
  EXPECT_TRUE(c->right);
}

TEST(SortConfidence, WithoutBinsItIsTheBeliefInTheFinalMode) {
  const auto c = sort_confidence(sorted("a", 0, 5, {0.3, 0.7, 0.0}).result, {});
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->belief, 0.7);
  EXPECT_FALSE(c->right);  // the mode is 1, the truth 0
}

TEST(SortConfidence, ACappedTrialNeverSortedAndIsLeftOut) {
  JournalEntry e = sorted("a", 0, 3, {0.9, 0.05, 0.05});
  e.result.record.capped = true;
  EXPECT_FALSE(sort_confidence(e.result, kRightAction));
}

TEST(SortConfidence, PerArmMeansAndReliabilityBins) {
  std::vector<JournalEntry> entries{sorted("a", 2, 3, {0.2, 0.5, 0.3}),   // 0.5, right
                                    sorted("b", 1, 4, {0.0, 1.0, 0.0}),   // 1.0, right
                                    sorted("a", 1, 3, {0.5, 0.1, 0.4}),   // 0.9, wrong
                                    sorted("a", 0, 3, {0.9, 0.1, 0.0})};  // 0.9, right
  const std::vector<ArmConfidence> arms = arm_confidence({"a", "b", "c"}, entries, kRightAction);
  ASSERT_EQ(arms.size(), 3u);
  EXPECT_EQ(arms[0].arm, "a");
  EXPECT_EQ(arms[0].sorts, 3);
  EXPECT_DOUBLE_EQ(arms[0].mean_belief, (0.5 + 0.9 + 0.9) / 3);
  EXPECT_DOUBLE_EQ(arms[0].share_right, 2.0 / 3);
  ASSERT_EQ(arms[0].bins.size(), kReliabilityEdges.size() - 1);
  EXPECT_EQ(arms[0].bins[1].sorts, 1);  // [0.5, 0.6)
  EXPECT_DOUBLE_EQ(arms[0].bins[1].share_right, 1.0);
  EXPECT_EQ(arms[0].bins[5].sorts, 2);  // [0.9, 0.95)
  EXPECT_DOUBLE_EQ(arms[0].bins[5].mean_belief, 0.9);
  EXPECT_DOUBLE_EQ(arms[0].bins[5].share_right, 0.5);
  EXPECT_EQ(arms[1].bins.back().sorts, 1);  // a belief of exactly 1 is in the last bin
  EXPECT_EQ(arms[2].sorts, 0);              // an arm without trials
  EXPECT_DOUBLE_EQ(arms[2].mean_belief, 0.0);
}

}  // namespace
}  // namespace echoplan::experiment
