// The observation model end to end on synthetic recordings: training, calibration, reject, the JSON
// file.
#include "perception/observation_model.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>

#include "common/error.h"
#include "synthetic_sounds.h"

namespace echoplan::perception {
namespace {

namespace fs = std::filesystem;
using test_sounds::strike;
using test_sounds::three_objects;
using ::testing::HasSubstr;

const std::vector<std::string> kObjects{"thud", "ring", "click"};

// A strike of object k with the real recorder's quirks: leading zeros, noise, random force and
// detuning.
audio::AudioClip recording(std::size_t k, unsigned seed, double gain_lo = 0.2,
                           double gain_hi = 0.8) {
  std::mt19937 rng(seed);
  const double gain = std::uniform_real_distribution<double>(gain_lo, gain_hi)(rng);
  const double onset = std::uniform_real_distribution<double>(0.5, 0.8)(rng);
  return strike(three_objects()[k], {.duration_s = 1.8,
                                     .leading_zeros_s = 0.35,
                                     .onset_s = onset,
                                     .gain = gain,
                                     .noise_rms = 0.0005,
                                     .detune = 0.02,
                                     .seed = seed});
}

class ObservationModelTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(test_sounds::fresh_dir("model"));
    // Two actions; "tap" is the same strike 12 dB softer. Four recordings per (object, action).
    for (std::size_t k = 0; k < kObjects.size(); ++k)
      for (const std::string action : {"strike", "tap"})
        for (unsigned i = 0; i < 4; ++i) {
          auto clip = recording(k, 10 * static_cast<unsigned>(k) + i + (action == "tap" ? 500 : 0));
          if (action == "tap")
            for (float& x : clip.samples) x *= 0.25f;
          const fs::path path = *dir_ / kObjects[k] / action / (std::to_string(i) + ".wav");
          fs::create_directories(path.parent_path());
          audio::write_audio(path.string(), clip);
        }
    // Kept: other tests write model files into the folder, which is then no recording set.
    set_ = new RecordingSet(load_recording_set(dir_->string()));
    model_ = new ObservationModel(train_observation_model(*set_, TrainOptions{}));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete model_;
    delete set_;
    delete dir_;
  }
  static fs::path* dir_;
  static RecordingSet* set_;
  static ObservationModel* model_;
};
fs::path* ObservationModelTest::dir_ = nullptr;
RecordingSet* ObservationModelTest::set_ = nullptr;
ObservationModel* ObservationModelTest::model_ = nullptr;

