// Exact bounds on V*(b) and Q*(b, a) for identification problems: tabular POMDPs whose hidden state
// never changes while the agent senses, and whose episodes end with terminal actions (the report's
// "which object is it, then sort it" problem, `make-problem` output, .pomdp files of that shape).
//
// Why it can be exact: when the state is fixed, the belief after any history is
//   b(s) ∝ b0(s) · Π_(a,o) [stay(s, a) · O(a, s, o)]^n_ao
// where n_ao counts how often sensing action a heard o. Histories with the same counts share one
// belief, so a memoised search over count vectors reaches beliefs arbitrarily deep without the
// approximation a point-based solver makes. Every node holds sound bounds, and Bellman backups over
// its children tighten them. A belief met for the first time (the frontier) gets:
//   lower: the best plan among those already found, max_α α·b (HSVI's lower bound). Every backed-up
//          node has a plan (its best action by the lower bound, then its children's plans) whose
//          value from each live state is the vector α = R(·, a) + γ Σ_o stay·O(a, ·, o) α_child(o);
//          the plans start as "commit now" (one vector per terminal action).
//   upper: the sawtooth interpolation (solvers/sawtooth_upper_bound.h) between the known-state
//          values at the corners and the (belief, upper bound) of every backed-up node, capped by
//          max(commit now, max over sensing a of R(b, a) + γ Σ_s b(s) stay(s, a) V_known(s))
//          (with use limits, over the sensing actions still allowed),
//          where V_known(s) is the value when s is known ("one more sensing reveals the state"),
//          and by the partition relaxation: revealing which pair of states holds can only help,
//          so V*(b) <= Σ_pairs P(pair) V*_pair(b | pair), with each two-state sub-problem solved
//          once, up front, on a grid (solvers/pair_relaxation_bound.h).
// Both are valid at any belief because V* over the live states is convex (a POMDP value).
//
// Refinement works in passes of shrinking δ (the default): a pass expands, depth first, every
// belief whose reach · (upper − lower) exceeds δ (skipping actions whose upper bound is below what
// the belief already guarantees), and backs the bounds up; δ halves until the gap at the belief
// asked about meets the target. A belief's reach is γ^t · P(one history to it) · (the number of
// histories with its counts, at most Π_a n_a! / Π_o n_ao!): every history with the same counts is
// equally likely, so this bounds what the belief's gap can add to the gap at b0, whichever way it
// is reached. Weighting by reach stops the search down paths of negligible probability. New nodes
// start with the cheap bounds (commit now / one more sensing); the stored plans and points are
// consulted when a node is about to be expanded, which they may spare. The alternative,
// HSVI-style trials (Smith & Simmons 2005: descend the action with the highest upper bound and the
// observation with the largest P(o) · (gap − ε γ^-t), back up along the path) measured worse here
// (docs/BENCHMARKS.md, "Exact identification solver") and is kept as an option for that
// comparison. Every call is anytime: the bounds are valid whenever it stops.
//
// Shape accepted (identification_shape() explains a refusal in words):
//   - absorbing states: every action keeps them with reward 0 (Cassandra's goal-state rule);
//   - from a live state, every action either keeps the state or ends the episode (moves it to an
//     absorbing state, e.g. a sorting action or a collision), never to another live state;
//   - at least one terminal action (ends the episode from every live state);
//   - the start belief puts no mass on absorbing states.
// A collision (a sensing action that sometimes ends the episode) is allowed: its mass leaves the
// live belief, whose value is then scaled, V*(mixture) = (1 - q) V*(live part), since absorbing
// states earn nothing whatever is done.
//
// Use limits (IdentificationTables::limits, from pomdp::Model::max_uses): the uses of sensing
// action a at a node are its counts Σ_o n_ao, so a node is a (belief, uses) pair and V* there is
// the value with the remaining uses. Used-up actions are skipped everywhere (expansion, backups,
// trials; action_value() gives them -inf). A belief *after some uses* is the node its history
// reaches from the root by child(), as certify and the exact leaves walk it. The bounds stay
// sound: every node's own plan is feasible from that node; the upper bounds (known-state values,
// the pair relaxation, the sawtooth corners) ignore the limits, and dropping a limit can only
// raise V* (one more sensing counts only the actions still allowed, which is all that can come
// next). When every sensing action is limited, a belief with few readings left is also capped by
// what an agent told all of them at once could earn (solvers/readings_left_bound.h), which sees
// that they may not be enough to tell the object apart. What does not carry over as is, is reuse
// across nodes with different uses. The frontier's plans are therefore kept with their worst-case
// uses per action (the most any branch of the plan takes each action; commit-now plans need none)
// and a plan bounds a node from below only when it fits the node's remaining uses; they are not
// pruned by dominance (a dominated plan that needs fewer uses may be the one that fits). A sawtooth
// point's upper bound holds only for nodes with at least its uses spent, so with limits no points
// are stored (the corners stay). After a few readings, though, the stored plans (found near the
// root) rarely fit, and commit now is far below what one more reading earns: so with limits every
// new belief is also bounded below by the best "sense once, then sort by what was heard" among the
// actions its uses leave (a plan needing one use of that action). On a 20-class, 9-action problem
// with one use per action this halved the gap at b0 for the same expansions (docs/BENCHMARKS.md,
// "ABT, the exact solver and certify at 20 and 100 classes with 9 behaviours").
//
// Nodes are found by a 128-bit key, the sum of two independent random 64-bit codes per (a, o) pair
// times its count (order-free, so every path to the same counts meets the same node); two count
// vectors share a key with probability about 2^-128 per pair of nodes.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pomdp/model.h"
#include "solvers/alpha_vector_set.h"
#include "solvers/bounds.h"
#include "solvers/identification_tables.h"
#include "solvers/pair_relaxation_bound.h"
#include "solvers/readings_left_bound.h"
#include "solvers/sawtooth_upper_bound.h"

