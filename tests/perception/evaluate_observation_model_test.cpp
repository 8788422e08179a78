// Held-out evaluation: known objects against the model's symbols, strangers as `unknown`.
#include "perception/evaluate_observation_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "perception/fit_observation_model.h"
#include "trained_model.h"

namespace echoplan::perception {
namespace {

namespace fs = std::filesystem;
using test_model::kObjects;
using test_model::recording;
using test_model::trained;

TEST(EvaluateObservationModel, CountsHeldOutRecordingsIncludingUnknownObjects) {
  const fs::path held = trained().dir / "held_out";
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
  int last_done = 0, last_total = 0;
  const Evaluation e =
      evaluate_observation_model(trained().model, load_recording_set(held.string()),
                                 [&](const std::string&, int done, int total) {
                                   last_done = done;
                                   last_total = total;
                                 });
  EXPECT_EQ(last_done, 8);
  EXPECT_EQ(last_total, 8);
  ASSERT_EQ(e.per_action.size(), 1u);
  const ConfusionMatrix& c = e.per_action[0];
  EXPECT_EQ(c.total(), 8);
  EXPECT_DOUBLE_EQ(c.accuracy(), 1.0);
  const auto hum_row = static_cast<std::size_t>(
      std::find(c.objects.begin(), c.objects.end(), "hum") - c.objects.begin());
  EXPECT_EQ(c.counts[hum_row][3], 2);  // both hums are unknown
}

// A set recorded on two tables is counted table by table too: each table's matrix is what the same
// model hears on that table's recordings alone, and the tables add up to the whole. (No column, no
// tables: the test above's set has none.)
TEST(EvaluateObservationModel, CountsEachTableOfASetRecordedOnSeveral) {
  const fs::path dir = test_model::write_two_tables("evaluate_tables");
  const RecordingSet set = load_recording_set(dir.string());
  RecordingSet hard = set;
  std::erase_if(hard.recordings, [](const Recording& r) { return r.surface != "hard"; });
  FitOptions no_reject;
  no_reject.reject = false;
  const ObservationModel model = train_observation_model(hard, no_reject);
  const Evaluation all = evaluate_observation_model(model, set);
  ASSERT_EQ(all.per_surface.size(), 2u);
  ConfusionMatrix sum =
      ConfusionMatrix::zeros(all.per_action[0].objects, all.per_action[0].symbols);
  for (const std::string table : {"hard", "soft"}) {
    RecordingSet alone = set;
    std::erase_if(alone.recordings, [&](const Recording& r) { return r.surface != table; });
    const Evaluation e = evaluate_observation_model(model, alone);
    ASSERT_EQ(all.per_surface.at(table).size(), 1u);
    EXPECT_EQ(all.per_surface.at(table)[0].counts, e.per_action[0].counts) << table;
    for (std::size_t k = 0; k < sum.counts.size(); ++k)
      for (std::size_t o = 0; o < sum.counts[k].size(); ++o)
        sum.counts[k][o] += e.per_action[0].counts[k][o];
  }
  EXPECT_EQ(sum.counts, all.per_action[0].counts);
  EXPECT_DOUBLE_EQ(all.per_surface.at("hard")[0].accuracy(), 1.0);  // the table it was trained on
  EXPECT_TRUE(evaluate_observation_model(trained().model, trained().set).per_surface.empty());
  fs::remove_all(dir);
}

TEST(EvaluateObservationModel, RefusesActionsTheModelWasNotTrainedFor) {
  const fs::path held = trained().dir / "held_out_shake";
  for (std::size_t k = 0; k < 2; ++k) {
    const fs::path path = held / kObjects[k] / "shake" / "0.wav";
    fs::create_directories(path.parent_path());
    audio::write_audio(path.string(), recording(k, 5000 + static_cast<unsigned>(k)));
  }
  try {
    evaluate_observation_model(trained().model, load_recording_set(held.string()));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(),
              "action 'shake' of the recordings is not in the model (it was trained for: strike, "
              "tap)");
  }
}

}  // namespace
}  // namespace echoplan::perception