TEST_F(ObservationModelTest, CalibratedTableFollowsTheCrossValidatedConfusion) {
  const ObservationModel& m = *model_;
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

TEST_F(ObservationModelTest, ClassifiesNewRecordingsAtAnyRateAndRejectsStrangers) {
  const ObservationModel& m = *model_;
  for (std::size_t k = 0; k < 3; ++k) {
    // A new recording, resampled to 48 kHz and duplicated to stereo as the real recorder does.
    const audio::AudioClip mono =
        audio::resample(recording(k, 9000 + static_cast<unsigned>(k)), 48000);
    audio::AudioClip stereo = mono;
    stereo.channels = 2;
    stereo.samples.clear();
    for (float x : mono.samples) stereo.samples.insert(stereo.samples.end(), {x, x});
    const Prediction p = m.classify(stereo, "strike");
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
    const Prediction p = m.classify(*clip, "strike");
    EXPECT_TRUE(p.unknown);
    EXPECT_EQ(p.label, "unknown");
    EXPECT_EQ(p.symbol, 3);
    EXPECT_GT(p.distance, p.reject_threshold);
  }
  EXPECT_THROW(m.classify(noise, "shake"), InputError);
}

TEST_F(ObservationModelTest, RoundTripsThroughJson) {
  const fs::path file = *dir_ / "model.json";
  save_observation_model(*model_, file.string());
  const ObservationModel back = load_observation_model(file.string());
  EXPECT_EQ(back.to_json(), model_->to_json());
  const audio::AudioClip clip = recording(1, 777);
  const Prediction a = model_->classify(clip, "tap"), b = back.classify(clip, "tap");
  EXPECT_EQ(a.label, b.label);
  EXPECT_EQ(a.probabilities, b.probabilities);
  EXPECT_EQ(a.distance, b.distance);
}

TEST_F(ObservationModelTest, SoftTableIsRecordedAndRoundTrips) {
  EXPECT_EQ(model_->table_estimate(), TableEstimate::counts);
  EXPECT_EQ(model_->to_json()["table_estimate"], "counts");
  TrainOptions options;
  options.table = TableEstimate::soft;
  const ObservationModel soft = train_observation_model(*set_, options);
  EXPECT_EQ(soft.table_estimate(), TableEstimate::soft);
  for (const auto& action : soft.actions()) {
    const ActionCalibration& s = soft.calibration(action);
    const ActionCalibration& h = model_->calibration(action);
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
  const fs::path file = *dir_ / "soft.json";
  save_observation_model(soft, file.string());
  const ObservationModel back = load_observation_model(file.string());
  EXPECT_EQ(back.table_estimate(), TableEstimate::soft);
  EXPECT_EQ(back.to_json(), soft.to_json());
  // A file written before the option existed had a counts table.
  nlohmann::json old = model_->to_json();
  old.erase("table_estimate");
  EXPECT_EQ(ObservationModel::from_json(old, "old.json").table_estimate(), TableEstimate::counts);
}

TEST_F(ObservationModelTest, EvaluatesHeldOutRecordingsIncludingUnknownObjects) {
  const fs::path held = *dir_ / "held_out";
  for (std::size_t k = 0; k < 3; ++k)
    for (unsigned i = 0; i < 2; ++i) {
      const fs::path path = held / kObjects[k] / "strike" / (std::to_string(i) + ".wav");
      fs::create_directories(path.parent_path());
      audio::write_audio(path.string(), recording(k, 3000 + 10 * static_cast<unsigned>(k) + i));
    }
  // An object the model never heard: a hum.
  audio::AudioClip hum;
  for (int i = 0; i < 44100; ++i)
    hum.samples.push_back(static_cast<float>(0.3 * std::sin(2 * M_PI * 60.0 * i / 44100)));
  fs::create_directories(held / "hum" / "strike");
  audio::write_audio((held / "hum" / "strike" / "0.wav").string(), hum);
  audio::write_audio((held / "hum" / "strike" / "1.wav").string(), hum);
  const Evaluation e = evaluate_observation_model(*model_, load_recording_set(held.string()));
  ASSERT_EQ(e.per_action.size(), 1u);
  const ConfusionMatrix& c = e.per_action[0];
  EXPECT_DOUBLE_EQ(c.accuracy(), 1.0);
  const auto hum_row = static_cast<std::size_t>(
      std::find(c.objects.begin(), c.objects.end(), "hum") - c.objects.begin());
  EXPECT_EQ(c.counts[hum_row][3], 2);  // both hums are unknown
}

TEST_F(ObservationModelTest, EveryBrokenModelFileIsAClearError) {
  const nlohmann::json good = model_->to_json();
  const fs::path file = *dir_ / "broken.json";
  auto expect_error = [&](const std::string& text, const std::string& fragment) {
    std::ofstream(file, std::ios::trunc) << text;
    try {
      load_observation_model(file.string());
      ADD_FAILURE() << "no error; expected " << fragment;
    } catch (const InputError& e) {
      EXPECT_THAT(std::string(e.what()), HasSubstr(file.string()));
      EXPECT_THAT(std::string(e.what()), HasSubstr(fragment));
    }
  };
  const std::string text = good.dump();
  expect_error(text.substr(0, text.size() / 2), "not a valid JSON model file");
  expect_error("", "not a valid JSON model file");
  expect_error("[1, 2]", "expected a JSON object");
  expect_error("{\"version\": 8.5e6666666}", "not a valid JSON model file");  // found by the fuzzer
  auto with = [&](const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json doc = good;
    change(doc);
    return doc.dump();
  };
  expect_error(with([](auto& d) { d["version"] = 2; }), "version 2 is not supported");
  expect_error(with([](auto& d) { d["format"] = "other"; }), "not an observation model");
  expect_error(with([](auto& d) { d.erase("classes"); }), "classes: missing");
  expect_error(with([](auto& d) { d["classifier"] = "magic"; }), "unknown classifier 'magic'");
  expect_error(with([](auto& d) { d["analysis"]["sample_rate"] = 5; }), "analysis.sample_rate");
  expect_error(with([](auto& d) { d["analysis"]["preset"] = "nope"; }), "unknown feature preset");
  expect_error(with([](auto& d) { d["classes"][1] = d["classes"][0]; }), "appears twice");
  expect_error(with([](auto& d) { d["per_action"].erase("tap"); }), "per_action");
  expect_error(with([](auto& d) { d["per_action"]["tap"]["table"][0][0] = 0.9; }),
               "per_action.tap.table[0]: probabilities sum to");
  expect_error(with([](auto& d) { d["per_action"]["tap"]["confusion"][1][1] = -2; }),
               "per_action.tap.confusion");
  expect_error(with([](auto& d) { d["per_action"]["strike"]["temperature"] = 0; }),
               "per_action.strike.temperature");
  expect_error(with([](auto& d) { d["per_action"]["strike"]["reject_threshold"] = nullptr; }),
               "reject_threshold");
  expect_error(with([](auto& d) { d["per_action"]["strike"]["classifier"]["scale"].erase(0); }),
               "per_action.strike.classifier.scale: expected 123 numbers");
  expect_error(
      with([](auto& d) { d["per_action"]["strike"]["classifier"]["class_means"].erase(0); }),
      "fitted for 2 classes");
  expect_error(with([](auto& d) { d["per_action"]["strike"]["symbols"][3] = "nothing"; }),
               "per_action.strike.symbols");
  expect_error(with([](auto& d) { d["table_estimate"] = "hard"; }),
               "table_estimate: table estimate 'hard' is not one of: counts, soft");
  expect_error(with([](auto& d) { d["table_estimate"] = 3; }), "table_estimate");
  try {
    load_observation_model((*dir_ / "missing.json").string());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("cannot open"));
  }
}

TEST(ObservationModelTraining, BadSetsAndOptions) {
  const fs::path dir = test_sounds::fresh_dir("train_bad");
  // One recording per (object, action): leave-one-out cannot hold a class out.
  for (std::size_t k = 0; k < 2; ++k) {
    const fs::path path = dir / kObjects[k] / "strike" / "0.wav";
    fs::create_directories(path.parent_path());
    audio::write_audio(path.string(), recording(k, 1));
  }
  const RecordingSet set = load_recording_set(dir.string());
  try {
    train_observation_model(set, TrainOptions{});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("at least 2 recordings per (object, action)"));
  }
  TrainOptions magic, one_fold, small_margin;
  magic.classifier = "magic";
  one_fold.folds = 1;
  small_margin.reject_margin = 0.5;
  for (const auto* options : {&magic, &one_fold, &small_margin})
    EXPECT_THROW(train_observation_model(set, *options), InputError);
  // A corrupt recording is named.
  std::ofstream(dir / kObjects[0] / "strike" / "1.wav") << "RIFF garbage";
  try {
    train_observation_model(load_recording_set(dir.string()), TrainOptions{});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("1.wav"));
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace echoplan::perception
