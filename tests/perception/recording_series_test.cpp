// Tests of a recordings tree's series as modalities: the rows their features give, the model file
// that keeps how they were computed, and data computed another way refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "../common/input_error_message.h"
#include "../common/test_folder.h"
#include "perception/observation_model.h"
#include "perception/performance_reader.h"
#include "perception/recording_features.h"
#include "signal/series.h"
#include "synthetic_sounds.h"

namespace echoplan::perception {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A haptic-only robot's tree: objects heavy and light, behaviour lift, four performances each;
// effort j1 of performance p of an object of weight w is w * (i + 1) + p at samples i = 0..3, so
// its two bins of sums are w * 3 + 2p and w * 7 + 2p.
class RecordingSeriesTest : public TestFolder {
 protected:
  void SetUp() override {
    TestFolder::SetUp();
    for (const auto& [object, weight] : {std::pair("heavy", 5.0), std::pair("light", 1.0)})
      for (int p = 0; p < 4; ++p) {
        signal::Series s;
        s.channels = {"j1"};
        s.values.resize(1);
        for (int i = 0; i < 4; ++i) {
          s.t.push_back(0.01 * i);
          s.values[0].push_back(weight * (i + 1) + p);
        }
        fs::create_directories(dir_ / object / "lift");
        signal::write_series_csv(
            (dir_ / object / "lift" / (std::to_string(p) + ".effort.csv")).string(), s);
      }
  }
};

TEST_F(RecordingSeriesTest, SeriesBecomeRowsByTheChosenFeatures) {
  const FeatureSet set = feature_set_from_recordings(load_recording_set(dir_.string()), {}, {},
                                                     "summary", {{"effort", "bins(2,sum)"}});
  ASSERT_EQ(set.actions.size(), 1u);
  const ActionData& lift = set.actions[0];
  ASSERT_EQ(lift.modalities.size(), 1u);
  const Modality& effort = lift.modalities[0];
  EXPECT_EQ(effort.name, "effort");
  EXPECT_EQ(effort.series, "bins(2,sum)");
  EXPECT_EQ(effort.extractor, "");
  EXPECT_EQ(effort.feature_names, (std::vector<std::string>{"j1_b1", "j1_b2"}));
  ASSERT_EQ(effort.rows.size(), 8u);
  EXPECT_EQ(set.objects, (std::vector<std::string>{"heavy", "light"}));
  EXPECT_EQ(effort.rows[1], (std::vector<double>{5 * 3 + 2, 5 * 7 + 2}));  // heavy, performance 1
  EXPECT_EQ(effort.rows[4], (std::vector<double>{3, 7}));                  // light, performance 0
  EXPECT_FALSE(lift.rows[0].ebr_db.has_value());                           // no audio, no level
  // Without a choice, the default: means of ten bins need ten samples.
  EXPECT_THAT(input_error_message([&] { load_data(dir_.string()); }),
              HasSubstr("4 samples, fewer than the 10 bins"));
  EXPECT_THAT(input_error_message([&] {
                load_data(dir_.string(), {}, {{"force", "stats"}});
              }),
              HasSubstr("no performance has a 'force' series (series here: effort)"));
}

TEST_F(RecordingSeriesTest, TheModelFileKeepsHowSeriesBecameRows) {
  FitChoices choices;
  choices.series = {{"effort", "bins(2,sum)"}};
  const FitOptions options = choose_fit_options(choices, DataKind::recordings, false);
  const ObservationModel model =
      train_observation_model(load_recording_set(dir_.string()), options);
  ASSERT_EQ(model.modalities("lift").size(), 1u);
  EXPECT_EQ(model.modalities("lift")[0].series, "bins(2,sum)");
  const fs::path file = dir_ / "model.json";
  save_observation_model(model, file.string());
  const ObservationModel back = load_observation_model(file.string());
  EXPECT_EQ(back.modalities("lift")[0].series, "bins(2,sum)");
  // The loaded model hears the rows as the fitted one does: heavy and light are far apart.
  const FeatureSet same = load_data(dir_.string(), {}, {{"effort", "bins(2,sum)"}});
  const PerformanceReader reader(back, "lift", same);
  EXPECT_EQ(reader.classify(0).best_class, 0);
  EXPECT_EQ(reader.classify(7).best_class, 1);
  EXPECT_EQ(series_choices(back), (SeriesChoices{{"effort", "bins(2,sum)"}}));
  // Rows of the same length computed by means are other features: refused, saying how to fix it.
  const FeatureSet means = load_data(dir_.string(), {}, {{"effort", "bins(2,mean)"}});
  EXPECT_THAT(input_error_message([&] { PerformanceReader(back, "lift", means); }),
              HasSubstr("--series effort=bins(2,sum)"));
}

TEST_F(RecordingSeriesTest, AudioWithSeriesIsFittedWithoutTheRejectOption) {
  unsigned seed = 1;
  for (const char* object : {"heavy", "light"})
    for (int p = 0; p < 4; ++p) {
      test_sounds::StrikeOptions strike;
      strike.duration_s = 0.6;
      strike.seed = seed++;
      strike.detune = 0.01;
      audio::write_audio(
          (dir_ / object / "lift" / (std::to_string(p) + ".wav")).string(),
          test_sounds::strike(test_sounds::three_objects()[object[0] == 'h' ? 0 : 1], strike));
    }
  FitChoices choices;
  choices.series = {{"effort", "bins(2,sum)"}};
  const FitOptions options = choose_fit_options(choices, DataKind::recordings, false, true);
  EXPECT_FALSE(options.reject);
  const ObservationModel model =
      train_observation_model(load_recording_set(dir_.string()), options);
  const auto& modalities = model.modalities("lift");
  ASSERT_EQ(modalities.size(), 2u);
  EXPECT_EQ(modalities[0].name, "audio");
  EXPECT_NE(modalities[0].classifier->extractor(), nullptr);
  EXPECT_EQ(modalities[1].name, "effort");
  EXPECT_EQ(modalities[1].classifier->extractor(), nullptr);
  // Chosen back on, the reject option is refused with the flag that turns it off.
  choices.reject = true;
  EXPECT_THAT(input_error_message([&] {
                train_observation_model(
                    load_recording_set(dir_.string()),
                    choose_fit_options(choices, DataKind::recordings, false, true));
              }),
              HasSubstr("--no-reject"));
}

}  // namespace
}  // namespace echoplan::perception
