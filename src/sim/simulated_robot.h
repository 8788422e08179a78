// The simulated robot: executes the two sound-making actions on one object in the MuJoCo scene and
// reports what happened, including the object-table contacts the sound synthesis needs.
//
// Actions (the names used across echoplan):
//   "slide"  - the fingertip pad pushes the object 5 cm along +x at the trial's push speed;
//   "strike" - grasp (weld on), lift 5 cm, bring it down at the trial's impact speed onto the table,
//              release (weld off).
// Each execute() starts from the original system's initial configuration with the object at its
// nominal place plus the trial's placement offset (a lab reset between actions). The move from the
// initial configuration to the object is silent and done kinematically (checked for arm-table
// contact at waypoints); the action proper is simulated dynamically and its time starts at 0.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "common/rng.h"
#include "sim/catalogue.h"
#include "sim/contact_trace.h"
#include "sim/sim_config.h"

namespace echoplan::sim {

class Scene;

// The action names the simulator knows.
inline constexpr const char* kSlide = "slide";
inline constexpr const char* kStrike = "strike";

struct ActionOutcome {
  std::string action;
  bool collision = false;      // the arm touched the table; the action stopped there
  double collision_time_s = 0; // s from the start of the action (negative: during the approach)
  double duration_s = 0;       // s simulated, from the start of the action to its end (or the collision)
  TrialParameters parameters;  // what was drawn for this trial
  std::array<double, 3> object_displacement{};  // m, world frame: where the object ended minus where it began
  ContactTrace trace;          // object-table contacts
};

class SimulatedRobot {
 public:
  // Builds the scene for `object` (compiling the MuJoCo model once). The catalogue and config are
  // copied.
  SimulatedRobot(const Catalogue& catalogue, const std::string& object, const SimConfig& config);
  ~SimulatedRobot();
  SimulatedRobot(const SimulatedRobot&) = delete;
  SimulatedRobot& operator=(const SimulatedRobot&) = delete;

  // Runs `action` ("slide" or "strike") once, drawing the trial's variability from `rng`.
  // Throws InputError for an unknown action name.
  ActionOutcome execute(const std::string& action, Rng& rng);

  // As execute(), with the trial's parameters given instead of drawn.
  ActionOutcome execute(const std::string& action, const TrialParameters& parameters);

  const ObjectSpec& object() const { return object_; }
  const TableSpec& table() const { return table_; }
  const SimConfig& config() const { return config_; }

 private:
  ObjectSpec object_;
  TableSpec table_;
  SimConfig config_;
  std::unique_ptr<Scene> scene_;
};

}  // namespace echoplan::sim
