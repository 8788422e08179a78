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
// Babble: with `talkers` N > 1, a drawn recording is heard with N - 1 more segments of recordings
// drawn the same way, each at its own level, summed before the ratio is set: N people talking at
// once. One talker leaves gaps (a prompt's silences, the pauses between words) where the strike is
// heard clean and where a level measured from the clip sees no background (audio/levels.h);
// babble of many, as a canteen or an open office, fills them. A built-in source is one stream.
//
// Sources: recordings (files, or folders read recursively for .wav/.flac/.aiff files in name
// order), or built-in noise made at the clip's rate from the Rng: "white" (unit white noise),
// "room" (the simulator's room noise, flat below 500 Hz and falling 6 dB per octave above) and
// "motor" (the simulated arm's motor band, sim/sound_motor.h, running steadily) and "coloured"
// (noise of a colour drawn per recording: a low-pass corner and a band, to train on noise of any
// colour). The levels are audio/levels.h's.
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

// The built-in sources' names: white, room, motor, coloured.
const std::vector<std::string>& builtin_noise_names();

class BackgroundNoise {
 public:
  // Each entry a built-in name, a recording or a folder of them. InputError naming an entry that is
  // none of those, a folder without recordings, or a recording that does not decode.
  // InputError also for `talkers` outside [1, kMostTalkers].
  explicit BackgroundNoise(const std::vector<std::string>& sources, int talkers = 1);
  static constexpr int kMostTalkers = 64;

  struct Mixed {
    audio::AudioClip clip;  // the recording with the noise added, clamped to [-1, 1]
    std::string source;     // the built-in name or the file the noise came from (babble: the
                            // first talker's, "and N others")
    double ebr_db = 0.0;    // the ratio it was mixed at
  };
  // `recording` with noise at an EBR drawn from `ebr`. A silent recording gets no noise (its event
  // level is 0: no ratio can be kept).
  Mixed mix(const audio::AudioClip& recording, const EbrRange& ebr, Rng& rng) const;

  // The sources after folders are listed: built-in names and files, in order.
  const std::vector<std::string>& sources() const { return names_; }
  int talkers() const { return talkers_; }

 private:
  // The sum of talkers_ - 1 segments of recordings drawn from the recorded sources, added to
  // `noise`: the babble around the first talker.
  void add_other_talkers(std::vector<double>& noise, int rate, Rng& rng) const;

  std::vector<std::string> names_;
  std::vector<audio::AudioClip> recordings_;  // [source]: mono; empty for a built-in
  std::vector<std::size_t> recorded_;         // the indices of the recorded sources
  int talkers_ = 1;
};

}  // namespace echoplan::sim
