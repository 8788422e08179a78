#include "sim/action_script.h"

#include <cmath>

#include "sim/arm_kinematics.h"
#include "sim/scene.h"

namespace echoplan::sim {

namespace {

constexpr double kActionDistance =
    0.05;  // m: the slide's push and the strike's lift (the report's section 3.2.1)
constexpr double kLiftSpeed = 0.10;  // m/s, the report's 10 cm/s (the report's section 3.2.1)
// m between pad and object before the push: the pad starts just clear of the object. Geometry of
// this simulator's start pose, not tuned to the lab's recordings (the push then covers 5.1 cm).
constexpr double kPadGap = 0.001;
// s simulated after the strike so the object comes to rest: the object is already held still, and
// the clip's length does not depend on it (docs/simulator.md, "The push: speed and profile").
constexpr double kSettleTime = 0.2;
// s simulated after the push. The pad slows to rest gently (ArmConfig: over the push's last fifth,
// a few tenths of a m/s^2), and friction (mu g: metres per s^2) would stop an object sliding at a
// few cm/s within 20 ms anyway, so only the contacts settle. (Less physics than the strike's 0.2 s
// pays for the lab's longer push: git history.)
constexpr double kSlideSettleTime = 0.05;

// The strike: grasp, lift (tilting), pause, descend until contact, level, hold, release, settle.
std::vector<Segment> strike_script(const ActionVariation& p, const Eigen::Vector3d& at_object,
                                   const Eigen::Quaterniond& upright, const ArmConfig& arm) {
  const double ease = arm.strike_ease_s;
  std::vector<Segment> plan;
  const Eigen::Vector3d up(0, 0, kActionDistance);
  // The tilt turns the object about a horizontal axis through the grasp point while lifting, so
  // it meets the table rim first; on the table the hand turns it upright again before opening.
  const double azimuth = p.tilt_azimuth_deg * kPi / 180.0;
  const Eigen::Quaterniond tilted =
      Eigen::Quaterniond(
          Eigen::AngleAxisd(p.impact_tilt_deg * kPi / 180.0,
                            Eigen::Vector3d(std::cos(azimuth), std::sin(azimuth), 0.0))) *
      upright;
  const Eigen::Vector3d bottom = at_object - Eigen::Vector3d(0, 0, kPressDepth);
  plan.push_back({arm.grasp_time_s, at_object, at_object, upright, upright, 0, 1});
  Segment lift{
      kActionDistance / kLiftSpeed + ease, at_object, at_object + up, upright, tilted, 1, 1};
  lift.ease_in_s = lift.ease_out_s = ease;
  plan.push_back(lift);
  plan.push_back({arm.lift_pause_s, at_object + up, at_object + up, tilted, tilted, 1, 1});
  Segment descent{(kActionDistance + kPressDepth) / p.impact_speed + ease / 2,
                  at_object + up,
                  bottom,
                  tilted,
                  tilted,
                  1,
                  1,
                  true};
  descent.ease_in_s = ease;
  plan.push_back(descent);
  plan.push_back({arm.level_time_s, bottom, bottom, tilted, upright, 1, 1});
  plan.push_back({arm.hold_time_s, bottom, bottom, upright, upright, 1, 1});
  plan.push_back({arm.release_time_s, bottom, bottom, upright, upright, 1, 0});
  plan.push_back({kSettleTime, bottom, bottom, upright, upright, 0, 0});
  return plan;
}

// The slide: one push along +x, then the contacts settle.
std::vector<Segment> slide_script(const ActionVariation& p, const Eigen::Vector3d& at_object,
                                  const Eigen::Quaterniond& upright, const ArmConfig& arm) {
  std::vector<Segment> plan;
  const double push_distance = kActionDistance + kPadGap;  // the pad first closes its gap
  const Eigen::Vector3d end = at_object + Eigen::Vector3d(push_distance, 0, 0);
  // The push's duration is its distance at the drawn mean speed; the arm's profile is scaled to
  // it, so a slower push also builds up more slowly (ArmConfig).
  const double push_time = push_distance / p.push_speed;
  Segment push{push_time, at_object, end, upright, upright};
  push.ease_in_s = arm.push_accelerate_share * push_time;
  push.ease_out_s = arm.push_decelerate_share * push_time;
  plan.push_back(push);
  plan.push_back({kSlideSettleTime, end, end, upright, upright});
  return plan;
}

}  // namespace

Eigen::Vector3d action_start(SoundAction action, const ActionVariation& p,
                             const Eigen::Vector3d& object_base, double object_radius,
                             double table_top_z) {
  const double ee_z = table_top_z + p.grasp_height;
  return action == SoundAction::strike
             ? Eigen::Vector3d(object_base.x() + p.grasp_offset_x,
                               object_base.y() + p.grasp_offset_y, ee_z)
             : Eigen::Vector3d(object_base.x() - object_radius - kPadRadius - kPadGap,
                               object_base.y() + p.push_offset, ee_z);
}

std::vector<Segment> action_script(SoundAction action, const ActionVariation& variation,
                                   const Eigen::Vector3d& at_object,
                                   const Eigen::Quaterniond& upright, const ArmConfig& arm) {
  return action == SoundAction::strike ? strike_script(variation, at_object, upright, arm)
                                       : slide_script(variation, at_object, upright, arm);
}

}  // namespace echoplan::sim
