// libFuzzer target: arbitrary bytes through the audio decoder (libsndfile over memory) and, when
// they decode, through every feature extractor. Bad input must end in echoplan::InputError;
// anything else (a crash, a sanitizer report, another exception, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <span>

#include "audio/features.h"
#include "audio/io.h"
#include "audio/onsets.h"
#include "common/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace echoplan::audio;
  try {
    // At most 1 s so that each input runs in bounded time and memory.
    const AudioClip clip =
        read_audio_memory(std::span<const std::uint8_t>(data, size), "fuzz",
                          {.channel_policy = ChannelPolicy::mean, .max_duration_seconds = 1.0});
    (void)global_features(clip.samples, clip.sample_rate);
    for (const auto& config : {psf_preset(clip.sample_rate), librosa_preset(clip.sample_rate)}) {
      try {
        FeatureExtractor extractor(config);
        Features features;
        extractor.compute(clip.samples, features);
        const std::size_t anchor = alignment_frame(features.flux, OnsetChoice::strongest);
        (void)onset_window(features.mfcc, anchor, 3, 10);
      } catch (const echoplan::InputError&) {
        // A rate the preset cannot use (e.g. 1 Hz gives a zero-length psf frame): a clear error is
        // correct.
      }
    }
  } catch (const echoplan::InputError&) {
    // Not decodable audio: the documented outcome.
  }
  return 0;
}
