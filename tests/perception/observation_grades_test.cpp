// Graded observations: grades cut at the held-out terciles, counted on right and wrong decisions,
// a graded table whose grades only split the label table's cells; every fit grades, and the
// model file keeps them (and still reads files without them).
#include "perception/observation_grades.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "perception/dataset_folds.h"
#include "perception/fit_observation_model.h"
#include "perception/observation_model_json.h"
#include "synthetic_feature_set.h"
#include "trained_model.h"

namespace echoplan::perception {
namespace {

TEST(ObservationGrades, EdgesAreTheTercilesAndAConfidenceOnAnEdgeTakesTheHigherGrade) {
  const std::vector<double> confidence{0.9, 0.1, 0.5, 0.3, 0.7, 0.2, 0.8, 0.4, 0.6};
  const GradeCalibration g = fit_grades(confidence, std::vector<bool>(9, true));
  // Sorted: 0.1 ... 0.9; the edges are the 4th (index 3) and 7th (index 6) values.
  ASSERT_EQ(g.edges.size(), 2u);
  EXPECT_DOUBLE_EQ(g.edges[0], 0.4);
  EXPECT_DOUBLE_EQ(g.edges[1], 0.7);
  EXPECT_EQ(grade_of(g, 0.39), 0);
  EXPECT_EQ(grade_of(g, 0.4), 1);
  EXPECT_EQ(grade_of(g, 0.69), 1);
  EXPECT_EQ(grade_of(g, 0.7), 2);
  EXPECT_EQ(grade_of(g, 1.0), 2);
}

// Levels are cut where right and wrong decisions part: 100 decisions scored 0..99, the ten lowest
// wrong, the next twenty right every other one, the rest right. The cuts at 10 and 30 leave two
// pure bands and one half right; any other pair of cuts mixes more (e.g. 10 and 31: 11 right and
// 10 wrong in the middle, a lower likelihood than 10 and 10). The terciles would be 33 and 66.
TEST(ObservationGrades, InformativeEdgesCutWhereRightAndWrongPart) {
  std::vector<double> score;
  std::vector<bool> right;
  for (int i = 0; i < 100; ++i) {
    score.push_back(i);
    right.push_back(i >= 30 || (i >= 10 && i % 2 == 0));
  }
  EXPECT_EQ(informative_edges(score, right), (std::vector<double>{10, 30}));
  EXPECT_EQ(fit_grades(score, right).edges, (std::vector<double>{33, 66}));
  // Too few decisions for bands of five: the terciles.
  const std::vector<double> few{1, 2, 3, 4, 5, 6};
  EXPECT_EQ(informative_edges(few, {false, false, true, true, true, true}),
            fit_grades(few, {false, false, true, true, true, true}).edges);
  EXPECT_THROW(informative_edges(few, {true}), std::invalid_argument);
}

TEST(ObservationGrades, RightAndWrongDecisionsAreCountedWithOnePseudoCountPerGrade) {
  // Right decisions: confidences in grades high, high, mid; wrong ones: low, low.
  const std::vector<double> confidence{0.95, 0.9, 0.6, 0.2, 0.3};
  const std::vector<bool> right{true, true, true, false, false};
  const GradeCalibration g = fit_grades(confidence, right, {0.5, 0.8});
  // Right: counts (0, 1, 2) + 1 each over 3 + 3; wrong: (2, 0, 0) + 1 each over 2 + 3.
  EXPECT_DOUBLE_EQ(g.given_right[0], 1.0 / 6);
  EXPECT_DOUBLE_EQ(g.given_right[1], 2.0 / 6);
  EXPECT_DOUBLE_EQ(g.given_right[2], 3.0 / 6);
  EXPECT_DOUBLE_EQ(g.given_wrong[0], 3.0 / 5);
  EXPECT_DOUBLE_EQ(g.given_wrong[1], 1.0 / 5);
  EXPECT_DOUBLE_EQ(g.given_wrong[2], 1.0 / 5);
  EXPECT_THROW(fit_grades(confidence, std::vector<bool>(2, true)), std::invalid_argument);
}

TEST(ObservationGrades, TheGradedTableSplitsEachLabelCellAndKeepsUnknownWhole) {
  GradeCalibration g;
  g.edges = {0.5, 0.8};
  g.given_right = {0.1, 0.3, 0.6};
  g.given_wrong = {0.5, 0.3, 0.2};
  // Two classes and `unknown`.
  const std::vector<std::vector<double>> labels{{0.7, 0.2, 0.1}, {0.25, 0.7, 0.05}};
  const auto graded = graded_table(labels, g, 2);
  ASSERT_EQ(graded.size(), 2u);
  ASSERT_EQ(graded[0].size(), 7u);             // a@low a@mid a@high b@low b@mid b@high unknown
  EXPECT_DOUBLE_EQ(graded[0][2], 0.7 * 0.6);   // P(a@high | a): right
  EXPECT_DOUBLE_EQ(graded[0][3], 0.2 * 0.5);   // P(b@low | a): wrong
  EXPECT_DOUBLE_EQ(graded[1][0], 0.25 * 0.5);  // P(a@low | b): wrong
  EXPECT_DOUBLE_EQ(graded[1][6], 0.05);        // unknown
  for (std::size_t c = 0; c < 2; ++c) {
    double sum = 0.0;
    for (double p : graded[c]) sum += p;
    EXPECT_NEAR(sum, 1.0, 1e-12);
    for (std::size_t h = 0; h < 2; ++h)
      EXPECT_NEAR(graded[c][3 * h] + graded[c][3 * h + 1] + graded[c][3 * h + 2], labels[c][h],
                  1e-12);
  }
}

TEST(ObservationGrades, SymbolsAreNamedClassAtGradeAndIndexedClassMajor) {
  const std::vector<std::string> symbols = graded_symbols({"mug", "can"}, true);
  EXPECT_EQ(symbols, (std::vector<std::string>{"mug@low", "mug@mid", "mug@high", "can@low",
                                               "can@mid", "can@high", "unknown"}));
  EXPECT_EQ(symbols[static_cast<std::size_t>(graded_symbol(1, 2, 2))], "can@high");
  EXPECT_EQ(symbols[static_cast<std::size_t>(graded_symbol(0, 0, 2))], "mug@low");
  EXPECT_EQ(symbols[static_cast<std::size_t>(graded_symbol(2, 1, 2))], "unknown");
  EXPECT_EQ(parse_observation_kind("graded"), ObservationKind::graded);
  EXPECT_THROW(parse_observation_kind("soft"), InputError);
}

// A fit on recordings grades every action, a prediction carries its grade, and the model file keeps
// the grades; a file written before them loads, serves labels and refuses graded with a clear
// error.
TEST(ObservationGrades, TheClipModelGradesAndItsFileKeepsTheGrades) {
  const ObservationModel& model = test_model::trained().model;
  ASSERT_TRUE(model.graded());
  const auto symbols = model.observation_symbols(ObservationKind::graded);
  EXPECT_EQ(symbols.size(), model.classes().size() * kGrades + (model.reject() ? 1 : 0));
  const ClipAnalysis clip = test_model::analysed(model, test_model::recording(1, 4242));
  const Prediction p = model.classify(clip, "strike");
  ASSERT_GE(p.grade, 0);
  const int symbol = model.symbol(p, ObservationKind::graded);
  if (!p.unknown) {
    EXPECT_EQ(symbols[static_cast<std::size_t>(symbol)], graded_name(p.label, p.grade));
  }
  EXPECT_EQ(model.symbol(p, ObservationKind::labels), p.symbol);

  nlohmann::json file = observation_model_to_json(model);
  const ObservationModel back = observation_model_from_json(file, "model.json");
  EXPECT_EQ(back.observation_table("strike", ObservationKind::graded),
            model.observation_table("strike", ObservationKind::graded));
  for (auto& [action, entry] : file["per_action"].items()) entry.erase("grades");
  const ObservationModel old = observation_model_from_json(file, "old.json");
  EXPECT_FALSE(old.graded());
  EXPECT_EQ(old.observation_table("strike", ObservationKind::labels),
            model.observation_table("strike"));
  EXPECT_THROW(old.observation_symbols(ObservationKind::graded), InputError);
  file["per_action"]["strike"]["grades"] = {{"edges", {0.9, 0.5}},
                                            {"given_right", {0.2, 0.3, 0.5}},
                                            {"given_wrong", {0.2, 0.3, 0.5}},
                                            {"table", nlohmann::json::array()}};
  try {
    observation_model_from_json(file, "bad.json");
    ADD_FAILURE() << "descending edges were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("per_action.strike.grades.edges: must be ascending"),
              std::string::npos)
        << e.what();
  }
}

// On sessions with confusable objects, wrong decisions are less sure than right ones: the grades
// carry information the label does not.
TEST(ObservationGrades, OnSessionsWrongDecisionsAreHeardLessSureThanRightOnes) {
  SyntheticSpec spec;
  spec.objects = 6;
  spec.sessions = 6;
  spec.repeats = 2;
  spec.modalities = {{"audio", 4, 1.2}};  // close enough to confuse
  const auto dir = test_features::fresh_folder("grades_sessions");
  test_features::write_synthetic_feature_set(dir, spec);
  const FeatureSet set = load_feature_set(dir.string());
  const DatasetTask task = make_dataset_task(set, nullptr, HoldOut::session);
  const auto folds = make_folds(set, task);
  const ObservationModel model =
      fit_observation_model(set, task, training_sessions(set, folds[0]), session_fit_options());
  ASSERT_TRUE(model.graded());
  const ActionCalibration& c = model.calibration(set.actions[0].name);
  ASSERT_TRUE(c.fit.has_value());
  EXPECT_LT(c.fit->fused_accuracy, 0.95);  // the set does confuse
  EXPECT_GT(c.grades->given_right[2], c.grades->given_wrong[2]);
  EXPECT_LT(c.grades->given_right[0], c.grades->given_wrong[0]);
  EXPECT_GT(c.fit->graded_temper, 0.0);
  EXPECT_LE(c.fit->graded_temper, 1.0);
  for (const auto& row : c.graded_table) {
    double sum = 0.0;
    for (double p : row) sum += p;
    EXPECT_NEAR(sum, 1.0, 1e-9);
  }
}

}  // namespace
}  // namespace echoplan::perception
