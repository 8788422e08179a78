// Reference files: the shipped one holds the report's Tables 5.1 and 5.3; mistakes are InputErrors
// naming the file and the line; campaign.json carries a reference unchanged.
#include "experiment/reference_results.h"

#include <gtest/gtest.h>

#include "../common/source_dir.h"
#include "common/error.h"

namespace echoplan::experiment {
namespace {

const std::string kMinimal = R"(label: lab
objects:
  mug: {trials: 4, correct: 3, mean_discounted_reward: 1.5, mean_steps: 2}
)";

// The InputError of parsing `text`, as "file:line: problem".
std::string error_of(const std::string& text) {
  try {
    parse_reference_results(text, "/dir/ref.yaml");
  } catch (const InputError& e) {
    return e.file() + ":" + std::to_string(e.line()) + ": " + e.problem();
  }
  return "no error";
}

TEST(ReferenceResults, ShippedFileHoldsTheReportsTables) {
  const ReferenceResults r = load_reference_results(echoplan::testing::source_dir() +
                                                    "/experiments/chapter5_reference.yaml");
  EXPECT_EQ(r.label, "report");
  EXPECT_EQ(r.objects.size(), 6u);
  // Table 5.1: 10 of 10 for each original object; Table 5.3: 7 of 10 and 9 of 10.
  for (const char* object : {"pringles_can", "coffee_mug", "plastic_cup", "paper_base"}) {
    EXPECT_EQ(r.objects.at(object).trials, 10) << object;
    EXPECT_EQ(r.objects.at(object).correct, 10) << object;
  }
  EXPECT_EQ(r.objects.at("pringles_can_weighted").correct, 7);
  EXPECT_EQ(r.objects.at("coffee_mug_weighted").correct, 9);
  ASSERT_TRUE(r.original_objects && r.variants);
  EXPECT_FALSE(r.all);
  EXPECT_EQ(r.original_objects->result.trials, 40);
  EXPECT_EQ(r.original_objects->objects.size(), 4u);
  EXPECT_EQ(r.variants->result.correct, 16);
  // The totals are the means of their objects' rows (to the file's five decimals).
  double sum = 0.0;
  for (const std::string& o : r.original_objects->objects)
    sum += r.objects.at(o).mean_discounted_reward;
  EXPECT_NEAR(r.original_objects->result.mean_discounted_reward, sum / 4, 1e-5);
  EXPECT_NEAR(r.variants->result.mean_steps, (2.7 + 2.9) / 2, 1e-12);
}

TEST(ReferenceResults, ShippedFileHoldsWhatTheLabsClassifierHeard) {
  const ReferenceResults r = load_reference_results(echoplan::testing::source_dir() +
                                                    "/experiments/chapter5_reference.yaml");
  ASSERT_TRUE(r.heard);
  EXPECT_EQ(r.heard->classifier, "report-template");
  ASSERT_EQ(r.heard->actions.size(), 2u);
  // original-robot-runs.md: strikes of the four objects heard right 43 of 46 times, slides 23 of
  // 35, the paper base's slides 5 of 15; 81 sensing actions with the four objects, 36 with the
  // weighted ones.
  int four = 0, weighted = 0;
  for (const HeardCounts& h : r.heard->actions) {
    EXPECT_EQ(h.columns, (std::vector<std::string>{"pringles_can", "coffee_mug", "plastic_cup",
                                                   "paper_base"}));
    ASSERT_EQ(h.rows.size(), 6u);
    int right = 0, total = 0;
    for (std::size_t row = 0; row < 4; ++row) right += h.right(row), total += h.total(row);
    four += total;
    weighted += h.total(4) + h.total(5);
    EXPECT_EQ(right, h.action == "strike" ? 43 : 23) << h.action;
    EXPECT_EQ(total, h.action == "strike" ? 46 : 35) << h.action;
    if (h.action == "slide") {
      EXPECT_EQ(h.right(3), 5);
    } else {  // the weighted can's strikes heard as the can 7 of 9 (original-robot-runs.md)
      EXPECT_EQ(h.rows[4], "pringles_can_weighted");
      EXPECT_EQ(h.heard_as(4, "pringles_can"), 7);
      EXPECT_EQ(h.total(4), 9);
    }
  }
  EXPECT_EQ(four, 81);
  EXPECT_EQ(weighted, 36);
}

TEST(ReferenceResults, MinimalFile) {
  const ReferenceResults r = parse_reference_results(kMinimal, "/dir/ref.yaml");
  EXPECT_EQ(r.source, "/dir/ref.yaml");
  EXPECT_EQ(r.note, "");
  EXPECT_EQ(r.objects.at("mug").correct, 3);
  EXPECT_DOUBLE_EQ(r.objects.at("mug").mean_discounted_reward, 1.5);
  EXPECT_FALSE(r.original_objects || r.variants || r.all || r.heard);
}

TEST(ReferenceResults, MistakesNameTheFileAndLine) {
  EXPECT_EQ(error_of(kMinimal + "  cup: {trials: 4, correct: 5, mean_discounted_reward: 1, "
                                "mean_steps: 2}\n"),
            "/dir/ref.yaml:4: objects.cup: correct must not exceed trials (4)");
  EXPECT_EQ(error_of(kMinimal + "  cup: {trials: 0, correct: 0, mean_discounted_reward: 1, "
                                "mean_steps: 2}\n"),
            "/dir/ref.yaml:4: objects.cup: trials must be >= 1");
  const std::string typo = error_of(kMinimal + "totals:\n  originals: {}\n");
  EXPECT_EQ(typo.substr(0, 16), "/dir/ref.yaml:5:") << typo;
  EXPECT_NE(typo.find("unknown key 'originals'"), std::string::npos) << typo;
  const std::string missing = error_of("label: lab\nobjects:\n  mug: {trials: 4, correct: 3}\n");
  EXPECT_EQ(missing.substr(0, 16), "/dir/ref.yaml:3:") << missing;
  EXPECT_NE(missing.find("mean_discounted_reward"), std::string::npos) << missing;
  const std::string no_objects =
      error_of(kMinimal +
               "totals:\n  all: {trials: 4, correct: 3, mean_discounted_reward: 1, mean_steps: "
               "2}\n");
  EXPECT_NE(no_objects.find("objects"), std::string::npos) << no_objects;
  EXPECT_EQ(error_of("label: lab\nobjects: [mug]\n").substr(0, 16), "/dir/ref.yaml:2:");
  EXPECT_EQ(error_of("label: [lab\n").substr(0, 14), "/dir/ref.yaml:");
  const std::string heard = kMinimal +
                            "heard:\n  classifier: report-template\n  classes: [mug, cup]\n"
                            "  actions:\n    slide:\n";
  EXPECT_EQ(error_of(heard + "      mug: [1, 2, 3]\n"),
            "/dir/ref.yaml:9: heard.actions.slide.mug: expected 2 counts, one per class of "
            "heard.classes");
  EXPECT_EQ(error_of(heard + "      mug: [1, 0.5]\n"),
            "/dir/ref.yaml:9: heard.actions.slide.mug: counts must be whole numbers >= 0");
  const std::string no_classifier =
      error_of(kMinimal + "heard:\n  classes: [mug]\n  actions: {}\n");
  EXPECT_NE(no_classifier.find("classifier"), std::string::npos) << no_classifier;
}

TEST(ReferenceResults, JsonRoundTrip) {
  const ReferenceResults r = load_reference_results(echoplan::testing::source_dir() +
                                                    "/experiments/chapter5_reference.yaml");
  const ReferenceResults back = reference_results_from_json(to_json(r), "campaign.json");
  EXPECT_EQ(to_json(back), to_json(r));
  EXPECT_EQ(back.original_objects->objects, r.original_objects->objects);
  ASSERT_TRUE(back.heard);
  EXPECT_EQ(back.heard->actions[1].counts, r.heard->actions[1].counts);
  EXPECT_THROW(reference_results_from_json(nlohmann::json{{"label", "x"}}, "campaign.json"),
               InputError);
}

}  // namespace
}  // namespace echoplan::experiment
