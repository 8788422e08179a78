// An identification problem's tables, read once from the model and shared (const) by everything
// that works on one: the exact solver (identification_solver.h), the default sensing policy of
// ABT's leaves (sensing_policy.h) and the pair relaxation bound (pair_relaxation_bound.h).
//
// An identification problem: the hidden state stays fixed until an action ends the episode
// (identification_shape_problem() says why a model is not one). The tables are indexed by *live*
// state l (the model's non-absorbing states, in increasing order; model_state[l] is the model's
// index), since absorbing states never hold belief mass: every belief the users keep over the
// model's states has 0 there.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pomdp/model.h"
#include "solvers/use_limits.h"

namespace echoplan::solvers {

// Why `model` is not an identification problem, or nothing when it is one.
std::optional<std::string> identification_shape_problem(const pomdp::TabularModel& model);

struct IdentificationTables {
  int states = 0;  // the model's states, absorbing ones included
  int live_states = 0, actions = 0, observations = 0;  // L, A, O
  double discount = 0.0;
  std::vector<int> model_state;        // [l]: the model's index of live state l
  std::vector<bool> terminal;          // [a]: the action ends the episode from every live state
  std::vector<double> reward;          // [a * L + l] = R(l, a)
  std::vector<double> stay;            // [a * L + l] = P(state kept | l, a)
  std::vector<double> emission;        // [(a * O + o) * L + l] = stay(l, a) · O(a, l, o)
  std::vector<double> known_value;     // [l] = V*(state l known)
  std::vector<double> initial_belief;  // [s] over the model's states: the problem's b0
  // Per-action use limits in one episode (pomdp::Model::max_uses; empty: none). They are not in a
  // TabularModel's tables, so they come from the Model that owns them.
  UseLimits limits;
};

// Reads `model`'s tables, with the use `limits` of the Model they belong to (UseLimits(model);
// none by default). The caller checks identification_shape_problem() first (each says in its own
// words why it needs an identification problem); on another model the tables are meaningless.
std::shared_ptr<const IdentificationTables> read_identification_tables(
    const pomdp::TabularModel& model, const UseLimits& limits = {});

}  // namespace echoplan::solvers
