// The value a search tree assigns to a belief node it has not expanded yet.
//
// Why this matters: on the report's problem a uniformly random rollout makes sensing look worthless
// next to the -100 of a wrong sort (random play sorts wrongly half the time), so a planner valuing
// leaves by random rollouts commits after about one observation (about -28 against V* = 2.95).
// Six estimators are offered:
//
//   policy               the value of a default policy that senses with the most informative action
//                        until confident and then commits (sensing_policy.h), rolled out from the
//                        node's exact belief over the states of a tabular identification problem;
//                        the best of its stopping thresholds counts. A lower bound in expectation,
//                        which the search improves on. ABT only; needs model tables.
//   exact                the exact solver's lower bound at the node's belief
//                        (exact_bounds_guide.h): the value of a plan the IdentificationSolver
//                        knows there, after one lookahead over its children's bounds. The same
//                        solver is refined at the root for `exact_share` of every step's
//                        budget, and its [lower, upper] bounds on V* clamp every node's value; at
//                        the root, an action its bounds prove optimal is taken outright. Everything
//                        comes from the problem file within the step's budget. ABT only;
//                        identification problems only.
//   exact-offline        `exact`, but every trial starts from a solve of `offline_expansions`
//                        expansions made once, before the first step (reported apart: it is not
//                        computed within the per-step budget).
//   lookahead            the belief-level value of the best single next step: for each action, the
//                        mean over the node's particles of r(s, a) + gamma * h(s') (h = the model's
//                        heuristic_value; 0 after a terminal step), maximised over actions. For an
//                        object-identification problem that is "commit now to the best sorting
//                        action for this belief, or sense once more and then rely on h".
//   heuristic            the mean of the model's heuristic_value over the node's particles.
//   rollout              the mean discounted return of uniformly random play from each particle
//                        (classic POMCP), plus gamma^k * h at the depth limit. For comparison.
//
// A node stays a leaf until `expand_after` particles have reached it, so the belief-level estimate
// averages over more than one state before the search branches below it.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "common/rng.h"
#include "pomdp/belief.h"
#include "pomdp/model.h"
#include "solvers/sensing_policy.h"
#include "solvers/solver.h"
#include "solvers/use_limits.h"

namespace echoplan::solvers {

enum class LeafMode { policy, exact, exact_offline, lookahead, heuristic, rollout };

// Parses "policy" | "exact" | "exact-offline" | "lookahead" | "heuristic" | "rollout"; throws
// InputError naming the flag otherwise.
LeafMode parse_leaf_mode(const std::string& text);
const char* leaf_mode_name(LeafMode mode);
// Every mode's name, in the order above.
std::vector<std::string> leaf_mode_names();

// The leaf value a solver uses unless told otherwise: `policy` for ABT on a tabular identification
// problem, `lookahead` everywhere else. (`exact` measured better there, docs/BENCHMARKS.md
// "Certified share of V*", but as the default it fails the ROS loop test whose microphone carries
// no evidence: docs/planning.md.)
LeafMode default_leaf_mode(const std::string& solver, const pomdp::Model& model);
// True for the modes that follow the exact belief (policy, exact, exact-offline): only these know
// P(o | b, a), so only ABT takes them.
bool follows_exact_belief(LeafMode mode);

struct LeafOptions {
  LeafMode mode = LeafMode::lookahead;
  int expand_after = 4;  // >= 1: visits a node spends as a leaf before it is expanded
  // Modes exact and exact-offline: the share of each step's budget spent refining the exact
  // solver at the root before the episodes, in [0, 1] (of the milliseconds; with an episode budget
  // of N, N * share solver expansions and N * (1 - share) episodes, at least one).
  double exact_share = 1.0;
  // Mode exact-offline: expansions of the solve made before the first step; >= 1.
  long offline_expansions = 200000;
};

// Running estimate of an unexpanded node's value: one or more accumulators of sampled values, of
// which the best mean counts. A LeafValue (below) decides what is added.
class LeafEstimate {
 public:
  // Counts `samples` more samples and returns `accumulators` sums (all 0 the first time) for the
  // caller to add them to. A lookahead keeps one sum per action, the policy one per threshold,
  // the rest one.
  double* accumulate(std::size_t accumulators, int samples);
  // The current estimate; 0 before any particle was added.
  double value() const;
  int count() const { return count_; }
  // The accumulated sums; the difference across one add() is that particle's contribution.
  const std::vector<double>& sums() const { return sums_; }
  // Takes back one particle's `contribution` (as measured across its add()), for a solver that
  // revises its episodes (AbtSolver::revise).
  void remove(const std::vector<double>& contribution);
  // Sets the estimate to `value` (a leaf valued as a whole rather than particle by particle: the
  // exact modes).
  void set(double value);
  // Frees the accumulators (the node was expanded and no longer needs them).
  void release();

