// A discrete POMDP copied once from a pomdp::TabularModel into flat arrays, for the offline solver.
//
// The offline solver touches the tables millions of times; virtual calls per entry would dominate,
// so the tables are copied once, checked, and stored densely (observations) or sparsely
// (transitions, which are mostly deterministic in object-identification problems).
//
// Terminal states are made exact here: a state the model calls terminal gets reward 0 for every
// action and loops to itself, whatever its rows say, so its value is exactly 0 in both bounds.
//
// Not an identification problem's tables (solvers/identification_tables.h): the point-based
// solver serves every discrete POMDP, including those whose hidden state moves (Tiger's doors
// reset it), so FlatPomdp keeps full transitions over all states. The exact solver, the sensing
// policy and the pair relaxation, which need the identification shape, share IdentificationTables.
#pragma once

#include <vector>

#include "pomdp/model.h"
#include "solvers/alpha_vector_set.h"  // BeliefVector

namespace echoplan::solvers::offline {

struct Successor {
  int state = 0;
  double probability = 0.0;  // > 0
};

struct FlatPomdp {
  int num_states = 0;
  int num_actions = 0;
  int num_observations = 0;
  double discount = 0.95;  // in (0, 1)
  // reward[s * num_actions + a]: expected immediate reward; 0 for terminal s.
  std::vector<double> reward;
  // terminal[s]: nonzero when s is absorbing with value 0.
  std::vector<char> terminal;
  // successors[s * num_actions + a]: the states s' with P(s' | s, a) > 0. Terminal s: {s, 1}.
  std::vector<std::vector<Successor>> successors;
  // observation[(a * num_states + s') * num_observations + o] = P(o | s', a).
  std::vector<double> observation;
  BeliefVector initial_belief;

  double reward_at(int s, int a) const { return reward[s * num_actions + a]; }
  const std::vector<Successor>& successors_of(int s, int a) const {
    return successors[s * num_actions + a];
  }
  const double* observation_row(int a, int s_next) const {
    return &observation[(static_cast<std::size_t>(a) * num_states + s_next) * num_observations];
  }
};

// Copies and checks `model`. Throws InputError (naming `source`, e.g. the problem file) when a
// probability row does not sum to 1 within 1e-6, a probability is negative, the discount is not in
// (0, 1), or the model has no states, actions or observations.
FlatPomdp make_flat_pomdp(const pomdp::TabularModel& model, const std::string& source = "");

}  // namespace echoplan::solvers::offline
