// A training set collected on a robot: for every object and session, a trial in which the robot
// performs each behaviour in turn (the same Robot::execute the planner uses) while the recorder
// listens, written as a recordings tree DIR/<object>/<action>/s<session>.wav with its manifest
// (docs/feature-sets.md), plus any other signal the robot's side measured during the performance
// (DIR/<object>/<action>/s<session>.<modality>.csv).
//
// Resumable: each performance's files appear atomically, then its manifest row; run again on the
// same folder, the collection skips every performance the manifest lists and goes on with the rest
// (a session cut short resumes in a fresh trial for the behaviours it had left).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "robot/recorder.h"
#include "robot/robot.h"
#include "signal/series.h"

namespace echoplan::loop {

struct CollectionPlan {
  std::vector<std::string> objects;     // at least one, each once
  std::vector<std::string> behaviours;  // the sensing actions, in the order each session runs them
  int sessions = 10;                    // per object, >= 1; numbered from 1
  std::uint64_t seed = 0;               // the trials' seeds (a simulated world's variability)
  std::string output_dir;
};

struct CollectionSummary {
  int performed = 0;  // performances recorded by this run
  int kept = 0;       // already in the manifest, skipped
  int failed = 0;  // of those performed, not `done` (written all the same, status in the manifest)
  bool interrupted = false;
};

// The signals besides audio that the robot's side measured during the performance just executed
// (object, session, behaviour), by modality (a simulated arm's joint torques and wrist force);
// none for a robot with a microphone alone.
using PerformanceSignals = std::function<std::vector<std::pair<std::string, signal::Series>>(
    const std::string&, int, const std::string&)>;

// (object, session, behaviour, performances done, total)
using CollectionProgress =
    std::function<void(const std::string&, int, const std::string&, int, int)>;

// Runs the collection. Throws InputError before anything is performed for an empty or repeated
// object or behaviour, sessions < 1, or a manifest in DIR that is not this collection's (other
// columns, a row that does not read); stops between performances when `stop` becomes true.
CollectionSummary collect(robot::Robot& robot, robot::Recorder& recorder,
                          const CollectionPlan& plan, const PerformanceSignals& signals,
                          const CollectionProgress& progress, const std::atomic<bool>& stop);

}  // namespace echoplan::loop
