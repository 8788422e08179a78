// The belief tree that ABT and POMCP share, and the parts of a tree-search solver they have in
// common.
//
// A BeliefNode stands for a history (the root: the agent's current belief). It holds the particles
// (sampled states) that episodes brought to it, one ActionNode per action tried from it, and a leaf
// estimate while it is unexpanded. An ActionNode branches on observations (see
// observation_branch.h) to child BeliefNodes. The solvers differ only in how an episode's returns
// flow back up: ABT (abt_solver.h) recomputes each Q from its children's values (a max backup over
// the stored episodes), POMCP (pomcp_solver.h) averages the sampled returns (Monte-Carlo backup).
//
// TreeSearchSolver owns the tree: reset, the budget loop, UCB action selection, re-rooting and
// pruning on update, root replenishment and statistics. Every node registers itself in the solver's
// NodeCounts while alive, so the counts show that pruned subtrees really are freed.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pomdp/model.h"
#include "pomdp/problem.h"
#include "solvers/leaf_value.h"
#include "solvers/observation_branch.h"
#include "solvers/solver.h"
#include "solvers/use_limits.h"

namespace echoplan::solvers {

// How ABT values the outcomes of a sensing action that no episode has heard yet, when it follows
// the exact belief (leaf policy, exact or exact-offline):
//   share   the heard outcomes stand for the unheard in proportion to P(o | b, a). Unbiased when
//           every outcome is about as valuable; with many outcomes and few visits one lucky outcome
//           speaks for all, and the max over actions above then favours sensing.
//   commit  an unheard outcome counts the value of committing right after it (and a heard one at
//           least that): a lower bound, so sensing is worth only what the episodes have shown.
//           Favours behaviours whose outcomes are few. docs/planning.md says where each wins.
enum class UnheardOutcomes { share, commit };

// Parses "share" | "commit"; throws InputError otherwise.
UnheardOutcomes parse_unheard_outcomes(const std::string& text);
const char* unheard_outcomes_name(UnheardOutcomes unheard);
std::vector<std::string> unheard_outcomes_names();

// Options shared by the tree-search solvers. Validated by validate().
// The exploration constant and depth default to pomdp::PlannerDefaults (problem.h), the one place
// they are defined, so a problem file without a planner section and a SearchOptions{} agree.
struct SearchOptions {
  // UCB constant c (reward units): Q + c sqrt(ln N / n); >= 0
  double exploration = pomdp::PlannerDefaults{}.exploration;
  // Belief nodes deeper than this are valued by the leaf estimate; >= 1
  int max_depth = pomdp::PlannerDefaults{}.depth;
  int root_particles = 1000;     // particles drawn from the belief at reset / replenishment; >= 1
  int min_root_particles = 100;  // after update, a root with fewer particles is replenished; >= 0
  LeafOptions leaf;
  UnheardOutcomes unheard = UnheardOutcomes::share;  // ABT with a leaf that follows the belief
  ObservationBranching branching;
  // ABT only: keep every episode's (state, action, observation, reward) steps so that
  // AbtSolver::revise() can revise the tree after a model change. Off by default: nothing in
  // echoplan's commands changes the model mid-run, and keeping them adds CPU time per episode that
  // grows with the tree (measured: docs/BENCHMARKS.md, "Planning").
  bool keep_episodes = false;

  // Throws InputError naming the offending option.
  void validate() const;
};

// Live nodes of one tree (maintained by the nodes' constructors and destructors).
struct NodeCounts {
  std::int64_t belief = 0;
  std::int64_t action = 0;
};

struct ActionNode;

struct BeliefNode {
  explicit BeliefNode(NodeCounts* counts);
  ~BeliefNode();
  BeliefNode(const BeliefNode&) = delete;
  BeliefNode& operator=(const BeliefNode&) = delete;

  NodeCounts* counts;
  std::vector<pomdp::State> particles;               // states episodes brought here
  std::vector<std::unique_ptr<ActionNode>> actions;  // indexed by action; null until tried
  std::int64_t visits = 0;                           // episodes that reached this node
  std::int64_t action_visits = 0;                    // episodes that took an action here
  bool expanded = false;                             // false while valued by `leaf`
  LeafEstimate leaf;
  double value = 0.0;  // ABT: max_a Q (expanded) or the leaf estimate; POMCP: unused
  // ABT: every filed particle stepped once with every action; per action, the sum of the immediate
  // rewards, so Q's immediate term averages over all of the node's particles.
  std::vector<double> particle_reward_sums;
  std::int64_t particles_evaluated = 0;
  // ABT with an exact belief along the path: the belief the actions' cached terms below
  // (ActionNode::child_probability, ...) were computed at. Re-weighing a node's children at every
  // episode costs O(children x states) per action; the belief at a node rarely changes, so the
  // terms are kept until it does.
  std::vector<double> weighed_belief;
};

struct ObservationChild {
  pomdp::Observation observation;  // the branch's representative observation
  std::unique_ptr<BeliefNode> node;
  std::int64_t arrivals = 0;   // non-terminal transitions into this branch (ABT weights)
  double counted_value = 0.0;  // the child's value as last folded into the parent's future_sum
};

struct ActionNode {
  explicit ActionNode(NodeCounts* counts);
  ~ActionNode();
  ActionNode(const ActionNode&) = delete;
  ActionNode& operator=(const ActionNode&) = delete;

