#include "robot/classifier_service.h"

#include <gtest/gtest.h>

#include <numeric>

#include "common/error.h"
#include "common/rng.h"
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

}  // namespace
}  // namespace echoplan::robot