namespace echoplan::solvers {

// When a refinement call stops (whichever comes first); a call that stops early leaves valid
// bounds.
struct RefineLimits {
  double target_gap = 1e-4;  // absolute, in reward units
  double seconds = 0.0;      // wall time; <= 0 means no limit
  long expansions = 0;       // node expansions; <= 0 means no limit (repeats on any machine)
};

// How the solver bounds new beliefs and where it spends its expansions. The defaults are the
// fastest measured (docs/BENCHMARKS.md, "Exact identification solver"); the others are there to
// measure what each part buys.
struct IdentificationOptions {
  enum class Search { trials, passes };
  Search search = Search::passes;
  // Passes: at a node, expand only the actions whose upper bound on Q* lies within this share of
  // the node's gap below its upper bound (1: every action that can still be optimal). 0.3 narrows
  // the gap on V*(b0) 1.0-1.7x per expansion, but leaves the other actions' Q* loose, and what
  // their bounds then need costs more: certify took 10x the CPU on a 20-class problem
  // (docs/BENCHMARKS.md, "Exact identification solver").
  double expand_within = 1.0;
  bool plan_lower_bound = true;      // frontier lower bound from backed-up plans (else commit now)
  bool sawtooth_upper_bound = true;  // frontier upper bound by sawtooth (else one-more-sensing)
  // Every new belief's upper bound also capped by the partition relaxation over two-state
  // sub-problems solved up front (solvers/pair_relaxation_bound.h).
  bool pair_upper_bound = true;
  PairRelaxationOptions pair_relaxation;
  // A backed-up node's plan (point) joins the frontier's lower (upper) bound only when it beats
  // that bound at its belief by more than this: every stored plan and point costs every later
  // frontier evaluation, and small gains are not worth it (reward units).
  double frontier_margin = 1e-3;
  // At most this many points, and this many plans unless max_frontier_plans says otherwise (the
  // first found, which come from the beliefs nearest the root): a frontier evaluation costs
  // (plans + points) · states.
  std::size_t max_frontier_entries = 256;
  // The plans' own cap when > 0 (else max_frontier_entries): a plan costs a dot product over
  // the states per evaluation (kept contiguous), a sawtooth point a scan over its support, and
  // the frontier's lower bound is the side that gains more from more entries (measured: 1024
  // plans narrow the gap in equal time against 256 on the report's and 8-object problems;
  // docs/BENCHMARKS.md, "Exact identification solver").
  std::size_t max_frontier_plans = 1024;
  // With use limits, every new belief's lower bound also from the best "sense once, then sort by
  // what was heard" among the sensing actions its uses leave (else commit now): deep beliefs
  // rarely fit a stored plan, and commit now is far below what one more reading earns there
  // (measured: the gap at b0 on 20 classes with one use per behaviour halves for the same
  // expansions; docs/BENCHMARKS.md). Without limits it is not used: every stored plan fits every
  // belief, and it measured only slower.
  bool sense_once_lower_bound = true;
  // With every sensing action limited, every new belief's upper bound also capped by what an
  // agent told every reading its uses leave, at once, could earn (solvers/readings_left_bound.h):
  // the other upper bounds assume sensing can go on until the state is known.
  bool readings_left_upper_bound = true;
  ReadingsLeftOptions readings_left;
  // Memory cap: refinement stops (bounds stay valid) when this many nodes exist; 0: about 2 GB.
  std::size_t max_nodes = 0;
};

// Not thread-safe (even const calls share scratch space): one solver per thread.
class IdentificationSolver {
 public:
  using NodeId = std::int32_t;
  // The child of a node when the observation cannot be heard from any live state (it signals the
  // end of the episode, e.g. a collision's "none").
  static constexpr NodeId kEnded = -1;

