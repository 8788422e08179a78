// The dynamics of an action: stepping MuJoCo while the arm's joint servos follow an action script
// (IK at the arm controller's 100 Hz, joint targets ramped in between, gravity and Coriolis forces
// compensated as the real arm's controller does), the compliant grasp applied, and the
// object-table contacts collected into the action's contact trace.
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <vector>

#include "sim/arm_sensors.h"
#include "sim/cartesian_motion.h"
#include "sim/contact_trace.h"
#include "sim/scene.h"

namespace echoplan::sim {

// Simulates the object settling into its resting contact with the arm held at `targets`
// (unrecorded), so an action's first "impact" is not the object dropping through the contact
// margin.
void settle_before_action(const mjModel* m, mjData* d, const double* targets);

struct ScriptRun {
  enum class End {
    completed,     // every segment ran
    arm_on_table,  // the arm touched the table: stopped there
    lost_track,    // the arm could not follow a segment (the edge of its workspace): stopped there
  };
  End end = End::completed;
  double time_s = 0;                        // simulated from the start of the script to its end
  std::array<double, kArmJoints> joints{};  // rad, the servo targets where the arm was left
};

// Runs `script` from joint targets `q` in `d` (the model `m` of scene `s`), IK solved in `kin`,
// recording object-table contacts of an object of `object_radius` into `trace` and the arm's
// sensors into `sensors`. A segment that stops on contact moves the rest of the script to where it
// stopped (hence `script` is changed).
ScriptRun run_script(const Scene& s, const mjModel* m, mjData* d, mjData* kin,
                     std::vector<Segment>& script, std::array<double, kArmJoints> q,
                     double object_radius, ContactTrace& trace, ArmSensorRecorder& sensors);

}  // namespace echoplan::sim
