// The campaign's tables and numbers from a small hand-written campaign
// (campaign_results_fixture.h): the summary rows and their statistics, the reference matched by
// object and by the objects a total covers, the paired differences, the confusion counts and the
// CSV files, against values worked out by hand from the fixture's six trials.
#include "experiment/campaign_report.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "campaign_results_fixture.h"

namespace echoplan::experiment {
namespace {

namespace fs = std::filesystem;
using testing::small_campaign;
using testing::small_reference;

int lines_of(const fs::path& file) {
  std::ifstream in(file);
  int n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

TEST(CampaignReport, RowsPerArmWithTheirStatistics) {
  const std::vector<SummaryRow> rows = summary_rows(small_campaign());
  ASSERT_EQ(rows.size(), 10u);  // per arm: a, b_heavy, original objects, variants, all
  const std::vector<RowScope> scopes = {RowScope::object, RowScope::object,
                                        RowScope::original_objects, RowScope::variants,
                                        RowScope::all};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].arm, i < 5 ? "one" : "two");
    EXPECT_EQ(rows[i].scope, scopes[i % 5]);
    EXPECT_FALSE(rows[i].reference);  // the campaign names no reference
  }
  EXPECT_EQ(rows[0].label, "a");
  EXPECT_EQ(rows[2].label, "original objects");
  // Arm one, object a: trials 0 (right, 8) and 1 (wrong, -2), two steps each.
  EXPECT_EQ(rows[0].summary.trials, 2);
  EXPECT_DOUBLE_EQ(rows[0].summary.accuracy, 0.5);
  EXPECT_DOUBLE_EQ(rows[0].summary.mean_discounted_reward, 3.0);
  EXPECT_DOUBLE_EQ(rows[0].summary.mean_steps, 2.0);
  EXPECT_EQ(rows[0].summary.mean_action_counts, (std::vector<double>{1.0, 0.5, 0.5}));
  // The original objects are only a here; the variants only b_heavy.
  EXPECT_DOUBLE_EQ(rows[2].summary.mean_discounted_reward, 3.0);
  EXPECT_DOUBLE_EQ(rows[3].summary.mean_discounted_reward, 10.0);
  // Arm one, all: (8 - 2 + 10) / 3, 2 of 3 right, (2 + 2 + 1) / 3 steps.
  EXPECT_DOUBLE_EQ(rows[4].summary.mean_discounted_reward, 16.0 / 3);
  EXPECT_DOUBLE_EQ(rows[4].summary.accuracy, 2.0 / 3);
  EXPECT_DOUBLE_EQ(rows[4].summary.mean_steps, 5.0 / 3);
  // Arm two, all: (6 + 4 - 100) / 3.
  EXPECT_DOUBLE_EQ(rows[9].summary.mean_discounted_reward, -30.0);
}

TEST(CampaignReport, NoTotalsWithoutBothKindsOfObject) {
  CampaignResults results = small_campaign();
  results.groups.pop_back();  // only a: no variants, so no original/variant split
  std::vector<RowScope> scopes;
  for (const SummaryRow& row : summary_rows(results))
    if (row.arm == "one") scopes.push_back(row.scope);
  EXPECT_EQ(scopes, (std::vector<RowScope>{RowScope::object, RowScope::all}));
}

TEST(CampaignReport, ReferenceMatchedByObjectAndCoveredObjects) {
  CampaignResults results = small_campaign();
  results.config.reference = small_reference();
  const std::vector<SummaryRow> rows = summary_rows(results);
  for (const std::size_t arm : {0u, 5u}) {  // the same reference beside every arm
    ASSERT_TRUE(rows[arm + 0].reference);   // a: its own result
    EXPECT_EQ(rows[arm + 0].reference->correct, 9);
    EXPECT_FALSE(rows[arm + 1].reference);  // b_heavy: none in the reference
    ASSERT_TRUE(rows[arm + 2].reference);   // original objects: covers exactly {a}
    EXPECT_EQ(rows[arm + 2].reference->trials, 10);
    EXPECT_FALSE(rows[arm + 3].reference);  // variants: the reference's covers c_heavy too
    ASSERT_TRUE(rows[arm + 4].reference);   // all: {b_heavy, a} in another order
    EXPECT_EQ(rows[arm + 4].reference->correct, 25);
  }
  // Labels do not matter, structure does: an object named like a total gets no total's numbers.
  results.groups[0] = {"all", "all", 2};
  for (auto& e : results.entries)
    if (e.object == "a") e.object = "all";
  EXPECT_FALSE(summary_rows(results)[0].reference);
}

