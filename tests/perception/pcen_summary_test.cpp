// pcen_summary on synthetic strikes, its behaviour following from the signal: a strike far above
// its background reads the same at another force, a louder room lowers how far it rises, and the
// recorder's leading digital silence is not taken for a background.
#include "perception/pcen_summary.h"

#include <gtest/gtest.h>

#include <set>

#include "common/error.h"
#include "perception/summary_features.h"
#include "synthetic_sounds.h"

namespace echoplan::perception {
namespace {

using test_sounds::Mode;
using test_sounds::strike;
using test_sounds::StrikeOptions;

const std::vector<Mode> kPcenRing{{1000.0, 0.05, 1.0}};  // one mode, τ = 50 ms

ClipAnalysis pcen_analysed(const StrikeOptions& options) {
  ClipAnalyzer analyzer(AnalysisSettings{});
  ClipAnalysis analysis;
  analyzer.analyse(strike(kPcenRing, options), "test", analysis);
  return analysis;
}

std::vector<double> pcen_row(const StrikeOptions& options) {
  return pcen_summary(pcen_analysed(options));
}

TEST(PcenSummary, NamesOneEntryEachInTheDocumentedLayout) {
  const std::vector<std::string> names = pcen_summary_names();
  ASSERT_EQ(names.size(), kPcenSummarySize);
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), kPcenSummarySize);
  EXPECT_EQ(names[0], "pcen0_band0");
  EXPECT_EQ(names[103], "pcen3_band25");
  EXPECT_EQ(pcen_row(StrikeOptions{.noise_rms = 1e-3}).size(), kPcenSummarySize);
}

// Mean of segment `segment`'s 26 bands.
double pcen_segment_mean(const std::vector<double>& row, std::size_t segment) {
  double sum = 0.0;
  for (std::size_t b = 0; b < kSummaryBands; ++b) sum += row[segment * kSummaryBands + b];
  return sum / kSummaryBands;
}

TEST(PcenSummary, AStrikeFarAboveItsBackgroundReadsTheSameAtAnotherForce) {
  // 80 and 100 dB above the room: each band's rise is measured against its own average, which the
  // event itself lifts, so a strike ten times stronger reads within a tenth of the weaker.
  const std::vector<double> soft = pcen_row(StrikeOptions{.gain = 0.05, .noise_rms = 1e-6});
  const std::vector<double> hard = pcen_row(StrikeOptions{.gain = 0.5, .noise_rms = 1e-6});
  for (std::size_t i = 0; i < 2 * kSummaryBands; ++i)
    EXPECT_NEAR(hard[i], soft[i], 0.1 * std::max(1.0, soft[i])) << "entry " << i;
}

TEST(PcenSummary, ALouderRoomLowersHowFarTheStrikeRises) {
  // The same strike 60 dB and 20 dB above the room: the attack stands less far above the louder
  // background, in every band and on average by over a third.
  const std::vector<double> quiet = pcen_row(StrikeOptions{.noise_rms = 1e-4});
  const std::vector<double> loud = pcen_row(StrikeOptions{.noise_rms = 1e-2});
  EXPECT_LT(pcen_segment_mean(loud, 0), 0.67 * pcen_segment_mean(quiet, 0));
  for (std::size_t b = 0; b < kSummaryBands; ++b) EXPECT_LT(loud[b], quiet[b]) << "band " << b;
}

TEST(PcenSummary, LeadingDigitalSilenceIsNotABackground) {
  // The real recorder opens with 0.35 s of zeros; a strike 0.1 s after them reads as one 0.1 s
  // into a clip of room noise throughout (the same noise samples), not as one after silence: within
  // 15%, the frames that straddle the end of the silence holding less of the room's noise. Divided
  // by an average started in the silence, the attack would read 1/s = 40 times its background.
  const std::vector<double> plain = pcen_row(StrikeOptions{.onset_s = 0.1, .noise_rms = 1e-3});
  const std::vector<double> zeros =
      pcen_row(StrikeOptions{.leading_zeros_s = 0.35, .onset_s = 0.45, .noise_rms = 1e-3});
  for (std::size_t i = 0; i < kPcenSummarySize; ++i)
    EXPECT_NEAR(zeros[i], plain[i], 0.15 * std::max(1.0, plain[i])) << "entry " << i;
}

TEST(PcenSummary, RefusesAnalysisWithoutThePsfBands) {
  ClipAnalysis clip = pcen_analysed(StrikeOptions{.noise_rms = 1e-3});
  clip.features.log_mel.resize(clip.features.log_mel.rows, 40);
  EXPECT_THROW(pcen_summary(clip), InputError);
  clip.features.log_mel.resize(0, kSummaryBands);
  EXPECT_THROW(pcen_summary(clip), InputError);
}

}  // namespace
}  // namespace echoplan::perception
