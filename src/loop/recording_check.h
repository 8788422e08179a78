// Whether a recording can be trusted as the sound of the action it was made around, checked before
// the observation service hears it (loop/step_fault.h says what the loop does with a fault).
//
// Always checked, whatever the recorder:
//   recording empty     no frames at all;
//   capture device lost the recorder reports its stream ended by itself
//   (CaptureReport::stream_error:
//                       a USB microphone unplugged mid-recording): what arrived is the start of the
//                       sound at best.
// Checked for a live microphone (RecordingChecks::live; the simulated and replayed recorders are
// exact and leave it off):
//   recording silent    no sample above one 16-bit step (1/32768): a muted or dead input;
//   recording clipped   more than 1% of the samples at full scale (|x| >= 0.999): the gain is too
//                       high and the classifier would hear distortion;
//   recording shorter than the action
//                       the clip is more than 50 ms shorter than the robot says the action took:
//                       the recording cannot hold all of its sound.
// Checked when set: another sample rate or channel count than the classifier was trained on.
// Samples lost on the way in (overflows, a full ring) mark the step's CaptureReport but are not a
// fault: the clip keeps the rest of the sound and is heard.
#pragma once

#include <optional>

#include "audio/clip.h"
#include "loop/step_fault.h"
#include "robot/recorder.h"
#include "robot/robot.h"

namespace echoplan::loop {

struct RecordingChecks {
  bool live = false;    // a live microphone: also silent, clipped and shorter than the action
  int sample_rate = 0;  // Hz every recording must have; 0: any
  int channels = 0;     // channels every recording must have; 0: any
};

// The first fault of `clip`, recorded around the action `report` describes, or none.
std::optional<StepFault> check_recording(const audio::AudioClip& clip,
                                         const robot::ActionReport& report,
                                         const robot::CaptureReport& capture,
                                         const RecordingChecks& checks);

}  // namespace echoplan::loop