 private:
  std::vector<double> sums_;  // lookahead: one per action; policy: one per threshold; else one
  int count_ = 0;
};

// Where an episode stands when it reaches a node that is still a leaf.
struct LeafVisit {
  const pomdp::Model& model;  // the model planned with now (revise() may have replaced it)
  const pomdp::State& state;  // the particle that reached the node
  std::size_t depth;          // the node's depth below the root
  int steps_left;             // bounds a rollout
  // The result of stepping `state` once with each action when the caller already has it (ABT
  // below the root); the lookahead then reuses it instead of stepping again. May be null.
  const std::vector<pomdp::StepResult>* one_step_each = nullptr;
  // The model's use limits and the episode's uses up to the node (from the start of the real
  // episode, then along the tree's path): estimates never count an action used up there. Null
  // (or no limits): every action is available.
  const UseLimits* limits = nullptr;
  const UseCounts* uses = nullptr;

  bool allows(int action) const { return !limits || !uses || limits->allows(*uses, action); }
};

// How a tree-search solver values its leaves: one implementation per leaf mode, chosen once by
// make_leaf_value(). The modes that value states (lookahead, heuristic, rollout) only implement
// add(). The modes that need the exact belief at each node (policy, exact, exact-offline; ABT on a
// tabular identification problem) also follow it: the root's from reset() and follow(), each
// episode's from start_episode() and descend(); ABT weighs its Q values by it (exact_belief(),
// belief_model()). The exact modes also refine the exact solver inside the step's budget
// (episode_budget()), clamp node values into its bounds (clamp()) and decide at the root
// (root_decision()).
class LeafValue {
 public:
  virtual ~LeafValue() = default;

  // Adds what `visit` tells about the value of the leaf to `estimate`.
  virtual void add(LeafEstimate& estimate, const LeafVisit& visit, Rng& rng) = 0;

  // The tree was rooted at `belief` (reset) / moved along a real step.
  virtual void reset(const pomdp::Belief& /*belief*/) {}
  virtual void follow(int /*action*/, const pomdp::Observation& /*observation*/,
                      const pomdp::Belief& /*belief_after*/) {}
  // An episode starts at the root / goes from `depth` to depth + 1 by `action` into the branch of
  // (discrete) `observation`.
  virtual void start_episode() {}
  virtual void descend(std::size_t /*depth*/, int /*action*/, int /*observation*/) {}

  // The exact belief over the tabular states at `depth` of the episode being walked (depth 0: the
  // root's), or nullptr for a leaf value that does not follow beliefs.
  virtual const std::vector<double>* exact_belief(std::size_t /*depth*/) const { return nullptr; }
  // What weighs those beliefs (observation probabilities, expected rewards); nullptr likewise.
  virtual const SensingPolicy* belief_model() const { return nullptr; }

  // Spends its share of a step's `budget` outside the episodes; returns what is left for them.
  virtual Budget episode_budget(const Budget& budget) { return budget; }
  // `value` of the node at `depth` of the episode being backed up, moved into known bounds.
  virtual double clamp(std::size_t /*depth*/, double value) const { return value; }
  // The root's action when this leaf value knows better than the tree's Q estimates; -1 otherwise.
  virtual int root_decision(int /*actions*/) const { return -1; }
};

// Which tree asks: a belief tree may use every mode; a state tree (POMCP: its leaves see states,
// not beliefs) only lookahead, heuristic and rollout.
enum class LeafUse { belief_tree, state_tree };

// The leaf value `options` asks for, on `model`. Throws InputError when the mode does not fit the
// use (naming the alternatives) or the model (policy, exact, exact-offline need a tabular
// identification problem). With exact-offline the offline solve runs here.
std::unique_ptr<LeafValue> make_leaf_value(const LeafOptions& options, const pomdp::ModelPtr& model,
                                           LeafUse use);

}  // namespace echoplan::solvers
