// report-template reproduces the report's decision rule: templates are mean logfbank windows, a
// clip goes to the template with the smallest mean absolute difference. Checked on hand-made
// matrices.
#include "perception/report_template_classifier.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/error.h"

namespace echoplan::perception {
namespace {

constexpr std::size_t kWindow =
    ReportTemplateClassifier::kFramesBefore + ReportTemplateClassifier::kFramesAfter;

// A clip whose 2-band log filterbank is `before` up to the onset frame and `after` from it on.
ClipAnalysis clip(std::size_t frames, std::size_t onset, std::array<float, 2> before,
                  std::array<float, 2> after) {
  ClipAnalysis c;
  c.features.log_mel.resize(frames, 2);
  for (std::size_t t = 0; t < frames; ++t)
    for (std::size_t b = 0; b < 2; ++b)
      c.features.log_mel.at(t, b) = t < onset ? before[b] : after[b];
  c.onset_frame = onset;
  return c;
}

TEST(ReportTemplate, WindowIsAlignedOnTheOnset) {
  const ReportTemplateClassifier c;
  // The same sound starting at frame 40 or at frame 90 of a longer clip gives the same window.
  const auto early = ReportTemplateClassifier::onset_window(clip(300, 40, {-5, -5}, {3, 1}));
  const auto late = ReportTemplateClassifier::onset_window(clip(400, 90, {-5, -5}, {3, 1}));
  EXPECT_EQ(early, late);
  ASSERT_EQ(early.size(), kWindow * 2);
  // 10 frames before the onset, then the sound.
  EXPECT_EQ(early[0], -5);
  EXPECT_EQ(early[2 * 9 + 1], -5);
  EXPECT_EQ(early[2 * 10], 3);
  EXPECT_EQ(early[2 * 10 + 1], 1);
}

TEST(ReportTemplate, ReproducesTheReportsDecisionRule) {
  ReportTemplateClassifier c;
  // Class 0: two recordings with levels (1, 1) and (3, 5) after the onset: template (2, 3).
  // Class 1: one recording at (10, 10). Before the onset every clip is (0, 0).
  const std::vector<std::vector<double>> examples{
      ReportTemplateClassifier::onset_window(clip(200, 20, {0, 0}, {1, 1})),
      ReportTemplateClassifier::onset_window(clip(200, 20, {0, 0}, {3, 5})),
      ReportTemplateClassifier::onset_window(clip(200, 20, {0, 0}, {10, 10}))};
  c.fit(examples, std::vector<int>{0, 0, 1}, 2);
  ASSERT_EQ(c.num_classes(), 2);
  EXPECT_DOUBLE_EQ(c.templates()[0][2 * 10], 2.0);
  EXPECT_DOUBLE_EQ(c.templates()[0][2 * 10 + 1], 3.0);
  // A clip at (6, 4): |6-2| + |4-3| = 5 per sound frame against class 0, |6-10| + |4-10| = 10
  // against class 1; the 10 frames before the onset match both. Mean over 150 frames x 2 bands:
  //   class 0: 140 * 5 / 300 = 2.3333..., class 1: 140 * 10 / 300 = 4.6666...
  const ClassScores s =
      c.score(ReportTemplateClassifier::onset_window(clip(200, 20, {0, 0}, {6, 4})));
  EXPECT_NEAR(s.distances[0], 140.0 * 5 / 300, 1e-6);
  EXPECT_NEAR(s.distances[1], 140.0 * 10 / 300, 1e-6);
  EXPECT_EQ(s.log_scores[0], -s.distances[0]);
  // (9, 9) is nearer class 1: 140 * 13 / 300 against 140 * 2 / 300.
  const ClassScores t =
      c.score(ReportTemplateClassifier::onset_window(clip(200, 20, {0, 0}, {9, 9})));
  EXPECT_LT(t.distances[1], t.distances[0]);
}

TEST(ReportTemplate, SaveLoadRoundTripAndErrors) {
  ReportTemplateClassifier c;
  c.fit(
      std::vector<std::vector<double>>{
          ReportTemplateClassifier::onset_window(clip(200, 20, {0, 0}, {1, 2})),
          ReportTemplateClassifier::onset_window(clip(200, 20, {0, 0}, {4, 4}))},
      std::vector<int>{0, 1}, 2);
  ReportTemplateClassifier back;
  back.load(c.save(), "m.json");
  EXPECT_EQ(back.templates(), c.templates());
  nlohmann::json bad = c.save();
  bad["templates"][1].erase(3);
  EXPECT_THROW(back.load(bad, "m.json"), InputError);
  bad = c.save();
  bad["frames_after"] = 100;
  EXPECT_THROW(back.load(bad, "m.json"), InputError);
  EXPECT_THROW(c.fit(std::vector<std::vector<double>>{ReportTemplateClassifier::onset_window(
                         clip(200, 20, {0, 0}, {1, 2}))},
                     std::vector<int>{0}, 2),
               InputError);  // class 1 has no recording
}

}  // namespace
}  // namespace echoplan::perception
