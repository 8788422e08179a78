#include "sim/action_dynamics.h"

#include <algorithm>
#include <cmath>

#include "sim/action_script.h"
#include "sim/compliant_grasp.h"
#include "sim/contact_recorder.h"

namespace echoplan::sim {

namespace {

constexpr double kPreSettleTime = 0.04;  // s simulated before the action so the object rests
constexpr double kControlPeriod =
    0.01;  // s between IK solutions (100 Hz, as the arm's own controller)
constexpr double kTrackTolerance =
    0.01;  // m: the arm this far from a segment's end has not followed the path

// One physics step with the arm's servos at `targets`, gravity and Coriolis forces of the arm
// compensated as the real arm's controller does. `between` runs after mj_step1 (contacts found,
// forces not yet), `after` after mj_step2.
template <typename Between, typename After>
void physics_step(const mjModel* m, mjData* d, const double* targets, Between&& between,
                  After&& after) {
  mj_step1(m, d);
  between();
  for (int i = 0; i < kArmJoints; ++i) {
    d->ctrl[i] = targets[i];
    d->qfrc_applied[i] = d->qfrc_bias[i];
  }
  mj_step2(m, d);
  after();
}

// What running the script needs from one step to the next.
struct Run {
  const Scene& s;
  const mjModel* m;
  mjData* d;
  mjData* kin;
  ContactRecorder recorder;
  ArmSensorRecorder& sensors;
  CompliantGrasp grasp;
  const ContactTrace& trace;
  std::array<double, kArmJoints> q;
  double time = 0;
  bool grasp_closed = false;
};

// Runs segment `index` of `script`; returns false if the arm touched the table (run.q is then the
// servo targets where it stopped).
bool run_segment(Run& run, std::vector<Segment>& script, std::size_t index) {
  const mjModel* m = run.m;
  mjData* d = run.d;
  const Segment& seg = script[index];
  const double dt = m->opt.timestep;
  const int control_steps = std::max(1, static_cast<int>(std::lround(kControlPeriod / dt)));
  const int steps = std::max(1, static_cast<int>(std::lround(seg.duration_s / dt)));
  std::array<double, kArmJoints> q_previous = run.q, servo{};
  int tick_start = 0, tick_length = 1;
  for (int k = 1; k <= steps; ++k) {
    // Each control tick solves IK for the pose at the tick's end; joint targets ramp linearly to
    // it.
    if ((k - 1) % control_steps == 0) {
      q_previous = run.q;
      tick_start = k - 1;
      tick_length = std::min(control_steps, steps - tick_start);
      const double f = seg.progress(seg.duration_s * (tick_start + tick_length) / steps);
      dls_step(m, run.kin, run.s.end_effector_site, run.q.data(),
               seg.from + (seg.to - seg.from) * f, seg.turn_from.slerp(f, seg.turn_to));
    }
    const double ramp = static_cast<double>(k - tick_start) / tick_length;
    for (int i = 0; i < kArmJoints; ++i)
      servo[i] = q_previous[i] + ramp * (run.q[i] - q_previous[i]);
    const double strength =
        seg.grasp_from + (seg.grasp_to - seg.grasp_from) * static_cast<double>(k) / steps;
    physics_step(
        m, d, servo.data(),
        [&] {
          if (strength > 0 && !run.grasp_closed) {
            run.grasp.close(d);
            run.grasp_closed = true;
          }
          run.grasp.apply(m, d, strength);
          run.recorder.before_forces(m, d, run.time);
        },
        [&] {
          run.recorder.after_forces(m, d);
          run.sensors.after_step(m, d, run.time + dt);
        });
    run.time += dt;
    if (seg.stop_on_contact && !run.trace.impacts.empty()) {
      const double f = seg.progress(seg.duration_s * k / steps);
      const Eigen::Vector3d stop =
          seg.from + (seg.to - seg.from) * f - Eigen::Vector3d(0, 0, kPressDepth);
      for (std::size_t later = index + 1; later < script.size(); ++later)
        script[later].from = script[later].to = stop;
      run.q = servo;
      return true;
    }
    if (run.recorder.arm_on_table()) {
      run.q = servo;
      return false;
    }
  }
  return true;
}

}  // namespace

void settle_before_action(const mjModel* m, mjData* d, const double* targets) {
  for (int k = 0; k < static_cast<int>(kPreSettleTime / m->opt.timestep); ++k)
    physics_step(
        m, d, targets, [] {}, [] {});
}

ScriptRun run_script(const Scene& s, const mjModel* m, mjData* d, mjData* kin,
                     std::vector<Segment>& script, std::array<double, kArmJoints> q,
                     double object_radius, ContactTrace& trace, ArmSensorRecorder& sensors) {
  Run run{s,     m, d, kin, ContactRecorder(s, object_radius, trace), sensors, CompliantGrasp(s),
          trace, q};
  ScriptRun result;
  for (std::size_t index = 0; index < script.size(); ++index) {
    if (!run_segment(run, script, index)) {
      result.end = ScriptRun::End::arm_on_table;
      break;
    }
    // At the edge of its workspace the arm cannot follow the path (the IK falls behind its target).
    const Segment& seg = script[index];
    for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = run.q[i];
    mj_kinematics(m, kin);
    if (!seg.stop_on_contact &&
        (site_position(kin, s.end_effector_site) - seg.to).norm() > kTrackTolerance) {
      result.end = ScriptRun::End::lost_track;
      break;
    }
  }
  result.time_s = run.time;
  result.joints = run.q;
  return result;
}

}  // namespace echoplan::sim
