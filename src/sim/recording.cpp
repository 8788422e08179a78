#include "sim/recording.h"

namespace echoplan::sim {

Recording simulate_recording(SimulatedRobot& robot, const SoundRenderer& renderer,
                             SoundAction action, Rng& rng) {
  Recording r;
  robot.reset_trial(rng);
  r.outcome = robot.execute(action, rng);
  r.clip = renderer.render(r.outcome.trace, r.outcome.duration_s, rng);
  return r;
}

}  // namespace echoplan::sim
