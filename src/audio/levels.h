// A recording's levels as the field measures them for background noise (DCASE's office events; the
// knocks of issue 52): the event's level is the RMS of its loudest 50 ms, the background's the RMS
// of its quiet, and the event-to-background ratio (EBR) their ratio in dB. Channels are averaged.
//
// The background is measured from the recording itself, so a clip says how noisy it is without
// knowing what was added: the quiet around the contact (before the slide starts, after the strike
// has rung out) is the room. Its level is the 10th percentile of the RMS of the clip's 50 ms
// windows (hop 25 ms): the quietest tenth of the clip, robust to a single silent window (a gap, a
// fade).
#pragma once

#include "audio/clip.h"

namespace echoplan::audio {

// The RMS of the loudest 50 ms window (hop 5 ms; the whole clip when shorter); 0 for a silent or
// empty clip.
double event_level(const AudioClip& clip);

// The 10th percentile of the 50 ms windows' RMS (hop 25 ms; the whole clip when shorter); 0 for an
// empty clip.
double background_level(const AudioClip& clip);

// 20 log10(event_level / background_level), clamped to [-60, 120] dB (a clip of digital silence
// outside its event has no finite ratio); 0 for an empty or silent clip.
double measured_ebr_db(const AudioClip& clip);

}  // namespace echoplan::audio
