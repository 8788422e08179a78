// The online solver interface: plan from a belief, act, hear, keep planning from what was learned.
//
// A solver owns a search tree rooted at the agent's current belief. The execution loop calls
//   reset(belief)            once per episode, to root a fresh tree at the initial belief;
//   improve(budget)          to grow the tree (a wall-time or an episode budget);
//   best_action()            to read the decision;
//   update(a, o, belief)     after executing a and hearing o: the child for (a, o) becomes the
//   root, the
//                            rest of the tree is freed, and the root is topped up from the real
//                            belief when it holds too few particles.
// Every random choice comes from the Rng passed in, so an episode budget replays exactly.
#pragma once

#include <cstdint>
#include <vector>

#include "common/rng.h"
#include "pomdp/belief.h"
#include "pomdp/model.h"

namespace echoplan::solvers {

// How much search one improve() call may do. Episode budgets make results reproducible bit for bit;
// wall-time budgets are what a robot has.
struct Budget {
  enum class Kind { episodes, milliseconds };
  Kind kind = Kind::episodes;
  std::int64_t amount = 1000;  // episodes, or milliseconds of wall time; > 0

  static Budget episodes(std::int64_t n) { return {Kind::episodes, n}; }
  static Budget milliseconds(std::int64_t ms) { return {Kind::milliseconds, ms}; }
};

// What the tree looks like now (for logs, tests and benchmarks).
struct SolverStats {
  std::int64_t episodes_total = 0;  // episodes simulated since reset()
  std::int64_t episodes_last = 0;   // episodes simulated by the last improve()
  std::int64_t belief_nodes = 0;    // belief (history) nodes alive in the tree
  std::int64_t action_nodes = 0;    // action nodes alive in the tree
  int max_depth = 0;                // deepest belief node below the root (root = 0)
  std::int64_t root_particles = 0;  // states held by the root
};

class Solver {
 public:
  virtual ~Solver() = default;

  // Discards any tree and roots a new one at `belief` (root particles are sampled from it).
  virtual void reset(const pomdp::Belief& belief, Rng& rng) = 0;

  // Simulates episodes from the root until the budget is spent (at least one episode).
  virtual void improve(const Budget& budget, Rng& rng) = 0;

  // The action with the highest estimated value at the root. Requires at least one improve().
  virtual int best_action() const = 0;

  // Estimated value of each action at the root (NaN for actions never tried), for logs.
  virtual std::vector<double> root_action_values() const = 0;

  // Moves the root to the child reached by (action, observation) and frees the rest of the tree.
  // `belief_after` is the agent's real belief after the step; the new root is topped up from it
  // when it holds too few particles (or when the tree never saw this observation).
  virtual void update(int action, const pomdp::Observation& observation,
                      const pomdp::Belief& belief_after, Rng& rng) = 0;

  virtual SolverStats stats() const = 0;
};

}  // namespace echoplan::solvers