TEST(CampaignReport, SummaryJson) {
  CampaignResults results = small_campaign();
  nlohmann::json j = summary_json(results);
  EXPECT_EQ(j["trials_planned"], 6);
  EXPECT_EQ(j["trials_finished"], 6);
  EXPECT_EQ(j["complete"], true);
  ASSERT_EQ(j["results"].size(), 10u);
  EXPECT_FALSE(j["results"][0].contains("report"));
  // Two minus one, pair by pair: (6 - 8), (4 - -2), (-100 - 10).
  ASSERT_EQ(j["paired_differences"].size(), 1u);
  EXPECT_EQ(j["paired_differences"][0]["arm"], "two");
  EXPECT_EQ(j["paired_differences"][0]["minus"], "one");
  EXPECT_EQ(j["paired_differences"][0]["pairs"], 3);
  EXPECT_DOUBLE_EQ(j["paired_differences"][0]["mean_discounted_reward_difference"].get<double>(),
                   -106.0 / 3);

  results.config.reference = small_reference();
  j = summary_json(results);
  const nlohmann::json& reported = j["results"][0]["report"];
  EXPECT_EQ(reported["correct"], 9);
  EXPECT_DOUBLE_EQ(reported["accuracy"].get<double>(), 0.9);
  EXPECT_DOUBLE_EQ(reported["mean_discounted_reward"].get<double>(), 7.5);
  EXPECT_FALSE(j["results"][1].contains("report"));
  EXPECT_FALSE(j.contains("heard"));

  // A simulated world's training set heard beside the reference's counts.
  results.heard = {{"listen", {"a", "b"}, {"a", "b"}, {{3, 1}, {0, 4}}}};
  EXPECT_FALSE(summary_json(results).contains("heard")) << "the reference has no heard counts";
  results.config.reference->heard =
      HeardReference{"report-template", "", {{"listen", {"a"}, {"a", "b"}, {{5, 3}}}}};
  j = summary_json(results);
  EXPECT_EQ(j["heard"]["classifier"], "report-template");
  EXPECT_EQ(j["heard"]["simulated"][0]["counts"], nlohmann::json::parse("[[3, 1], [0, 4]]"));
  EXPECT_EQ(j["heard"]["lab"][0]["objects"], nlohmann::json::parse(R"(["a"])"));
  EXPECT_EQ(j["heard"]["lab"][0]["counts"], nlohmann::json::parse("[[5, 3]]"));
}

TEST(CampaignReport, ConfusionCountsPerArmAndSensingAction) {
  const std::vector<ConfusionCounts> all = confusion_counts(small_campaign());
  // Only listening heard a class; the picks heard "none", which is no class.
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].arm, "one");
  EXPECT_EQ(all[0].action, "listen");
  EXPECT_EQ(all[0].rows, (std::vector<std::string>{"a", "b_heavy"}));
  EXPECT_EQ(all[0].columns, (std::vector<std::string>{"heard_a", "heard_b"}));
  EXPECT_EQ(all[0].counts, (std::vector<std::vector<int>>{{1, 1}, {0, 0}}));
  EXPECT_EQ(all[1].arm, "two");
  EXPECT_EQ(all[1].counts, (std::vector<std::vector<int>>{{2, 1}, {0, 1}}));
}

TEST(CampaignReport, SummaryTextShowsTheReferenceOnlyWhenLoaded) {
  CampaignResults results = small_campaign();
  std::string text = summary_text(results);
  EXPECT_EQ(text.find('|'), std::string::npos) << text;
  EXPECT_NE(text.find("6 of 6 trials; planner abt with 100 episodes per step"), std::string::npos);
  EXPECT_NE(text.find("audio_objects.yaml, its observation table calibrated on the training set)"),
            std::string::npos);
  EXPECT_NE(text.find("two minus one, paired trials"), std::string::npos);
  EXPECT_NE(text.find("-35.33"), std::string::npos) << text;

  results.config.reference = small_reference();
  text = summary_text(results);
  EXPECT_NE(text.find("| lab: correct  reward"), std::string::npos) << text;
  EXPECT_NE(text.find("9/10    7.50"), std::string::npos) << text;
  EXPECT_NE(text.find("25/30    4.25"), std::string::npos) << text;
}

TEST(CampaignReport, TablesWholeAndPerArm) {
  const fs::path dir = fs::temp_directory_path() / "echoplan_campaign_report_test";
  fs::remove_all(dir);
  write_tables(dir, small_campaign());
  EXPECT_EQ(lines_of(dir / "trials.csv"), 1 + 6);
  EXPECT_EQ(lines_of(dir / "arms" / "one" / "trials.csv"), 1 + 3);
  EXPECT_EQ(lines_of(dir / "arms" / "two" / "trials.csv"), 1 + 3);
  // Steps: 2 + 2 + 1 for arm one, 3 + 2 + 2 for arm two.
  EXPECT_EQ(lines_of(dir / "steps.csv"), 1 + 12);
  EXPECT_EQ(lines_of(dir / "arms" / "one" / "steps.csv"), 1 + 5);
  std::ifstream whole(dir / "trials.csv");
  std::string header;
  std::getline(whole, header);
  EXPECT_NE(header.find("arm,object"), std::string::npos) << header;
  std::ifstream per_arm(dir / "arms" / "two" / "trials.csv");
  std::getline(per_arm, header);
  EXPECT_EQ(header.find("arm"), std::string::npos) << header;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace echoplan::experiment