  // Reads the tables once (the model is not kept). Throws std::invalid_argument with
  // identification_shape_problem()'s reason when the model does not qualify.
  explicit IdentificationSolver(const pomdp::TabularModel& model,
                                const IdentificationOptions& options = {});
  // The same on tables already read (shared with other users of the same problem).
  explicit IdentificationSolver(std::shared_ptr<const IdentificationTables> tables,
                                const IdentificationOptions& options = {});

  NodeId root() const { return 0; }
  // The node after sensing action `action` heard observation `observation` at `node`, created if
  // needed; kEnded when no live state can emit it. Throws std::invalid_argument when `action` is
  // not a sensing action, is used up at `node` (available()), or an index is out of range.
  NodeId child(NodeId node, int action, int observation);

  // Bounds on V*(b) at the node's belief b (over live states only; see the header comment).
  Bounds value(NodeId node) const;
  // Bounds on Q*(b, a) from the current bounds of the children (one backup, no search); -inf for
  // an action used up at the node.
  Bounds action_value(NodeId node, int action) const;
  // P(observation | b, action) for a sensing action, counting only outcomes that stay live.
  double observation_probability(NodeId node, int action, int observation) const;
  // The node's belief over all model states (absorbing ones 0).
  std::vector<double> belief(NodeId node) const;
  // How often sensing action `action` was taken on the way to `node` (Σ_o n_ao; 0 for a terminal
  // action), and whether the use limits allow it once more there (a terminal action: always).
  int uses(NodeId node, int action) const;
  bool available(NodeId node, int action) const;

  // Tightens value(node) until its gap is at most limits.target_gap (or a limit is hit).
  // Returns true when the target was reached.
  bool refine(NodeId node, const RefineLimits& limits);
  // Tightens action_value(node, action) the same way (a terminal action's value is exact).
  bool refine_action(NodeId node, int action, const RefineLimits& limits);

  bool is_terminal_action(int action) const { return kind_[action] == ActionKind::terminal; }
  bool is_sensing_action(int action) const { return kind_[action] == ActionKind::sensing; }
  int num_actions() const { return num_actions_; }
  int num_observations() const { return num_observations_; }
  double discount() const { return discount_; }
  std::size_t num_nodes() const { return lower_.size(); }
  long expansions() const { return expansions_; }
  // How many plans bound new beliefs from below, and how many belief points from above.
  std::size_t num_plans() const { return plan_matrix_.size() / std::size_t(num_live_); }
  std::size_t num_upper_points() const { return upper_points_.num_points(); }
  // How many two-state sub-problems cap new beliefs' upper bounds (0 when the option is off).
  std::size_t num_relaxation_pairs() const { return pair_bound_.num_pairs(); }
  // That bound, over the live states in model order (belief() without the absorbing states).
  const PairRelaxationBound& pair_relaxation() const { return pair_bound_; }

 private:
  enum class ActionKind { sensing, terminal };
  struct Key {
    std::uint64_t a = 0, b = 0;
    friend bool operator==(const Key&, const Key&) = default;
  };
  // Node ids by key: open addressing with linear probing (the keys are random codes, so their
  // low bits are a good hash). A node-based hash map cost a cache miss or two per lookup and
  // was the largest single cost of a search (perf; git history).
  class NodeIndex {
   public:
    // The node with `key`, or kEnded when there is none.
    NodeId find(const Key& key) const;
    void insert(const Key& key, NodeId id);

   private:
    struct Slot {
      Key key;
      NodeId id = kEnded;
    };
    void grow();
    std::vector<Slot> slots_;
    std::size_t size_ = 0;
  };
  // What a one-step lookahead at a node says about its children.
  struct ChildView {
    double probability = 0.0;
    Bounds bounds;
    NodeId id = kEnded;  // kEnded when the child is not stored yet
  };

