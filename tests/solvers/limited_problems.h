// Small identification problems with use limits and prerequisites, and V* on them by brute force:
// the references of the tests of use limits (use_limits_test.cpp) and of the bounds that read
// them (readings_left_bound_test.cpp).
#pragma once

#include <algorithm>
#include <limits>
#include <memory>
#include <vector>

#include "../common/source_dir.h"
#include "pomdp/object_identification_model.h"
#include "pomdp/problem.h"

namespace echoplan::solvers::testing {

// Two objects, one noisy sensor heard right 80% of the time, sort right +10 / wrong -100, sensing
// -1, γ = 0.9. With `uses` listens allowed (0: no limit).
inline pomdp::ModelPtr one_noisy_sensor(int uses) {
  pomdp::ObjectProblemData d;
  d.name = "one_noisy_sensor";
  d.discount = 0.9;
  d.objects = {"a", "b"};
  d.prior = {0.5, 0.5};
  d.sensing = {pomdp::SensingAction{"listen"}};
  d.sensing[0].uses = uses;
  d.sorting = {"to_a", "to_b"};
  d.observation_symbols = {"a", "b"};
  d.observation_table = {{{0.8, 0.2}, {0.2, 0.8}}};
  d.sorting_reward = {{10.0, -100.0}, {-100.0, 10.0}};
  return std::make_shared<const pomdp::ObjectIdentificationModel>(std::move(d));
}

// The same two objects and sensor, which now hears only what the robot holds: "listen" requires
// "grasp", which tells nothing (its rows uniform). Each once (`uses`), so that the brute force
// ends.
inline pomdp::ModelPtr grasp_then_listen() {
  pomdp::ObjectProblemData d;
  d.name = "grasp_then_listen";
  d.discount = 0.9;
  d.objects = {"a", "b"};
  d.prior = {0.5, 0.5};
  d.sensing = {pomdp::SensingAction{"grasp"}, pomdp::SensingAction{"listen"}};
  d.sensing[0].uses = d.sensing[1].uses = 1;
  d.sensing[1].prerequisites = {0};
  d.sorting = {"to_a", "to_b"};
  d.observation_symbols = {"a", "b"};
  d.observation_table = {{{0.5, 0.5}, {0.5, 0.5}}, {{0.8, 0.2}, {0.2, 0.8}}};
  d.sorting_reward = {{10.0, -100.0}, {-100.0, 10.0}};
  return std::make_shared<const pomdp::ObjectIdentificationModel>(std::move(d));
}

// The report's problem with `slide` and `strike` uses; with `waiting` (0 slide, 1 strike) that
// action also waits for the other one (a prerequisite).
inline pomdp::ModelPtr report_with_limits(int slide, int strike, int waiting = -1) {
  const pomdp::Problem p =
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
  pomdp::ObjectProblemData d = p.model->object_identification()->data();
  d.sensing[0].uses = slide;
  d.sensing[1].uses = strike;
  if (waiting >= 0) d.sensing[waiting].prerequisites = {1 - waiting};
  return std::make_shared<const pomdp::ObjectIdentificationModel>(std::move(d));
}

// V* by recursion over every history, on the raw tables: commit now (best terminal action) or any
// sensing action still allowed (its limit not spent, its prerequisites taken), then each
// observation. Exact, since limits on every sensing action bound the depth. `uses` counts per
// action.
inline double brute_force_value(const pomdp::Model& model, const std::vector<double>& b,
                                std::vector<int>& uses) {
  const pomdp::TabularModel& m = *model.tabular();
  const int S = m.num_states();
  auto expected = [&](int a) {
    double r = 0.0;
    for (int s = 0; s < S; ++s) r += b[s] * m.reward(s, a);
    return r;
  };
  double best = -std::numeric_limits<double>::infinity();
  for (int a = 0; a < m.num_actions(); ++a) {
    const bool sensing = model.max_uses(a) > 0;  // here: exactly the sensing actions
    if (!sensing) {
      best = std::max(best, expected(a));
      continue;
    }
    if (uses[a] >= model.max_uses(a)) continue;
    const std::vector<int> required = model.prerequisites(a);
    if (std::any_of(required.begin(), required.end(), [&](int r) { return uses[r] == 0; }))
      continue;
    double q = expected(a);
    ++uses[a];
    for (int o = 0; o < m.num_observations(); ++o) {
      std::vector<double> next(S, 0.0);
      double p = 0.0;
      for (int s = 0; s < S; ++s) p += next[s] = b[s] * m.observation(a, s, o);
      if (p <= 0.0) continue;
      for (double& x : next) x /= p;
      q += m.discount() * p * brute_force_value(model, next, uses);
    }
    --uses[a];
    best = std::max(best, q);
  }
  return best;
}

}  // namespace echoplan::solvers::testing
