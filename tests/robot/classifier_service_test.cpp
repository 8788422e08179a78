#include "robot/classifier_service.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numeric>
#include <span>

#include "../common/source_dir.h"
#include "common/error.h"
#include "common/rng.h"
#include "perception/dataset_task.h"
#include "perception/feature_set.h"
#include "perception/fit_observation_model.h"
#include "perception/performance_reader.h"
#include "perception/recording_features.h"
#include "sim/recording.h"
#include "sim/simulated_robot.h"
#include "small_training_set.h"

namespace echoplan::robot {
namespace {

const std::vector<std::string> kObjects{"coffee_mug", "plastic_cup"};

std::shared_ptr<const perception::ObservationModel> model() {
  static const auto m = testing::train_small_model(kObjects, {"slide", "strike"}, 3);
  return m;
}

// A fresh simulated recording (a seed the training set did not use).
audio::AudioClip recording(const std::string& object, const std::string& action,
                           std::uint64_t seed) {
  sim::SimulatedRobot robot(testing::shipped_catalogue(), object, sim::SimConfig{});
  sim::SoundRenderer recorder(robot.object(), robot.table(), sim::SimConfig{});
  Rng rng(seed);
  return sim::simulate_recording(robot, recorder, sim::parse_sound_action(action), rng).clip;
}

TEST(ClassifierService, SaysWhatTheModelCanReport) {
  ClassifierService service(model());
  const auto v = service.vocabulary();
  ASSERT_TRUE(v.has_value());
  ASSERT_EQ(v->labels.size(), 2u);
  EXPECT_EQ(v->labels.at("slide"), model()->classes());
  EXPECT_EQ(v->labels.at("strike"), model()->classes());
  EXPECT_TRUE(v->may_report_unknown);  // trained with the reject option
}

TEST(ClassifierService, ReportsTheModelsDecisionWithCalibratedProbabilities) {
  ClassifierService service(model());
  const audio::AudioClip clip = recording("coffee_mug", "strike", 987654);
  const HeardObservation heard = service.observe(clip, "strike");
  // What the service must agree with: the model's decision on the clip analysed its way.
  perception::ClipAnalyzer analyzer(model()->analysis());
  perception::ClipAnalysis analysis;
  analyzer.analyse(clip, "clip", analysis);
  const perception::Prediction p = model()->classify(analysis, "strike");
  EXPECT_EQ(heard.label, p.label);
  EXPECT_EQ(heard.unknown, p.unknown);
  EXPECT_DOUBLE_EQ(heard.distance, p.distance);
  ASSERT_EQ(heard.probabilities.size(), kObjects.size());
  double sum = 0;
  for (std::size_t k = 0; k < kObjects.size(); ++k) {
    EXPECT_EQ(heard.probabilities[k].first, model()->classes()[k]);
    EXPECT_DOUBLE_EQ(heard.probabilities[k].second, p.probabilities[k]);
    sum += heard.probabilities[k].second;
  }
  EXPECT_NEAR(sum, 1.0, 1e-9);
  EXPECT_DOUBLE_EQ(heard.probability, p.probabilities[p.best_class]);
  // The simulated mug strike is heard as the mug.
  EXPECT_EQ(heard.label, "coffee_mug");
  EXPECT_GT(heard.probability, 0.5);
}

TEST(ClassifierService, SummarisesTheClipForLogs) {
  ClassifierService service(model());
  const audio::AudioClip clip = recording("plastic_cup", "strike", 4242);
  const HeardObservation heard = service.observe(clip, "strike");
  std::map<std::string, double> f(heard.features.begin(), heard.features.end());
  ASSERT_EQ(f.size(), 5u);
  EXPECT_NEAR(f.at("duration_s"), clip.duration_seconds(), 0.01);
  // The strike's impact comes after the lift and the descent (over a second into the action).
  EXPECT_GT(f.at("onset_s"), 1.0);
  EXPECT_LT(f.at("onset_s"), f.at("duration_s"));
  EXPECT_LT(f.at("peak_dbfs"), 0.0);
  EXPECT_GT(f.at("peak_dbfs"), -60.0);
  EXPECT_GT(f.at("centroid_hz"), 20.0);
  EXPECT_LT(f.at("centroid_hz"), 22050.0);
  EXPECT_GE(f.at("flatness"), 0.0);
  EXPECT_LE(f.at("flatness"), 1.0);
}

TEST(ClassifierService, ActionWithoutAClassifierIsAnInputError) {
  ClassifierService service(model());
  try {
    service.observe(recording("coffee_mug", "strike", 1), "shake");
    FAIL() << "no error for an action the model was not trained for";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shake"), std::string::npos) << e.what();
  }
}

// A model fitted on the shipped feature set: every modality (its audio.csv too) a sensor's rows.
std::shared_ptr<const perception::ObservationModel> sensor_model() {
  static const auto m = [] {
    const perception::FeatureSet set = perception::load_feature_set(
        echoplan::testing::source_dir() + "/experiments/data/synthetic_objects");
    std::vector<int> sessions(set.sessions.size());
    std::iota(sessions.begin(), sessions.end(), 0);
    return std::make_shared<const perception::ObservationModel>(perception::fit_observation_model(
        set, perception::make_dataset_task(set, nullptr, perception::HoldOut::session), sessions,
        perception::session_fit_options()));
  }();
  return m;
}

// Any row of `length` values, different per `seed`.
std::vector<double> some_row(std::size_t length, int seed) {
  std::vector<double> row(length);
  for (std::size_t i = 0; i < length; ++i) row[i] = std::sin(1.7 * seed + 0.9 * i) * 2.0;
  return row;
}

// Each action of the set reads two sensors, audio.csv and haptic.csv, given in the model's order.
TEST(ClassifierService, APerformanceSeenBySensorsIsTheModelsDecisionOnItsRows) {
  ClassifierService service(sensor_model());
  const std::string action = "press";
  ASSERT_EQ(service.sensor_modalities(action), (std::vector<std::string>{"audio", "haptic"}));
  EXPECT_TRUE(service.sensor_modalities("strike").empty());  // not in the model
  for (int seed = 0; seed < 5; ++seed) {
    // press/audio.csv has 6 features, press/haptic.csv 3.
    const std::vector<std::vector<double>> rows = {some_row(6, seed), some_row(3, seed + 10)};
    const HeardObservation heard = service.observe_performance(action, rows, nullptr);
    const std::vector<std::span<const double>> spans(rows.begin(), rows.end());
    const perception::Prediction p =
        service.model().classify_rows(service.model().action_index(action), spans);
    EXPECT_EQ(heard.label, p.label);
    ASSERT_EQ(heard.probabilities.size(), p.probabilities.size());
    for (std::size_t k = 0; k < p.probabilities.size(); ++k)
      EXPECT_EQ(heard.probabilities[k].second, p.probabilities[k]);
    EXPECT_EQ(heard.probability, p.probabilities[p.best_class]);
    EXPECT_TRUE(heard.features.empty());  // no clip to summarise
  }
  // The clip path is not the way to observe it.
  EXPECT_THROW(service.observe(recording("coffee_mug", "strike", 3), action), InputError);
}

TEST(ClassifierService, SensorRowsThatDoNotFitTheModelAreInputErrors) {
  ClassifierService service(sensor_model());
  const std::vector<std::vector<double>> one = {some_row(3, 1)};
  EXPECT_THROW(service.observe_performance("press", one, nullptr), InputError);  // 1 of 2 rows
  const std::vector<std::vector<double>> short_rows = {some_row(2, 1), some_row(2, 2)};
  EXPECT_THROW(service.observe_performance("press", short_rows, nullptr), InputError);
  EXPECT_THROW(service.observe_performance("shake_hands", one, nullptr), InputError);
}

// An action with an audio modality computed from clips and a haptic sensor: fitted on simulated
// recordings of the two objects plus a made-up haptic row per recording.
std::shared_ptr<const perception::ObservationModel> mixed_model() {
  static const auto m = [] {
    const auto dir = testing::unique_temp_dir("mixed");
    testing::write_small_dataset(dir, kObjects, {"strike"}, 6, 3);
    perception::FeatureSet set = perception::load_data(dir.string());
    std::filesystem::remove_all(dir);
    perception::ActionData& strike = set.actions.at(0);
    perception::Modality haptic{"haptic", {"stiffness", "damping"}, {}, ""};
    for (std::size_t r = 0; r < strike.rows.size(); ++r) {
      std::vector<double> row = some_row(2, static_cast<int>(r));
      row[0] += 5.0 * strike.rows[r].object;
      haptic.rows.push_back(row);
    }
    strike.modalities.push_back(haptic);  // after "audio": the names' order
    std::vector<int> sessions(set.sessions.size());
    std::iota(sessions.begin(), sessions.end(), 0);
    return std::make_shared<const perception::ObservationModel>(perception::fit_observation_model(
        set, perception::make_dataset_task(set, nullptr, perception::HoldOut::session), sessions,
        perception::session_fit_options()));
  }();
  return m;
}

TEST(ClassifierService, AMixedPerformanceTakesItsAudioRowFromTheClip) {
  ClassifierService service(mixed_model());
  ASSERT_EQ(service.sensor_modalities("strike"), std::vector<std::string>{"haptic"});
  const audio::AudioClip clip = recording("plastic_cup", "strike", 2024);
  const std::vector<std::vector<double>> haptic = {{5.2, 0.3}};
  const HeardObservation heard = service.observe_performance("strike", haptic, &clip);
  // The model's own decision on (the clip's audio row, the haptic row), in its modality order.
  perception::ClipAnalyzer analyzer(service.model().analysis());
  perception::ClipAnalysis analysis;
  analyzer.analyse(clip, "clip", analysis);
  const std::vector<double> audio_row =
      service.model().modalities("strike").at(0).classifier->embed(analysis);
  const std::vector<std::span<const double>> rows = {audio_row, haptic[0]};
  const perception::Prediction p = service.model().classify_rows(0, rows);
  EXPECT_EQ(heard.label, p.label);
  for (std::size_t k = 0; k < p.probabilities.size(); ++k)
    EXPECT_EQ(heard.probabilities.at(k).second, p.probabilities[k]);
  EXPECT_FALSE(heard.features.empty());  // the clip is summarised for the log
  try {
    service.observe_performance("strike", haptic, nullptr);
    FAIL() << "no error without the clip the audio modality needs";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs the clip of the performance for its 'audio'"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace echoplan::robot