  const double* node_belief(NodeId node) const { return &beliefs_[std::size_t(node) * num_live_]; }
  // The child's live belief (unnormalised weight returned) into `out`.
  double child_belief(const double* belief, int action, int observation, double* out) const;
  // Bounds at a belief not backed up yet; its best plan's vector into `plan` when not null.
  // simple_bounds: commit now / one more sensing (cheap, what new nodes start with);
  // frontier_bounds: the stored plans and the sawtooth (tighter, costs a pass over both).
  // `uses`: the belief's node's uses per action (null: none), which decide what it may still
  // sense; its plan's worst-case uses per action into `plan_uses` when not null.
  // lower_wanted false: a caller that reads only the upper bound skips sense_once() (the lower
  // bound is then commit now, still sound).
  Bounds simple_bounds(const double* belief, const std::uint16_t* uses, double* plan,
                       std::uint16_t* plan_uses, bool lower_wanted = true) const;
  // `lower` raised to the best "sense once, then sort by what was heard" among the sensing
  // actions `uses` still allows, when one beats it; that plan into `plan` and its uses into
  // `plan_uses` (one of its action), each when not null (left alone otherwise).
  double sense_once(const double* belief, const std::uint16_t* uses, double lower, double* plan,
                    std::uint16_t* plan_uses) const;
  // The best sort after hearing an observation whose emission row (over live states) is `e`: the
  // terminal action whose bonus above the floor, weighted by belief · e, is largest (into
  // `terminal`); returns that weighted bonus.
  double best_sort_bonus(const double* belief, const double* e, int& terminal) const;
  // Action `action` may be taken once more after `uses` (null: none): limits and prerequisites.
  bool allowed(const std::uint16_t* uses, int action) const;
  // Fills sort_floor_, sort_bonus_ and heard_floor_ from the tables (only when sense_once() is
  // used), and sizes its scratch space.
  void read_sort_rewards();
  // The upper bound is never above upper_cap (a bound already known there).
  // With limits, `node_uses` (the node's uses per action) admits only the plans that fit them;
  // the chosen plan's index goes to `index` when not null.
  Bounds frontier_bounds(const double* belief, double* plan, double upper_cap,
                         const std::uint16_t* node_uses = nullptr,
                         std::size_t* index = nullptr) const;
  // The stored plan best at `belief` (its values over live states) and its value there.
  // With `node_uses`, only among the plans that fit them (plan_fits); `index` as above.
  const double* best_plan(const double* belief, double& value,
                          const std::uint16_t* node_uses = nullptr,
                          std::size_t* index = nullptr) const;
  // `plan_uses`: with limits, the plan's worst-case uses per action (null: none, commit now).
  void add_plan(AlphaVector plan, const std::uint16_t* plan_uses = nullptr);
  // With limits: stored plan `plan` needs no more uses than a node with `node_uses` has left.
  bool plan_fits(std::size_t plan, const std::uint16_t* node_uses) const;
  // The node's uses per action (into scratch space, valid until the next call).
  const std::uint16_t* node_uses(NodeId node) const;
  // Tightens a stored node's bounds with what the plans and points know now.
  void refresh(NodeId node);
  double expected_reward(const double* belief, int action) const;
  NodeId insert(const Key& key, const double* belief, double log_reach,
                const std::uint16_t* counts);
  Key child_key(NodeId node, int action, int observation) const;
  // Bounds on Q(node, action) from its children's bounds; fills `children` (one per observation)
  // and, when `plan` is not null, the vector of the plan "action, then each child's plan".
  // With limits, `plan_uses` (when not null) gets that plan's worst-case uses per action.
  // lower_wanted false: the children not stored yet get simple_bounds() without sense_once()
  // (for a caller that reads only the upper bound).
  Bounds lookahead(NodeId node, int action, std::vector<ChildView>& children,
                   double* plan = nullptr, std::uint16_t* plan_uses = nullptr,
                   bool lower_wanted = true) const;
  // Bellman backup of both bounds; true when either tightened.
  bool backup(NodeId node);
  // What one refine call may still spend (its RefineLimits and what it has spent so far; not an
  // online solver's per-step Budget, solver.h).
  struct RefineSpend {
    RefineLimits limits;
    std::chrono::steady_clock::time_point start;
    long expansions = 0;
    bool stopped = false;
    bool exhausted(const IdentificationSolver& solver);
  };
  // Expands `node` and, recursively, every descendant whose reach · gap exceeds `delta`, then
  // backs it up; at `node` only `forced_action` when it is >= 0 (and regardless of its gap).
  void expand(NodeId node, double delta, int forced_action, RefineSpend& budget);
  // One HSVI trial from `node` (first action `forced_action` when >= 0); true when it tightened a
  // bound or made a node.
  bool trial(NodeId node, int forced_action, double epsilon, RefineSpend& budget);
  // refine() (action < 0) or refine_action().
  bool refine_to(NodeId node, int action, const RefineLimits& limits);

