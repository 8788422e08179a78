// calibrated_problem() with the report's shipped problem (problems/audio_objects.yaml) and the
// stored observation model tests/data/perception/seed_gaussian_model.json (a report-gaussian model
// saved under its old name seed-gaussian; classes coffee_mug and plastic_cup, actions slide and
// strike, reject on): the model's table replaces the hand-tuned one, rows matched to the
// problem's objects and actions by name, everything else kept; problems the model was not
// trained for are refused naming what is missing.
#include "loop/calibrated_problem.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../common/source_dir.h"
#include "common/error.h"
#include "perception/observation_model.h"
#include "pomdp/problem.h"

namespace echoplan::loop {
namespace {

using pomdp::ObjectProblemData;

std::string repo_file(const std::string& relative) {
  return echoplan::testing::source_dir() + "/" + relative;
}

const perception::ObservationModel& stored_model() {
  static const perception::ObservationModel m = perception::load_observation_model(
      repo_file("tests/data/perception/seed_gaussian_model.json"));
  return m;
}

ObjectProblemData report_data() {
  const pomdp::Problem p = pomdp::load_problem(repo_file("problems/audio_objects.yaml"));
  return (*p.model->object_identification()).data();
}

// The report's problem cut down to the model's two objects, listed in the other order than the
// model's classes (plastic_cup first), and with its sensing actions in the other order too
// (strike first), so that matching by position would give wrong rows.
constexpr int kReportMug = 1, kReportCup = 2;  // object indices in audio_objects.yaml
ObjectProblemData cup_or_mug() {
  const ObjectProblemData report = report_data();
  ObjectProblemData d = report;
  d.objects = {"plastic_cup", "coffee_mug"};
  d.prior = {0.5, 0.5};
  d.sensing = {report.sensing[1], report.sensing[0]};
  d.observation_symbols = {"plastic_cup", "coffee_mug"};
  d.observation_table = {{{0.9, 0.1}, {0.1, 0.9}}, {{0.8, 0.2}, {0.2, 0.8}}};
  d.sorting_reward.clear();
  for (const auto& row : report.sorting_reward)
    d.sorting_reward.push_back({row[kReportCup], row[kReportMug]});
  pomdp::validate_object_problem(d);
  return d;
}

// The stored model's tables (seed_gaussian_model.json, per_action.*.table), rows coffee_mug then
// plastic_cup, columns coffee_mug, plastic_cup, unknown.
const std::vector<std::vector<double>> kSlideTable{{4.0 / 6, 1.0 / 6, 1.0 / 6},
                                                   {1.0 / 6, 4.0 / 6, 1.0 / 6}};
const std::vector<std::vector<double>> kStrikeTable{{3.0 / 6, 2.0 / 6, 1.0 / 6},
                                                    {1.0 / 6, 4.0 / 6, 1.0 / 6}};

void expect_rows(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t o = 0; o < want.size(); ++o) EXPECT_NEAR(got[o], want[o], 1e-12) << o;
}

TEST(CalibratedProblem, TakesTheModelsRowsMatchedByName) {
  const ObjectProblemData base = cup_or_mug();
  const ObjectProblemData out = calibrated_problem(base, stored_model());
  EXPECT_EQ(out.observation_symbols,
            (std::vector<std::string>{"coffee_mug", "plastic_cup", "unknown"}));
  ASSERT_EQ(out.observation_table.size(), 2u);  // strike, slide: the problem's action order
  ASSERT_EQ(out.observation_table[0].size(), 2u);
  // Action 0 is the strike; object 0 is the plastic cup (the model's second class).
  expect_rows(out.observation_table[0][0], kStrikeTable[1]);
  expect_rows(out.observation_table[0][1], kStrikeTable[0]);
  expect_rows(out.observation_table[1][0], kSlideTable[1]);
  expect_rows(out.observation_table[1][1], kSlideTable[0]);
}

TEST(CalibratedProblem, KeepsEverythingButTheObservationModel) {
  const ObjectProblemData base = cup_or_mug();
  const ObjectProblemData out = calibrated_problem(base, stored_model());
  EXPECT_EQ(out.name, base.name);
  EXPECT_EQ(out.discount, base.discount);
  EXPECT_EQ(out.objects, base.objects);
  EXPECT_EQ(out.prior, base.prior);
  EXPECT_EQ(out.initial_joints, base.initial_joints);
  EXPECT_EQ(out.initial_offset, base.initial_offset);
  ASSERT_EQ(out.sensing.size(), base.sensing.size());
  for (std::size_t a = 0; a < base.sensing.size(); ++a) {
    EXPECT_EQ(out.sensing[a].name, base.sensing[a].name);
    EXPECT_EQ(out.sensing[a].reward, base.sensing[a].reward);
    EXPECT_EQ(out.sensing[a].offset_change, base.sensing[a].offset_change);
    EXPECT_EQ(out.sensing[a].collision_probability, base.sensing[a].collision_probability);
  }
  EXPECT_EQ(out.sorting, base.sorting);
  EXPECT_EQ(out.sorting_reward, base.sorting_reward);
  EXPECT_EQ(out.collision_reward, base.collision_reward);
  // The result is a valid problem the planner can build a model from, with one more symbol
  // ("unknown") than the hand-tuned table had.
  const pomdp::ObjectIdentificationModel model(out);
  EXPECT_EQ(model.none_symbol(), 3);
}

TEST(CalibratedProblem, AProblemWithFewerActionsTakesOnlyItsOwn) {
  ObjectProblemData base = cup_or_mug();
  base.sensing.erase(base.sensing.begin());  // only the slide is left
  base.observation_table.erase(base.observation_table.begin());
  const ObjectProblemData out = calibrated_problem(base, stored_model());
  ASSERT_EQ(out.observation_table.size(), 1u);
  expect_rows(out.observation_table[0][1], kSlideTable[0]);
}

TEST(CalibratedProblem, RefusesAnObjectTheModelDoesNotKnow) {
  // The report's full problem: the pringles can and the paper base were never recorded.
  try {
    calibrated_problem(report_data(), stored_model());
    ADD_FAILURE() << "calibrated a problem with unknown objects";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("audio_objects"), std::string::npos) << message;
    EXPECT_NE(message.find("'pringles_can'"), std::string::npos) << message;
    EXPECT_NE(message.find("coffee_mug, plastic_cup"), std::string::npos) << message;
  }
}

TEST(CalibratedProblem, RefusesASensingActionWithoutAClassifier) {
  ObjectProblemData base = cup_or_mug();
  base.sensing[0].name = "shake";
  try {
    calibrated_problem(base, stored_model());
    ADD_FAILURE() << "calibrated a problem with an untrained action";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'shake'"), std::string::npos) << message;
    EXPECT_NE(message.find("slide, strike"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace echoplan::loop
