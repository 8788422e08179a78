// The loop tests' small world: the mug or the cup, a classifier trained on a few simulated
// recordings of each, and the simulator that holds them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "../robot/small_training_set.h"
#include "loop/calibrated_problem.h"
#include "loop/world_spec.h"
#include "pomdp/problem.h"

namespace echoplan::loop::test {

inline const std::vector<std::string> kObjects{"coffee_mug", "plastic_cup"};

inline std::shared_ptr<const perception::ObservationModel> model() {
  static const auto m = testing::train_small_model(kObjects, {"slide", "strike"}, 3);
  return m;
}

// Mug or cup, sorted to A (mug) or B (cup); the report's rewards. Observation symbols and
// table: `symbols` with a uniform table (calibrated_problem replaces both).
inline pomdp::ObjectProblemData mug_or_cup(std::vector<std::string> objects = kObjects) {
  pomdp::ObjectProblemData d;
  d.name = "mug_or_cup";
  d.discount = 0.99;
  d.objects = objects;
  d.prior.assign(objects.size(), 1.0 / static_cast<double>(objects.size()));
  d.initial_joints = {-2.89527, 1.45058, -0.18396, 2.07696, -0.310356, 0.630897, -1.54233};
  d.initial_offset = {0.1, 0, 0};
  d.sensing = {{"slide", -1.0, {0.05, 0, 0}, 0.0}, {"strike", -1.0, {0, 0, 0}, 0.0}};
  d.sorting = {"move_to_A", "move_to_B"};
  d.observation_symbols = objects;
  const std::vector<double> uniform(objects.size(), 1.0 / static_cast<double>(objects.size()));
  d.observation_table.assign(2, std::vector<std::vector<double>>(objects.size(), uniform));
  d.sorting_reward = {std::vector<double>(objects.size(), -100.0),
                      std::vector<double>(objects.size(), -100.0)};
  d.sorting_reward[0][0] = 10;
  for (std::size_t k = 1; k < objects.size(); ++k) d.sorting_reward[1][k] = 10;
  return d;
}

inline std::shared_ptr<const pomdp::Problem> calibrated(const pomdp::ObjectProblemData& base) {
  auto p = std::make_shared<pomdp::Problem>();
  p->model = std::make_shared<pomdp::ObjectIdentificationModel>(calibrated_problem(base, *model()));
  p->belief.particles = 300;
  p->planner.exploration = 110;
  return p;
}

inline SimulatedWorldSpec simulator() {
  return {std::make_shared<const sim::Catalogue>(testing::shipped_catalogue()),
          std::make_shared<const sim::SimConfig>()};
}

}  // namespace echoplan::loop::test
