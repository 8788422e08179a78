// What the sound synthesis needs from the physics: the object-table contacts of an action, turned
// into a ContactTrace step by step (impacts with their speed and effective mass, the normal force,
// the sliding speed, the arm's joint speed), and whether the arm has touched the table.
#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <vector>

#include "sim/contact_trace.h"

namespace echoplan::sim {

class Scene;

// Effective mass of the object at a contact along `normal`: 1 / (j M^-1 j^T) with j the normal row
// of the contact point's Jacobian over the object's own six degrees of freedom. The grasp is
// compliant on the ~0.1 ms scale of an impact, so the arm does not take part.
double effective_mass(const mjModel* m, const mjData* d, const Scene& s, const mjtNum point[3],
                      const Eigen::Vector3d& normal);

// Whether any arm geom touches the table among the contacts in `d` (after collision detection).
bool arm_touches_table(const mjData* d, const Scene& s);

// Collects the ContactTrace during the dynamic part of an action.
class ContactRecorder {
 public:
  ContactRecorder(const Scene& scene, double object_radius, ContactTrace& trace)
      : s_(scene), object_radius_(object_radius), trace_(trace) {}

  // After mj_step1: contacts and pre-impulse velocities of this step; detects an impact.
  void before_forces(const mjModel* m, mjData* d, double time);
  // After mj_step2: contact forces of this step, and the object's sliding speed.
  void after_forces(const mjModel* m, mjData* d);

  bool arm_on_table() const { return arm_on_table_; }

 private:
  const Scene& s_;
  double object_radius_;
  ContactTrace& trace_;
  bool clear_of_table_ = false;
  std::vector<int> object_contacts_;
  bool arm_on_table_ = false;
  bool pending_impact_ = false;
  double best_speed_ = 0;
  int best_contact_ = -1;
  Eigen::Vector3d best_normal_ = Eigen::Vector3d::UnitZ();
  double last_impact_ = -1.0;
};

}  // namespace echoplan::sim
