// Heard confusion: leave-one-out counts per action, right where the objects differ, wrong where one
// object's recordings are another's.
#include "perception/heard_confusion.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "trained_model.h"

namespace echoplan::perception {
namespace {

namespace fs = std::filesystem;
using test_model::kObjects;

TEST(HeardConfusion, DistinctObjectsAreAllHeardRight) {
  // Three objects with different modes (test_sounds::three_objects): every held-out strike is
  // nearest its own object's template, so each action's matrix is 4 on the diagonal.
  const auto& t = test_model::trained();
  const std::vector<HeardConfusion> heard = heard_confusion(t.set, "report-template");
  ASSERT_EQ(heard.size(), 2u);
  EXPECT_EQ(heard[0].action, t.set.actions[0]);
  for (const HeardConfusion& h : heard) {
    EXPECT_EQ(h.confusion.objects, t.set.objects);
    EXPECT_EQ(h.confusion.symbols, t.set.objects);  // no `unknown` column
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        EXPECT_EQ(h.confusion.counts[i][j], i == j ? 4 : 0) << h.action << " " << i << " " << j;
  }
}

TEST(HeardConfusion, AnObjectWhoseRecordingsAreAnothersIsHeardAsIt) {
  // "twin" holds exact copies of "ring"'s strikes. Held out, a ring strike x is compared with the
  // mean of the other three ring strikes, m3, and with twin's mean (x + 3 m3) / 4, which is exactly
  // 3/4 as far from x in every value: every ring strike is heard as the twin, and every twin strike
  // as the ring, by the same argument. "thud" differs from both and is heard right.
  const fs::path dir = test_sounds::fresh_dir("heard_twin");
  const std::vector<std::pair<std::string, std::size_t>> objects{
      {"thud", 0}, {"ring", 1}, {"twin", 1}};
  for (const auto& [name, k] : objects)
    for (unsigned i = 0; i < 4; ++i) {
      const fs::path path = dir / name / "strike" / (std::to_string(i) + ".wav");
      fs::create_directories(path.parent_path());
      audio::write_audio(path.string(), test_model::recording(k, 40 + 10 * k + i));
    }
  const RecordingSet set = load_recording_set(dir.string());
  const std::vector<HeardConfusion> heard = heard_confusion(set, "report-template");
  ASSERT_EQ(heard.size(), 1u);
  const ConfusionMatrix& c = heard[0].confusion;
  const int ring = set.object_index("ring"), twin = set.object_index("twin"),
            thud = set.object_index("thud");
  EXPECT_EQ(c.counts[ring][twin], 4);
  EXPECT_EQ(c.counts[twin][ring], 4);
  EXPECT_EQ(c.counts[thud][thud], 4);
  EXPECT_EQ(c.total(), 12);
  EXPECT_THROW(heard_confusion(set, "no-such-classifier"), InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace echoplan::perception
