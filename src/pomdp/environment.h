// The execution side: where actions really happen and observations really come from.
//
// The planner plans on a Model; the world is an Environment. For planner studies the environment is
// the model itself (ModelEnvironment); later the simulated robot with synthesized sound and a
// trained classifier, or a real robot, implement the same interface.
#pragma once

#include <optional>
#include <string>

#include "common/rng.h"
#include "pomdp/model.h"

namespace echoplan::pomdp {

struct Outcome {
  Observation observation;
  double reward = 0.0;
  bool terminal = false;
  bool collision = false;
  // The observation service's calibrated probability of the heard class, for worlds that classify a
  // recording; absent when the observation is drawn from a table.
  std::optional<double> heard_probability;
  // The event-to-background ratio measured from that recording (audio/levels.h), in dB: how noisy
  // what was heard was. Absent without a recording.
  std::optional<double> heard_ebr_db;
};

class Environment {
 public:
  virtual ~Environment() = default;
  // Starts a new episode. `true_state` is the hidden truth for this episode (e.g. drawn by the
  // trial runner so it can be logged); environments that cannot be told the truth (a real robot)
  // may ignore it.
  virtual void reset(const State& true_state, Rng& rng) = 0;
  // Executes `action` and reports what happened.
  virtual Outcome execute(int action, Rng& rng) = 0;
  // The hidden state as far as the environment knows it (for logs); may be unknown for a real
  // robot.
  virtual const State& true_state() const = 0;
};

}  // namespace echoplan::pomdp
