// The trained model's classification: calibrated probabilities, the reject decision, the actions it
// knows.
#include "perception/observation_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>

#include "common/error.h"
#include "trained_model.h"

namespace echoplan::perception {
namespace {

using test_model::analysed;
using test_model::kObjects;
using test_model::recording;
using test_model::trained;

TEST(ObservationModel, ClassifiesNewRecordingsAtAnyRateAndRejectsStrangers) {
  const ObservationModel& m = trained().model;
  for (std::size_t k = 0; k < 3; ++k) {
    // A new recording, resampled to 48 kHz and duplicated to stereo as the real recorder does.
    const audio::AudioClip mono =
        audio::resample(recording(k, 9000 + static_cast<unsigned>(k)), 48000);
    audio::AudioClip stereo = mono;
    stereo.channels = 2;
    stereo.samples.clear();
    for (float x : mono.samples) stereo.samples.insert(stereo.samples.end(), {x, x});
    const Prediction p = m.classify(analysed(m, stereo), "strike");
    const auto expected = static_cast<int>(
        std::find(m.classes().begin(), m.classes().end(), kObjects[k]) - m.classes().begin());
    EXPECT_EQ(p.symbol, expected);
    EXPECT_EQ(p.label, kObjects[k]);
    EXPECT_FALSE(p.unknown);
    EXPECT_NEAR(std::accumulate(p.probabilities.begin(), p.probabilities.end(), 0.0), 1.0, 1e-12);
    EXPECT_EQ(
        std::max_element(p.probabilities.begin(), p.probabilities.end()) - p.probabilities.begin(),
        expected);
    EXPECT_LE(p.distance, p.reject_threshold);
  }
  // White noise and a 60 Hz hum are like none of the objects.
  std::mt19937 rng(4);
  std::normal_distribution<double> gauss(0.0, 0.1);
  audio::AudioClip noise;
  noise.samples.resize(44100 * 2);
  for (float& x : noise.samples) x = static_cast<float>(gauss(rng));
  audio::AudioClip hum;
  for (int i = 0; i < 44100 * 2; ++i)
    hum.samples.push_back(static_cast<float>(0.3 * std::sin(2 * M_PI * 60.0 * i / 44100)));
  for (const auto* clip : {&noise, &hum}) {
    const Prediction p = m.classify(analysed(m, *clip), "strike");
    EXPECT_TRUE(p.unknown);
    EXPECT_EQ(p.label, "unknown");
    EXPECT_EQ(p.symbol, 3);
    EXPECT_GT(p.distance, p.reject_threshold);
  }
  EXPECT_THROW(m.classify(analysed(m, noise), "shake"), InputError);
}

TEST(ObservationModel, AnswersPerActionAndNamesTheActionsItKnows) {
  const ObservationModel& m = trained().model;
  EXPECT_EQ(m.observation_symbols(),
            (std::vector<std::string>{"click", "ring", "thud", "unknown"}));
  EXPECT_EQ(m.observation_symbols(), observation_symbols(m.description()));
  for (const auto& action : m.actions()) {
    EXPECT_EQ(m.calibration(action).action, action);
    EXPECT_EQ(&m.observation_table(action), &m.calibration(action).table);
    EXPECT_EQ(m.classifier(action).num_classes(), 3);
    EXPECT_EQ(m.classifier(action).name(), m.classifier_name());
  }
  try {
    m.calibration("shake");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(), "action 'shake' is not in the model (it was trained for: strike, tap)");
  }
  EXPECT_THROW(m.classifier("shake"), InputError);
}

TEST(ObservationModel, RefusesActionModelsThatDoNotMatchItsActions) {
  ModelDescription d;
  d.classes = {"cup", "mug"};
  d.actions = {"strike"};
  EXPECT_THROW(ObservationModel(d, {}), std::invalid_argument);
  std::vector<ActionModel> unnamed(1);
  unnamed[0].modalities.push_back({"audio", make_classifier(kDefaultClassifier)});
  unnamed[0].weights = {1.0};
  unnamed[0].calibration.action = "slide";  // not the description's action
  EXPECT_THROW(ObservationModel(d, unnamed), std::invalid_argument);
  unnamed[0].calibration.action = "strike";
  unnamed[0].weights = {};  // a weight per modality missing
  EXPECT_THROW(ObservationModel(d, unnamed), std::invalid_argument);
  unnamed[0].weights = {0.5, 0.5};
  unnamed[0].modalities.push_back({"haptic", make_modality_classifier("lda")});
  d.reject = true;  // with two modalities
  EXPECT_THROW(ObservationModel(d, unnamed), std::invalid_argument);
}

TEST(TableEstimate, NamesParseBackAndUnknownNamesAreListed) {
  for (const auto estimate : {TableEstimate::counts, TableEstimate::soft, TableEstimate::shrunk})
    EXPECT_EQ(parse_table_estimate(table_estimate_name(estimate)), estimate);
  EXPECT_EQ(table_estimate_names(), (std::vector<std::string>{"counts", "soft", "shrunk"}));
  try {
    parse_table_estimate("hard");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(), "table estimate 'hard' is not one of: counts, soft, shrunk");
  }
}

}  // namespace
}  // namespace echoplan::perception
