// Background noise heard with a recording, at an event-to-background ratio (EBR): the noise of a
// room where people talk or a machine runs, mixed into what the microphone recorded
// (docs/noise.md).
//
// Levels, as the field states them (DCASE's office events; the knocks in issue 52): the event's is
// the RMS of its loudest 50 ms (channels averaged), the background's the RMS of the noise added
// over the whole clip, and EBR = 20 log10(event / background). The noise is one segment of one
// source, looped if the source is shorter than the clip, at the clip's rate and added alike to
// every channel; which source, where in it and (for a range of EBRs) which ratio are drawn from the
// caller's Rng, so the same seed gives the same noise.
//
// Sources: recordings (files, or folders read recursively for .wav/.flac/.aiff files in name
// order), or built-in noise made at the clip's rate from the Rng: "white" (unit white noise),
// "room" (the simulator's room noise, flat below 500 Hz and falling 6 dB per octave above) and
// "motor" (the simulated arm's motor band, sim/sound_motor.h, running steadily). The levels are
// audio/levels.h's.
#pragma once

#include <string>
#include <vector>

#include "audio/clip.h"
#include "common/rng.h"

namespace echoplan::sim {

// An EBR in dB, one number or a range drawn uniformly per recording.
struct EbrRange {
  double low = 0.0;
  double high = 0.0;
};
// "X" or "LO:HI" (LO <= HI), each in [-60, 60]; InputError naming the text otherwise.
EbrRange parse_ebr(const std::string& text);

// The built-in sources' names: white, room, motor.
const std::vector<std::string>& builtin_noise_names();

class BackgroundNoise {
 public:
  // Each entry a built-in name, a recording or a folder of them. InputError naming an entry that is
  // none of those, a folder without recordings, or a recording that does not decode.
  explicit BackgroundNoise(const std::vector<std::string>& sources);

  struct Mixed {
    audio::AudioClip clip;  // the recording with the noise added, clamped to [-1, 1]
    std::string source;     // the built-in name or the file the noise came from
    double ebr_db = 0.0;    // the ratio it was mixed at
  };
  // `recording` with noise at an EBR drawn from `ebr`. A silent recording gets no noise (its event
  // level is 0: no ratio can be kept).
  Mixed mix(const audio::AudioClip& recording, const EbrRange& ebr, Rng& rng) const;

  // The sources after folders are listed: built-in names and files, in order.
  const std::vector<std::string>& sources() const { return names_; }

 private:
  std::vector<std::string> names_;
  std::vector<audio::AudioClip> recordings_;  // [source]: mono; empty for a built-in
};

}  // namespace echoplan::sim
