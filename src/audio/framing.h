// Cutting a signal into overlapping frames: how many frames a signal gives and what each holds.
//
// Two conventions, both from the reference libraries:
//  - centred (librosa, center=True): frame t is centred on sample t * hop; the signal is padded
//  with
//    frame_length / 2 samples on each side (zeros, or copies of the edge sample), and there are
//    1 + (padded_length - frame_length) / hop frames (integer division);
//  - start-aligned (python_speech_features): frame t starts at sample t * hop; with pad_tail there
//  are
//    1 + ceil((length - frame_length) / hop) frames (1 if length <= frame_length) and the last is
//    zero- padded; without pad_tail only whole frames count and a signal shorter than one frame is
//    an error.
#pragma once

#include <cstddef>
#include <span>

namespace echoplan::audio {

enum class PadMode {
  zeros,  // np.pad(mode="constant"): librosa's STFT and RMS
  edge,   // np.pad(mode="edge"): librosa's zero-crossing rate
};

// Plain configuration of a framing. Invariants (checked by validate_framing): frame_length >= 1,
// hop >= 1.
struct FramingConfig {
  int frame_length = 2048;              // samples per frame
  int hop = 512;                        // samples between frame starts
  bool center = true;                   // centred frames (librosa) or start-aligned frames (psf)
  PadMode center_pad = PadMode::zeros;  // what fills the centring pad
  bool pad_tail =
      false;  // start-aligned only: zero-pad a partial last frame instead of dropping it
};

// Throws InputError naming the parameter if the configuration breaks an invariant.
void validate_framing(const FramingConfig& config);

// Frames a signal of `length` samples gives (0 if it gives none: length 0, or start-aligned without
// pad_tail and length < frame_length).
std::size_t frame_count(const FramingConfig& config, std::size_t length);

// Copies frame `index` of `signal` into `out` (size frame_length), padding as the config says.
void copy_frame(const FramingConfig& config, std::span<const float> signal, std::size_t index,
                std::span<float> out);

}  // namespace echoplan::audio
