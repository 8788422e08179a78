// Training: cross-validated confusion, its smoothed table, calibration, fold assignment, bad input.
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <numeric>

#include "common/error.h"
#include "perception/evaluate_observation_model.h"
#include "perception/fit_observation_model.h"
#include "trained_model.h"

namespace echoplan::perception {
namespace {

namespace fs = std::filesystem;
using test_model::kObjects;
using test_model::recording;
using test_model::trained;
using ::testing::HasSubstr;

TEST(FitOnRecordings, CalibratedTableFollowsTheCrossValidatedConfusion) {
  const ObservationModel& m = trained().model;
  EXPECT_EQ(m.classifier_name(), std::string(kDefaultClassifier));
  EXPECT_EQ(m.classes(), (std::vector<std::string>{"click", "ring", "thud"}));
  EXPECT_EQ(m.actions(), (std::vector<std::string>{"strike", "tap"}));
  EXPECT_EQ(m.observation_symbols(),
            (std::vector<std::string>{"click", "ring", "thud", "unknown"}));
  for (const auto& action : m.actions()) {
    const ActionCalibration& c = m.calibration(action);
    EXPECT_EQ(c.confusion.total(), 12);
    EXPECT_DOUBLE_EQ(c.confusion.accuracy(), 1.0) << action;
    // Table = (counts + 1) / (4 + 4) for every cell.
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t o = 0; o < 4; ++o)
        EXPECT_DOUBLE_EQ(c.table[k][o], (c.confusion.counts[k][o] + 1.0) / 8.0);
    EXPECT_GT(c.temperature, 0.0);
    EXPECT_GT(c.reject_threshold, 0.0);
  }
  EXPECT_THROW(m.calibration("shake"), InputError);
}

TEST(FitOnRecordings, SoftTableKeepsTheDecisionsAndSoftensTheRows) {
  const ObservationModel& counts = trained().model;
  EXPECT_EQ(counts.table_estimate(), TableEstimate::counts);
  FitOptions options;
  options.table = TableEstimate::soft;
  const ObservationModel soft = train_observation_model(trained().set, options);
  EXPECT_EQ(soft.table_estimate(), TableEstimate::soft);
  for (const auto& action : soft.actions()) {
    const ActionCalibration& s = soft.calibration(action);
    const ActionCalibration& h = counts.calibration(action);
    // Same classifier, same held-out decisions: only the table differs.
    EXPECT_EQ(s.confusion.counts, h.confusion.counts);
    EXPECT_DOUBLE_EQ(s.temperature, h.temperature);
    for (std::size_t k = 0; k < s.table.size(); ++k) {
      EXPECT_NEAR(std::accumulate(s.table[k].begin(), s.table[k].end(), 0.0), 1.0, 1e-12);
      // Every held-out clip was right (accuracy 1) and no probability is exactly 1, so the
      // expected diagonal is below the hard one; no clip was rejected, so `unknown` keeps the
      // prior's share alone (1 / (4 + 4)).
      EXPECT_LT(s.table[k][k], h.table[k][k]) << action << " row " << k;
      EXPECT_DOUBLE_EQ(s.table[k][3], 1.0 / 8.0);
    }
  }
}

TEST(FitOnRecordings, KFoldsCoverEveryRecordingOnceAndRepeatWithTheSeed) {
  FitOptions options;
  options.folds = 2;
  options.seed = 7;
  const ObservationModel a = train_observation_model(trained().set, options);
  const ObservationModel b = train_observation_model(trained().set, options);
  for (const auto& action : a.actions()) {
    EXPECT_EQ(a.calibration(action).confusion.total(), 12) << action;
    EXPECT_EQ(a.calibration(action).confusion.counts, b.calibration(action).confusion.counts);
    EXPECT_EQ(a.calibration(action).temperature, b.calibration(action).temperature);
  }
}

// A clip is a session of one performance with one modality: a recordings tree takes the feature
// sets' options too (here all of session_fit_options, with the default audio preset): folds by
// session, fusion, the shrunk table tempered for repeats, no `unknown`, and a lookalike share.
TEST(FitOnRecordings, ARecordingsTreeTakesTheFeatureSetsOptions) {
  const ObservationModel m =
      train_observation_model(trained().set, session_fit_options(std::string(kDefaultClassifier)));
  EXPECT_EQ(m.classifier_name(), std::string(kDefaultClassifier));
  EXPECT_FALSE(m.reject());
  EXPECT_EQ(m.observation_symbols(), m.classes());
  EXPECT_EQ(m.table_estimate(), TableEstimate::shrunk);
  EXPECT_GE(m.lookalike_share(ObservationKind::labels), 0.0);
  for (const auto& action : m.actions()) {
    const ActionCalibration& c = m.calibration(action);
    EXPECT_EQ(c.confusion.total(), 12);
    EXPECT_EQ(c.fit->fused_accuracy, 1.0) << action;  // the clips are told apart
    EXPECT_GT(c.fit->shrinkage_strength, 0.0);
    EXPECT_GT(c.fit->temper, 0.0);
    EXPECT_LE(c.fit->temper, 1.0);
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_NEAR(std::accumulate(c.table[k].begin(), c.table[k].end(), 0.0), 1.0, 1e-12);
      EXPECT_EQ(std::max_element(c.table[k].begin(), c.table[k].end()) - c.table[k].begin(),
                static_cast<long>(k));
    }
  }
}

