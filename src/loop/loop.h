// The closed loop, assembled once: what `echoplan run`, `echoplan trials`, the ROS planner node and
// a campaign's workers all call.
//
//   LoopSettings settings;  // the problem, the world, the observation model, the planner
//   auto spec = std::make_shared<const LoopSpec>(std::move(settings));  // checked: InputError now
//   Loop loop(spec);        // a world and a planner of its own (one per thread)
//   std::optional<Trial> trial = loop.run({.index = 0, .object = 2, .seed = 7}, print_step);
//
// Each returned step carries everything it produced: the decision, the belief before and after,
// what the planner was told and, in a world with a robot, the robot's report, the clip and what
// the service heard (loop/trial_runner.h).
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "loop/planner.h"
#include "loop/trial_runner.h"
#include "loop/world_spec.h"
#include "perception/observation_model.h"
#include "pomdp/problem.h"
#include "solvers/planner_overrides.h"

namespace echoplan::loop {

struct LoopSettings {
  std::shared_ptr<const pomdp::Problem> problem;  // what the planner plans on
  // What scores the world (rewards, observation symbols, the table world's table); null: `problem`.
  // A campaign's calibrated arm plans on its own table in the world problem's world.
  std::shared_ptr<const pomdp::Problem> world_problem;
  WorldSpec world = TableWorldSpec{};
  std::shared_ptr<const perception::ObservationModel>
      observation_model;  // simulator and replay worlds
  // The world's object when a problem object is the truth (e.g. coffee_mug -> coffee_mug_weighted).
  std::map<std::string, std::string> world_objects;
  // Background noise the simulator's or replay's recordings are heard with; none: as recorded.
  std::optional<robot::WorldNoise> noise;
  solvers::PlannerOverrides planner;  // the solver and budget; empty fields: the problem file's
  int max_steps = 100;                // a trial stops after this many steps; >= 1
};

// Checked settings, immutable and safe to share between threads.
class LoopSpec {
 public:
  // Throws InputError naming what does not fit: a missing problem, a planner the solver rejects,
  // max_steps < 1, the planning and world problems disagreeing on objects, actions or
  // observations, a world that does not fit (make_world_factory).
  explicit LoopSpec(LoopSettings settings);

  const LoopSettings& settings() const { return settings_; }
  const pomdp::Problem& problem() const { return *settings_.problem; }
  const pomdp::Problem& world_problem() const { return *settings_.world_problem; }
  const WorldFactory& world_factory() const { return world_factory_; }

 private:
  LoopSettings settings_;
  WorldFactory world_factory_;
};

// Which trial to run.
struct TrialRequest {
  int index = 0;    // the trial's number: its random streams come from (seed, index)
  int object = -1;  // the true object (index into the problem's objects); -1: drawn
  std::uint64_t seed = 1;
};

// A world and a planner of one's own, built from a shared spec.
class Loop {
 public:
  explicit Loop(std::shared_ptr<const LoopSpec> spec);

  // Runs one trial; `on_step` sees each step as it happens. Returns nothing when `stop` was set
  // before the trial ended (a cut-short trial is dropped whole).
  std::optional<Trial> run(const TrialRequest& request, const StepFn& on_step = {},
                           const std::atomic<bool>* stop = nullptr);

  const LoopSpec& spec() const { return *spec_; }
  const Planner& planner() const { return planner_; }

 private:
  std::shared_ptr<const LoopSpec> spec_;
  Planner planner_;
  std::unique_ptr<World> world_;
};

// The planner reads the world's symbols by the world problem's indices, so the two must share
// objects, actions and observations; InputError naming `plan`'s file when they do not.
void check_same_names(const pomdp::Problem& plan, const pomdp::Problem& world);

// The index of `object` among the problem's objects; InputError naming the problem's objects when
// it is not one.
int object_index(const pomdp::Problem& problem, const std::string& object);

}  // namespace echoplan::loop
