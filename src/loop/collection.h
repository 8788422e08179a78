// A training set collected on a robot: for every object and session, a trial in which the robot
// performs each behaviour in turn (the same Robot::execute the planner uses) while the recorder
// listens, written as a recordings tree DIR/<object>/<action>/s<session>.wav with its manifest
// (docs/feature-sets.md), plus any other signal the robot's side measured during the performance
// (DIR/<object>/<action>/s<session>.<modality>.csv). A robot without a microphone has no recorder:
// its performances are their signals alone (the manifest names the first one's file).
//
// Resumable: each performance's files appear atomically, then its manifest row; run again on the
// same folder, the collection skips every performance the manifest lists and goes on with the rest
// (a session cut short resumes in a fresh trial for the behaviours it had left). A performance
// whose recording or signals failed in a way the next one may not (robot::TransientError: a device
// gone, a sensor stream that stopped) is not written: the run says why and goes on, and running it
// again performs that one anew.
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
  int lost = 0;    // performed but not recorded (a TransientError): not written, left for a rerun
  bool interrupted = false;
};

// The signals besides audio that the robot's side measured during the performance just executed
// (object, session, behaviour), by modality (a simulated arm's joint torques and wrist force);
// none for a robot with a microphone alone.
using PerformanceSignals = std::function<std::vector<std::pair<std::string, signal::Series>>(
    const std::string&, int, const std::string&)>;

// One performance finished: written, or lost (`lost` says why).
struct CollectionStep {
  std::string object;
  int session = 0;
  std::string behaviour;
  int done = 0;  // performances in the manifest now (kept and written)
  int total = 0;
  std::string lost;  // why it was not recorded; empty when it was written
};
using CollectionProgress = std::function<void(const CollectionStep&)>;

// Runs the collection. `recorder` may be null (no microphone): then every performance must have
// signals. Throws InputError before anything is performed for an empty or repeated object or
// behaviour, sessions < 1, or a manifest in DIR that is not this collection's (other columns, a
// row that does not read), and when a performance without a recorder brought no signal; stops
// between performances when `stop` becomes true.
CollectionSummary collect(robot::Robot& robot, robot::Recorder* recorder,
                          const CollectionPlan& plan, const PerformanceSignals& signals,
                          const CollectionProgress& progress, const std::atomic<bool>& stop);

}  // namespace echoplan::loop
