// One simulated recording: a trial begun on the simulated robot, one action, and the sound the
// renderer makes of its contact trace, all drawn from one Rng (so one seed gives one file).
#pragma once

#include "audio/clip.h"
#include "common/rng.h"
#include "sim/simulated_robot.h"
#include "sim/sound_action.h"
#include "sim/sound_renderer.h"

namespace echoplan::sim {

struct Recording {
  ActionOutcome outcome;
  audio::AudioClip clip;
};

// Begins a trial on `robot`, runs `action` as its first action and renders it: the placement, the
// outcome and its clip, all from `rng`.
Recording simulate_recording(SimulatedRobot& robot, const SoundRenderer& renderer,
                             SoundAction action, Rng& rng);

}  // namespace echoplan::sim
