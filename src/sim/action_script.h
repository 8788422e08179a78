// The action script: which straight-line motions of the end effector each sound-making action is,
// and where it begins relative to the object. Pure geometry and timing; no physics.
//
// The distances and times are the report's (section 3.2.1: a 5 cm push, a 5 cm lift) or chosen so
// the motion is gentle where the lab's arm was (no second hit while levelling, the hand closed
// before it lifts); docs/simulator.md, "Tuned constants", lists them.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "sim/cartesian_motion.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"
#include "sim/sound_action.h"

namespace echoplan::sim {

// m the strike's target lies below the resting height, so the hand presses the object onto the
// table (and where a descent stopped on contact, the rest of the script is moved to).
inline constexpr double kPressDepth = 0.001;

// Where the action begins (the end effector, m, world): for a strike the hand around the object's
// axis (off by the grasp offset) at grasp height, for a slide the pad just behind the object.
Eigen::Vector3d action_start(SoundAction action, const ActionVariation& variation,
                             const Eigen::Vector3d& object_base, double object_radius,
                             double table_top_z);

// The action's segments from `at_object` (action_start), the hand kept `upright` except for the
// strike's drawn tilt. The strike's descent stops on contact (Segment::stop_on_contact).
std::vector<Segment> action_script(SoundAction action, const ActionVariation& variation,
                                   const Eigen::Vector3d& at_object,
                                   const Eigen::Quaterniond& upright, const ArmConfig& arm);

}  // namespace echoplan::sim