  int num_states_ = 0, num_actions_ = 0, num_observations_ = 0, num_live_ = 0;
  double discount_ = 0.0;
  std::size_t max_nodes_ = 0;
  std::shared_ptr<const IdentificationTables> tables_;  // the problem, over live states
  std::vector<ActionKind> kind_;                        // per action
  std::vector<Key> pair_code_;                          // [a * O + o]
  IdentificationOptions options_;
  AlphaVectorSet plans_;             // over live states: the frontier's lower bound
  std::vector<double> plan_matrix_;  // [k * L + l]: plans_'s vectors, contiguous for the scans
  SawtoothUpperBound upper_points_{{{0.0}}, 0.0};  // over live states: the frontier's upper bound
  PairRelaxationBound pair_bound_;                 // over live states: every new belief's cap
  ReadingsLeftBound readings_bound_;  // with limits on every sensing action: another cap

  // Nodes: flat arrays indexed by NodeId.
  std::vector<double> beliefs_;  // [node * L + l], normalised over live states
  std::vector<Key> keys_;
  std::vector<double> lower_, upper_;
  std::vector<double> plan_;  // [node * L + l]: the plan achieving lower_ (lower_ = plan · belief)
  // log of the node's reach weight γ^t · (number of histories with its counts, bounded) ·
  // P(one such history): an upper bound on how much its gap can add to the gap at b0.
  std::vector<double> log_reach_;
  // [node * count_pairs_ + count_slot_[a] + o] = n_ao, for sensing actions only (a terminal
  // action is never counted, and the counts are most of a node's memory).
  std::vector<std::uint16_t> counts_;
  std::vector<int> count_slot_;  // [a]: the sensing action's first count in a node's; -1: terminal
  std::size_t count_pairs_ = 0;  // counts per node: sensing actions × observations
  // The smallest δ each node was expanded with; +inf when never.
  std::vector<double> expanded_at_;
  NodeIndex index_;
  long expansions_ = 0;
  std::vector<ChildView> children_scratch_;     // backup()'s lookahead
  mutable std::vector<double> belief_scratch_;  // lookahead()'s child belief
  mutable std::vector<double> plan_scratch_;    // lookahead()'s child plan
  // Use limits (tables_->limits.any()): stored plans are kept with their worst-case uses per
  // action and admitted at a node only when they fit its remaining uses.
  bool limited_ = false;
  std::vector<std::uint16_t> plan_uses_matrix_;      // [k * A + a]: stored plan k's uses of a
  std::vector<std::uint16_t> node_plan_uses_;        // [node * A + a]: the node's plan's uses of a
  mutable std::vector<std::uint16_t> uses_scratch_;  // node_uses(), insert()
  mutable std::vector<std::uint16_t> child_uses_scratch_, child_plan_uses_scratch_;  // lookahead()
  mutable std::vector<int> sort_scratch_;  // [a * O + o]: sense_once()'s sort after (a, o)
  // The terminal actions' rewards as a floor per live state (the least any of them pays there)
  // plus each one's sparse bonus above it: the best sort after an observation then costs the
  // bonus entries (one per state when a sort pays more only in its own bin's states), not
  // terminals × states.
  struct SortBonus {
    int state;
    double bonus;
  };
  std::vector<double> sort_floor_;             // [l]
  std::vector<int> sort_terminals_;            // the terminal actions
  std::vector<SortBonus> sort_bonus_;          // by terminal, in sort_terminals_'s order
  std::vector<std::size_t> sort_bonus_start_;  // [k]: terminal k's first entry; one past the end
  // [a * L + l]: the floor a sort earns in state l after sensing a, whatever is heard:
  // Σ_o emission(a, o, l) · sort_floor_[l] (sensing actions; 0 for terminal ones).
  std::vector<double> heard_floor_;
};

}  // namespace echoplan::solvers
