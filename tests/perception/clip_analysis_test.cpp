// Tests of onset alignment on clips with the real robot's quirks: digital zeros, noise, other
// forces.
#include "perception/clip_analysis.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "synthetic_sounds.h"

namespace echoplan::perception {
namespace {

using test_sounds::strike;
using test_sounds::StrikeOptions;

const std::vector<test_sounds::Mode>& mug() { return test_sounds::three_objects()[1]; }

ClipAnalysis analyse(const audio::AudioClip& clip) {
  ClipAnalyzer analyzer(AnalysisSettings{});
  ClipAnalysis a;
  analyzer.analyse(clip, "test", a);
  return a;
}

// psf framing: 25 ms frames every 10 ms, start-aligned; the frame that first holds the strike at
// time t is frame ceil((t - 0.025) / 0.01) .. t / 0.01; the flux peaks on one of the two frames
// that first hold it.
void expect_onset_near(const ClipAnalysis& a, double seconds) {
  const double frame = seconds / a.hop_seconds;
  EXPECT_GE(static_cast<double>(a.onset_frame), frame - 2.5)
      << "onset " << a.onset_frame << ", strike at frame " << frame;
  EXPECT_LE(static_cast<double>(a.onset_frame), frame + 1.0)
      << "onset " << a.onset_frame << ", strike at frame " << frame;
}

TEST(ClipAnalysis, FindsAStrikeAfterTheRecordersDigitalZeros) {
  // The real recorder: 0.355 s of exact zeros, then robot noise, then the strike at 0.9 s.
  const auto clip = strike(
      mug(), {.duration_s = 2.5, .leading_zeros_s = 0.355, .onset_s = 0.9, .noise_rms = 0.003});
  const ClipAnalysis a = analyse(clip);
  // Frame 35 still overlaps the zeros' last 5 ms; 36 is the first frame wholly after it holds sound
  // (rms > 0).
  EXPECT_GE(a.first_sound_frame, 33u);
  EXPECT_LE(a.first_sound_frame, 36u);
  expect_onset_near(a, 0.9);
}

TEST(ClipAnalysis, OnsetSurvivesALevelChange) {
  // The same strike 20 dB softer over the same noise floor, and 6 dB louder: the same onset frame.
  StrikeOptions o{
      .duration_s = 2.0, .leading_zeros_s = 0.35, .onset_s = 0.7, .gain = 0.5, .noise_rms = 0.001};
  const std::size_t reference = analyse(strike(mug(), o)).onset_frame;
  expect_onset_near(analyse(strike(mug(), o)), 0.7);
  o.gain = 0.05;
  EXPECT_EQ(analyse(strike(mug(), o)).onset_frame, reference);
  o.gain = 0.99;
  EXPECT_EQ(analyse(strike(mug(), o)).onset_frame, reference);
}

TEST(ClipAnalysis, StrongestEventWinsOverAnEarlierSofterOne) {
  // A soft click 30 dB down at 0.4 s (a gripper noise), then the strike at 1.1 s.
  auto clip = strike(mug(), {.duration_s = 2.0, .onset_s = 1.1});
  const auto click =
      strike(test_sounds::three_objects()[2], {.duration_s = 2.0, .onset_s = 0.4, .gain = 0.016});
  for (std::size_t i = 0; i < clip.samples.size(); ++i) clip.samples[i] += click.samples[i];
  expect_onset_near(analyse(clip), 1.1);
}

TEST(ClipAnalysis, ResamplesAndMixesToTheModelRate) {
  auto clip = strike(mug(), {.sample_rate = 22050, .duration_s = 1.0, .onset_s = 0.5});
  const ClipAnalysis a = analyse(clip);
  EXPECT_EQ(a.sample_rate, 44100);
  EXPECT_EQ(a.mono.size(), 44100u);
  expect_onset_near(a, 0.5);
}

TEST(ClipAnalysis, FirstSoundFrameOfSilenceIsTheLastFrame) {
  audio::FeatureMatrix rms;
  rms.resize(4, 1);
  rms.values = {0.0f, 0.0f, 0.0f, 0.0f};
  EXPECT_EQ(first_sound_frame(rms, 0.0), 3u);
  rms.values = {0.0f, 1e-7f, 0.2f, 0.1f};
  EXPECT_EQ(first_sound_frame(rms, 1e-6), 2u);
  EXPECT_EQ(first_sound_frame(rms, 0.0), 1u);
}

TEST(ClipAnalysis, BadInput) {
  ClipAnalyzer analyzer(AnalysisSettings{});
  ClipAnalysis a;
  audio::AudioClip empty;
  EXPECT_THROW(analyzer.analyse(empty, "empty.wav", a), InputError);
  audio::AudioClip tiny;
  tiny.samples.assign(10, 0.1f);
  EXPECT_NO_THROW(analyzer.analyse(tiny, "tiny.wav", a));  // psf pads a short clip to one frame
  EXPECT_EQ(a.features.log_mel.rows, 1u);
  AnalysisSettings low_rate;
  low_rate.sample_rate = 10;
  EXPECT_THROW(ClipAnalyzer{low_rate}, InputError);
  AnalysisSettings bad_preset;
  bad_preset.preset = "nope";
  EXPECT_THROW(ClipAnalyzer{bad_preset}, InputError);
}

}  // namespace
}  // namespace echoplan::perception