  NodeCounts* counts;
  std::int64_t visits = 0;
  double future_sum = 0.0;  // ABT: sum over children of arrivals * value
  double value = 0.0;       // the action's estimated value, used by UCB and best_action()
  std::vector<ObservationChild> children;
  // ABT's exact-belief terms at the node's weighed_belief: for children[0..k) (children are only
  // ever appended) P(o | b, a) and, with unheard outcomes at commit, SensingPolicy::commit_after(b,
  // a, o).commit; the expected reward, and either the chance the episode goes on (unheard shared)
  // or the value of sensing once with this action and then committing (unheard at commit).
  std::vector<double> child_probability, child_commit;
  double expected_reward = 0.0;
  double live_probability = 0.0;
  double commit_after_sensing = 0.0;
  bool weighed = false;
};

class TreeSearchSolver : public Solver {
 public:
  // Builds the leaf value options.leaf asks for (make_leaf_value(), for a tree of kind `use`).
  TreeSearchSolver(pomdp::ModelPtr model, SearchOptions options, LeafUse use);
  TreeSearchSolver(const TreeSearchSolver&) = delete;
  TreeSearchSolver& operator=(const TreeSearchSolver&) = delete;

  void reset(const pomdp::Belief& belief, Rng& rng) override;
  void improve(const Budget& budget, Rng& rng) override;
  int best_action() const override;
  std::vector<double> root_action_values() const override;
  void update(int action, const pomdp::Observation& observation, const pomdp::Belief& belief_after,
              Rng& rng) override;
  SolverStats stats() const override;

  // Belief nodes in the subtree that update(action, observation) would keep (0 if none), counted
  // by walking the tree; lets tests check that update() keeps exactly that subtree.
  std::int64_t subtree_belief_nodes(int action, const pomdp::Observation& observation) const;
  // Belief and action nodes reachable from the root, counted by walking the tree.
  NodeCounts reachable_nodes() const;

  const SearchOptions& options() const { return options_; }

 protected:
  // One episode from a particle of the root, including its backup.
  virtual void run_episode(Rng& rng) = 0;
  // Called for each particle reset() or replenishment adds to the root.
  virtual void root_particle_added(BeliefNode& /*root*/, const pomdp::State& /*state*/,
                                   Rng& /*rng*/) {}
  // Called by reset() and update() while the old tree still exists, before everything outside the
  // subtree of `kept` (the new root; null when none is kept) is freed.
  virtual void before_reroot(const BeliefNode* /*kept*/) {}
  // Plans with `model` from now on (a model change, see model_change.h). Throws InputError when
  // it does not share the old model's actions, observation names and discount.
  void replace_model(pomdp::ModelPtr model);

  const pomdp::Model& model() const { return *model_; }
  const pomdp::ModelPtr& model_ptr() const { return model_; }
  bool has_root() const { return root_ != nullptr; }
  BeliefNode& root() { return *root_; }
  const pomdp::State& sample_root_particle(Rng& rng) const;
  // How leaves are valued (chosen once, from options().leaf).
  LeafValue& leaf_value() { return *leaf_value_; }
  const LeafValue& leaf_value() const { return *leaf_value_; }
  // Decides how the episode treats a node at `depth` reached for the visits-th time: returns true
  // when the node is valued as a leaf this time; otherwise expands it (once: `expanded` set, its
  // leaf accumulators freed) and returns false, and the caller must choose an action.
  bool leaf_or_expand(BeliefNode& node, int depth);
  // UCB1 over the node's actions still allowed after `uses` (the episode's uses up to the node,
  // path_uses_at_root() plus the path); untried actions first, in index order. Throws
  // std::logic_error when the limits leave no action.
  int select_action(const BeliefNode& node, const UseCounts& uses) const;
  // The model's use limits (empty when it has none) and the uses of the real steps since reset():
  // where every episode's count starts.
  const UseLimits& use_limits() const { return use_limits_; }
  const UseCounts& path_uses_at_root() const { return root_uses_; }
  ActionNode& action_node(BeliefNode& node, int action);
  // Index of the child of `action` that `observation` branches to, created if new.
  std::size_t child_for(ActionNode& action, const pomdp::Observation& observation);

 private:
  std::unique_ptr<BeliefNode> new_belief_node();
  void replenish_root(const pomdp::Belief& belief, Rng& rng);

  pomdp::ModelPtr model_;
  SearchOptions options_;
  UseLimits use_limits_;
  UseCounts root_uses_;  // actions taken in the real episode so far (told through update())
  std::unique_ptr<LeafValue> leaf_value_;
  NodeCounts counts_;  // declared before root_ so it outlives the nodes
  std::unique_ptr<BeliefNode> root_;
  std::int64_t episodes_total_ = 0;
  std::int64_t episodes_last_ = 0;
};

}  // namespace echoplan::solvers
