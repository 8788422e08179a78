// Observations graded by level: the class heard and how noisy its recording was, measured from
// the recording (audio/levels.h) against the terciles of the training recordings' levels. Trained
// on quiet strikes and their twins in loud white noise, the noisy grade comes with more wrong
// decisions than right ones, so a noisy reading tells the planner less; the model file keeps the
// level grades, and a model fitted on features without levels has none and says so.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>

#include "audio/io.h"
#include "audio/levels.h"
#include "common/error.h"
#include "perception/fit_observation_model.h"
#include "perception/observation_grades.h"
#include "perception/observation_model_json.h"
#include "perception/recording_set.h"
#include "synthetic_feature_set.h"
#include "trained_model.h"

namespace echoplan::perception {
namespace {

// `clip` with white noise at `ebr_db` below its event level (independent of echoplan's mixer).
audio::AudioClip in_white_noise(audio::AudioClip clip, double ebr_db, unsigned seed) {
  const double rms = audio::event_level(clip) / std::pow(10.0, ebr_db / 20.0);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, rms);
  for (float& x : clip.samples) x += static_cast<float>(noise(rng));
  return clip;
}

// Three struck objects, six quiet strikes each and six in white noise 12 dB above the event.
std::filesystem::path quiet_and_noisy_strikes() {
  const std::filesystem::path dir = test_sounds::fresh_dir("levels_set");
  for (std::size_t k = 0; k < test_model::kObjects.size(); ++k)
    for (unsigned i = 0; i < 12; ++i) {
      audio::AudioClip clip = test_model::recording(k, 100 * static_cast<unsigned>(k) + i);
      if (i % 2) clip = in_white_noise(std::move(clip), -12.0, 7 + i + 100 * k);
      const auto path = dir / test_model::kObjects[k] / "strike" / (std::to_string(i) + ".wav");
      std::filesystem::create_directories(path.parent_path());
      audio::write_audio(path.string(), clip);
    }
  return dir;
}

TEST(ObservationLevels, SymbolsAreNamedClassAtLevelNoisiestFirst) {
  EXPECT_EQ(graded_symbols({"mug"}, false, ObservationKind::levels),
            (std::vector<std::string>{"mug@noisy", "mug@fair", "mug@clear"}));
  EXPECT_EQ(class_of_symbol("mug@clear"), "mug");
  EXPECT_EQ(class_of_symbol("mug@high"), "mug");
  EXPECT_EQ(parse_observation_kind("levels"), ObservationKind::levels);
  EXPECT_STREQ(observation_kind_name(ObservationKind::levels), "levels");
}

TEST(ObservationLevels, ANoisyRecordingIsHeardAsNoisyAndANoisyReadingTellsLess) {
  const auto dir = quiet_and_noisy_strikes();
  const ObservationModel model =
      train_observation_model(load_recording_set(dir.string()), FitOptions{});
  ASSERT_TRUE(model.levelled());
  const ActionCalibration& c = model.calibration("strike");
  ASSERT_TRUE(c.level_grades.has_value());
  // Half the strikes are drowned: they fill the noisy grade, where the classifier errs more.
  const auto& g = *c.level_grades;
  // A drowned strike measures about 0 dB (its loudest window is mostly noise), a quiet one tens
  // of dB, and every quiet one is heard right: the cuts (informative_edges) lie among the drowned
  // strikes, where right and wrong readings part, and the quiet ones are all clear.
  EXPECT_LT(g.edges[0], 10.0);
  EXPECT_LT(g.edges[1], 10.0);
  EXPECT_GT(g.given_wrong[0], g.given_right[0]);
  EXPECT_GT(g.given_right[2], g.given_wrong[2]);
  // So the likelihood ratio of hearing the true class is lower in noise than in the clear.
  const auto& table = model.observation_table("strike", ObservationKind::levels);
  const int n = static_cast<int>(model.classes().size());
  const auto cell = [&](int truth, int heard, int level) {
    return table[static_cast<std::size_t>(truth)]
                [static_cast<std::size_t>(graded_symbol(heard, level, n))];
  };
  EXPECT_LT(cell(0, 0, 0) / cell(1, 0, 0), cell(0, 0, 2) / cell(1, 0, 2));
  for (const auto& row : table) {
    double sum = 0.0;
    for (double p : row) sum += p;
    EXPECT_NEAR(sum, 1.0, 1e-9);
  }
  // A new strike is graded by its own recording's level.
  const audio::AudioClip quiet = test_model::recording(1, 4242);
  EXPECT_EQ(model.classify(test_model::analysed(model, quiet), "strike").level_grade, 2);
  const audio::AudioClip noisy = in_white_noise(quiet, -12.0, 99);
  EXPECT_LT(model.classify(test_model::analysed(model, noisy), "strike").level_grade, 2);

  nlohmann::json file = observation_model_to_json(model);
  const ObservationModel back = observation_model_from_json(file, "model.json");
  EXPECT_EQ(back.observation_table("strike", ObservationKind::levels), table);
  EXPECT_EQ(back.calibration("strike").level_grades->edges, g.edges);
  for (auto& [action, entry] : file["per_action"].items()) entry.erase("level_grades");
  EXPECT_FALSE(observation_model_from_json(file, "old.json").levelled());
  std::filesystem::remove_all(dir);
}

TEST(ObservationLevels, AModelFittedOnFeaturesWithoutLevelsHasNoneAndSaysSo) {
  SyntheticSpec spec;
  spec.objects = 3;
  spec.sessions = 3;
  const auto dir = test_features::fresh_folder("levels_features");
  test_features::write_synthetic_feature_set(dir, spec);
  const FeatureSet set = load_feature_set(dir.string());
  const DatasetTask task = make_dataset_task(set, nullptr, HoldOut::session);
  const std::vector<int> all{0, 1, 2, 3, 4, 5, 6, 7, 8};
  const ObservationModel model = fit_observation_model(set, task, all, session_fit_options());
  EXPECT_FALSE(model.levelled());
  try {
    model.observation_symbols(ObservationKind::levels);
    ADD_FAILURE() << "a model without levels listed level symbols";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no observations graded by level"), std::string::npos);
  }
}

}  // namespace
}  // namespace echoplan::perception
