// What the physics hands to the sound synthesis: the object-table contacts of one action, at
// physics rate.
//
// Impacts are too short for the physics step (a Hertz contact lasts ~0.1 ms, the step is 1-2 ms),
// so an impact is recorded as an event with the quantities that set its pulse (normal speed,
// effective mass, where on the rim it landed); sliding is recorded step by step.
#pragma once

#include <array>
#include <vector>

namespace echoplan::sim {

// A point of an object-table contact: where around the object's axis it lies and how hard it
// pushes.
struct RimContact {
  double azimuth_rad = 0;   // angle around the object's axis, in the object's frame
  double normal_force = 0;  // N, >= 0, in the step the contact was detected
};

// One impact of the object on the table.
struct Impact {
  double time_s = 0;        // from the start of the action
  double normal_speed = 0;  // m/s, approach speed along the contact normal just before contact, > 0
  double effective_mass = 0;  // kg, 1 / (n^T J M^-1 J^T n) over the object's own degrees of freedom
  std::vector<RimContact> contacts;  // the contact points of that step (at least one)
};

// The object-table contacts of one action. The per-step vectors all have `steps` entries.
struct ContactTrace {
  double timestep_s = 0.002;    // physics step (s)
  int steps = 0;                // number of physics steps simulated
  std::vector<Impact> impacts;  // in time order
  std::vector<double>
      sliding_speed;  // m/s, tangential speed of the object over the table (0 off the table)
  std::vector<double> normal_force;         // N, total object-table normal force
  std::array<double, 3> object_position{};  // m, world position of the object's base at the start

  double duration_s() const { return steps * timestep_s; }
};

}  // namespace echoplan::sim
