// summary_features on synthetic strikes whose answers follow from the signal, not from the code:
// a louder copy and a later copy of the same sound give the same summary (it is measured from the
// onset and relative to the peak); a mode decaying with time constant τ falls 10/20/30 dB after
// τ·ln(10)·{0.5, 1, 1.5} s; a higher tone has a higher centroid; noise is flatter than a tone.
#include "perception/summary_features.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "common/error.h"
#include "synthetic_sounds.h"

namespace echoplan::perception {
namespace {

using test_sounds::Mode;
using test_sounds::strike;
using test_sounds::StrikeOptions;

std::array<double, kSummarySize> summary_of(const audio::AudioClip& clip) {
  ClipAnalyzer analyzer(AnalysisSettings{});
  ClipAnalysis analysis;
  analyzer.analyse(clip, "test", analysis);
  return summary_features(analysis);
}

// Index of the entry called `name` in the layout.
std::size_t index_of(const std::string& name) {
  const std::vector<std::string> names = summary_feature_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  ADD_FAILURE() << "no summary entry " << name;
  return 0;
}

// Frames (10 ms) from the onset until the level fell `db` below its peak, from the decay entry.
double decay_frames(const std::array<double, kSummarySize>& s, int db) {
  return std::expm1(s[index_of("decay" + std::to_string(db))]);
}

const std::vector<Mode> kRing{{1000.0, 0.05, 1.0}};  // one mode, τ = 50 ms

TEST(SummaryFeatures, NamesOneEntryEachInTheDocumentedLayout) {
  const std::vector<std::string> names = summary_feature_names();
  ASSERT_EQ(names.size(), kSummarySize);
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), kSummarySize);
  // The header's layout: 4 segments x 26 bands, 12 MFCC spreads, 3 decays, 2 flatness, 2 centroid.
  EXPECT_EQ(names[0], "shape0_band0");
  EXPECT_EQ(names[103], "shape3_band25");
  EXPECT_EQ(names[104], "mfcc_std1");
  EXPECT_EQ(names[115], "mfcc_std12");
  EXPECT_EQ(names[116], "decay10");
  EXPECT_EQ(names[118], "decay30");
  EXPECT_EQ(names[119], "flatness_early");
  EXPECT_EQ(names[122], "centroid_late");
}

TEST(SummaryFeatures, ALouderCopyGivesTheSameSummary) {
  StrikeOptions soft;
  soft.gain = 0.05;
  StrikeOptions loud = soft;
  loud.gain = 0.5;  // 20 dB louder
  const auto a = summary_of(strike(kRing, soft));
  const auto b = summary_of(strike(kRing, loud));
  for (std::size_t i = 0; i < kSummarySize; ++i)
    EXPECT_NEAR(a[i], b[i], 1e-3) << summary_feature_names()[i];
}

TEST(SummaryFeatures, ALaterCopyAfterDigitalSilenceGivesTheSameSummary) {
  StrikeOptions early;
  early.onset_s = 0.3;
  StrikeOptions late = early;
  late.leading_zeros_s = 0.35;  // the real recorder's opening
  late.onset_s = 0.5;           // 20 hops of 10 ms later
  late.duration_s = early.duration_s + 0.2;
  const auto a = summary_of(strike(kRing, early));
  const auto b = summary_of(strike(kRing, late));
  for (std::size_t i = 0; i < kSummarySize; ++i)
    EXPECT_NEAR(a[i], b[i], 1e-3) << summary_feature_names()[i];
}

TEST(SummaryFeatures, DecayEntriesFollowTheModesTimeConstant) {
  // Power falls as exp(-2t/τ): D dB below the peak after t = τ·ln(10)·D/20. Each entry counts from
  // the onset frame, the first frame whose window holds the strike, which starts up to one window
  // (25 ms, 2.5 hops) before it, to the first frame below the threshold: so each count lies in
  // [t, t + 4] frames, and the differences between the three (the offset cancels) match the
  // analytic ones to the one-frame rounding of each count.
  for (const double tau : {0.03, 0.08}) {
    StrikeOptions o;
    o.duration_s = 2.0;
    const auto s = summary_of(strike({{1000.0, tau, 1.0}}, o));
    auto analytic = [&](int db) { return 100.0 * tau * std::log(10.0) * db / 20.0; };
    for (const int db : {10, 20, 30}) {
      EXPECT_GE(decay_frames(s, db), analytic(db)) << "tau " << tau << " s, " << db << " dB";
      EXPECT_LE(decay_frames(s, db), analytic(db) + 4.0) << "tau " << tau << " s, " << db << " dB";
    }
    EXPECT_NEAR(decay_frames(s, 20) - decay_frames(s, 10), analytic(20) - analytic(10), 1.0)
        << "tau " << tau;
    EXPECT_NEAR(decay_frames(s, 30) - decay_frames(s, 20), analytic(30) - analytic(20), 1.0)
        << "tau " << tau;
  }
}

TEST(SummaryFeatures, CentroidRisesWithATonesFrequency) {
  // The psf preset frames with python_speech_features' defaults: no window, and frames cut to the
  // 512-point FFT. A pure tone then leaks into every bin and its magnitude-weighted centroid lies
  // far above the tone (about 3 kHz for 500 Hz), so only the order is a property to rely on; the
  // classifier uses it as a brightness cue, not as a frequency.
  StrikeOptions o;
  const auto low = summary_of(strike({{500.0, 0.5, 1.0}}, o));  // rings through both halves
  const auto high = summary_of(strike({{2000.0, 0.5, 1.0}}, o));
  for (const char* half : {"centroid_early", "centroid_late"}) {
    EXPECT_GT(std::expm1(high[index_of(half)]), std::expm1(low[index_of(half)]) + 500.0) << half;
    EXPECT_GT(std::expm1(low[index_of(half)]), 500.0) << half;
  }
}

TEST(SummaryFeatures, NoiseIsFlatterThanATone) {
  StrikeOptions tone_options;
  const auto tone = summary_of(strike({{1000.0, 0.5, 1.0}}, tone_options));
  StrikeOptions noise_options;
  noise_options.gain = 0.0;
  noise_options.noise_rms = 0.1;
  noise_options.onset_s = 0.0;
  const auto noise = summary_of(strike({}, noise_options));
  for (const char* half : {"flatness_early", "flatness_late"}) {
    // ln(geometric / arithmetic mean) of the band energies: 0 for a flat spectrum, below for a
    // peaked one. White noise's mel bands hold energy in proportion to their widths (psf's
    // triangles are not area-normalised), so it is well below 0; a tone is lower still, though
    // less than it would be with a window: the unwindowed frames leak it into every band.
    EXPECT_LT(noise[index_of(half)], 0.0) << half;
    EXPECT_LT(tone[index_of(half)], noise[index_of(half)] - 0.5) << half;
  }
}

TEST(SummaryFeatures, RefusesFeaturesOfAnotherShape) {
  ClipAnalysis analysis;
  analysis.features.log_mel.resize(10, 40);  // not the psf preset's 26 bands
  analysis.features.mfcc.resize(10, 13);
  EXPECT_THROW(summary_features(analysis), InputError);
  analysis.features.log_mel.resize(0, 26);  // no frame at all
  analysis.features.mfcc.resize(0, 13);
  EXPECT_THROW(summary_features(analysis), InputError);
}

}  // namespace
}  // namespace echoplan::perception
