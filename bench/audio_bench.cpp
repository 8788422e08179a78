// Audio features of a 2 s, 44.1 kHz stereo clip on one core: every feature together (channel mean,
// STFT, log-mel, MFCC, centroid and the other spectral shapes, RMS, ZCR) against the "floor" of the
// same clip's STFT power spectrogram alone with the same framing. Results: docs/BENCHMARKS.md,
// "Audio features".
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "audio/features.h"
#include "audio/io.h"
#include "common/rng.h"

namespace {

using namespace echoplan::audio;

// A deterministic impact-like stereo clip: decaying partials plus low noise, right channel slightly
// delayed.
AudioClip make_clip() {
  AudioClip clip;
  clip.sample_rate = 44100;
  clip.channels = 2;
  const std::size_t frames = 2 * 44100;
  clip.samples.resize(frames * 2);
  echoplan::Rng rng(42);
  for (std::size_t n = 0; n < frames; ++n) {
    const double t = static_cast<double>(n) / 44100.0;
    double s = 0.0;
    for (double hz : {523.0, 1410.0, 2730.0, 4480.0})
      s += 0.2 * std::exp(-t * hz / 400.0) * std::sin(2 * std::numbers::pi * hz * t);
    const double noise = 0.01 * (echoplan::uniform01(rng) - 0.5);
    clip.samples[2 * n] = static_cast<float>(s + noise);
    clip.samples[2 * n + 1] = static_cast<float>(0.9 * s - noise);
  }
  return clip;
}

FeatureConfig preset(int index) { return index == 0 ? psf_preset(44100) : librosa_preset(44100); }

// One benchmark body for both measurements: `all_features` false is the floor (channel mean + STFT
// only).
void run(benchmark::State& state, bool all_features) {
  const AudioClip clip = make_clip();
  FeatureExtractor extractor(preset(static_cast<int>(state.range(0))));
  Features features;
  FeatureMatrix power;
  for (auto _ : state) {
    const AudioClip mono = convert_clip(clip, {.channel_policy = ChannelPolicy::mean}, "bench");
    if (all_features)
      extractor.compute(mono.samples, features);
    else
      extractor.power_spectrogram(mono.samples, power);
    benchmark::DoNotOptimize(features.mfcc.values.data());
    benchmark::DoNotOptimize(power.values.data());
  }
  state.SetLabel(state.range(0) == 0 ? "psf" : "librosa");
}

void BM_AllFeatures(benchmark::State& state) { run(state, true); }
void BM_StftFloor(benchmark::State& state) { run(state, false); }

BENCHMARK(BM_StftFloor)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AllFeatures)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
