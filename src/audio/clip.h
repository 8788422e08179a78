// An audio clip: interleaved float samples in [-1, 1) at a known rate, recorded or synthesized.
//
// The one type that carries sound between modules: files read from disk, the simulator's
// synthesized recordings and (later) live microphone captures are all AudioClips.
#pragma once

#include <cstddef>
#include <vector>

namespace echoplan::audio {

struct AudioClip {
  int sample_rate = 44100;     // frames per second
  int channels = 1;            // >= 1
  std::vector<float> samples;  // interleaved: frame f, channel c at samples[f * channels + c]

  std::size_t frames() const {
    return channels > 0 ? samples.size() / static_cast<std::size_t>(channels) : 0;
  }
  double duration_seconds() const {
    return sample_rate > 0 ? static_cast<double>(frames()) / sample_rate : 0.0;
  }
};

}  // namespace echoplan::audio