TEST(CrossValidationFolds, LeaveOneOutGivesEveryExampleItsOwnFold) {
  const std::vector<int> labels{0, 1, 0, 1, 1};
  EXPECT_EQ(cross_validation_folds(labels, 2, 0, 3, "strike"), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(CrossValidationFolds, KFoldsAreStratifiedAndFollowTheSeedAndTheAction) {
  std::vector<int> labels;
  for (int i = 0; i < 30; ++i) labels.push_back(i % 3);  // ten examples of each of three classes
  const auto folds = cross_validation_folds(labels, 3, 5, 11, "strike");
  ASSERT_EQ(folds.size(), labels.size());
  // Each class dealt round-robin: two examples of every class in every fold.
  for (int k = 0; k < 3; ++k)
    for (int f = 0; f < 5; ++f) {
      int n = 0;
      for (std::size_t i = 0; i < labels.size(); ++i) n += labels[i] == k && folds[i] == f;
      EXPECT_EQ(n, 2) << "class " << k << " fold " << f;
    }
  EXPECT_EQ(cross_validation_folds(labels, 3, 5, 11, "strike"), folds);
  EXPECT_NE(cross_validation_folds(labels, 3, 5, 12, "strike"), folds);
  EXPECT_NE(cross_validation_folds(labels, 3, 5, 11, "slide"), folds);
}

TEST(CrossValidationFolds, AreTheSameOnEveryPlatform) {
  // The shuffle's stream follows the action's stable_hash (FNV-1a), not std::hash, whose values
  // differ between standard libraries: these folds are a fixed point of the seed and the action.
  const std::vector<int> labels{0, 0, 0, 0, 0, 1, 1, 1, 1, 1};
  EXPECT_EQ(cross_validation_folds(labels, 2, 3, 1, "strike"),
            (std::vector<int>{0, 0, 1, 1, 2, 2, 0, 0, 1, 1}));
}

// By surface, every table is heard as never heard: the cross-validated confusion is, table by
// table, that of a model trained on the other table alone and evaluated on this one.
TEST(FitOnRecordings, BySurfaceEachTableIsHeldOutInTurn) {
  const fs::path dir = test_model::write_two_tables("by_surface");
  const RecordingSet set = load_recording_set(dir.string());
  FitOptions by_surface;
  by_surface.cross_validation = CrossValidation::by_surface;
  by_surface.reject = false;
  const ObservationModel model = train_observation_model(set, by_surface);
  const ConfusionMatrix& held_out = model.calibration("strike").confusion;

  ConfusionMatrix expected = ConfusionMatrix::zeros(held_out.objects, held_out.symbols);
  for (const std::string table : {"hard", "soft"}) {
    RecordingSet training = set, tested = set;
    std::erase_if(training.recordings, [&](const Recording& r) { return r.surface == table; });
    std::erase_if(tested.recordings, [&](const Recording& r) { return r.surface != table; });
    FitOptions alone;
    alone.reject = false;
    const Evaluation e =
        evaluate_observation_model(train_observation_model(training, alone), tested);
    ASSERT_EQ(e.per_action.size(), 1u);
    ASSERT_EQ(e.per_action[0].symbols, held_out.symbols);
    for (std::size_t k = 0; k < expected.counts.size(); ++k)
      for (std::size_t o = 0; o < expected.counts[k].size(); ++o)
        expected.counts[k][o] += e.per_action[0].counts[k][o];
  }
  EXPECT_EQ(held_out.counts, expected.counts);
  EXPECT_EQ(held_out.total(), 18);
  // The tables differ enough that holding one out costs something: by performance (the other
  // recordings of an object on the same table in training) hears more right.
  FitOptions by_performance;
  by_performance.reject = false;
  EXPECT_GT(train_observation_model(set, by_performance).calibration("strike").confusion.accuracy(),
            held_out.accuracy());
  fs::remove_all(dir);
}

TEST(FitOnRecordings, BySurfaceNeedsATreeOnSeveralTables) {
  EXPECT_EQ(parse_cross_validation("surface"), CrossValidation::by_surface);
  EXPECT_STREQ(cross_validation_name(CrossValidation::by_surface), "surface");
  FitChoices choices;
  choices.cross_validation = "surface";
  const FitOptions o = choose_fit_options(choices, DataKind::recordings, false, false);
  EXPECT_EQ(o.cross_validation, CrossValidation::by_surface);
  EXPECT_EQ(o.table, FitOptions{}.table);  // a recordings tree's defaults
  EXPECT_TRUE(o.reject);
  try {
    choose_fit_options(choices, DataKind::features, false, false);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("a feature set names no tables"));
  }
  EXPECT_THROW(choose_fit_options(choices, DataKind::recordings, true, false), InputError);
  // The shared training set has no surface column.
  FitOptions by_surface;
  by_surface.cross_validation = CrossValidation::by_surface;
  try {
    train_observation_model(trained().set, by_surface);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("names no table"));
  }
}

TEST(FitOnRecordings, BadSetsAndOptions) {
  const fs::path dir = test_sounds::fresh_dir("train_bad");
  // One recording per (object, action): leave-one-out cannot hold a class out.
  for (std::size_t k = 0; k < 2; ++k) {
    const fs::path path = dir / kObjects[k] / "strike" / "0.wav";
    fs::create_directories(path.parent_path());
    audio::write_audio(path.string(), recording(k, 1));
  }
  const RecordingSet set = load_recording_set(dir.string());
  try {
    train_observation_model(set, FitOptions{});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()),
                HasSubstr("at least 2 performances of each class per action, found 1"));
  }
  FitOptions magic, one_fold, small_margin;
  magic.classifier = "magic";
  one_fold.folds = 1;
  small_margin.reject_margin = 0.5;
  for (const auto* options : {&magic, &one_fold, &small_margin})
    EXPECT_THROW(train_observation_model(set, *options), InputError);
  // A corrupt recording is named.
  std::ofstream(dir / kObjects[0] / "strike" / "1.wav") << "RIFF garbage";
  try {
    train_observation_model(load_recording_set(dir.string()), FitOptions{});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("1.wav"));
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace echoplan::perception
