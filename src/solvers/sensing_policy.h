// A default policy for identification problems: sense with the most informative action until
// confident, then commit. ABT rolls it out at new leaves (leaf mode `policy`, leaf_value.h).
//
// Why: the `lookahead` leaf value ("commit now, or sense once more and then know for sure") is an
// upper bound that treats one more observation as a perfect one, so on the report's noisy sensors
// it values every uncertain belief at about -1 + γ·10 and keeps the search sensing for the wrong
// reasons. The value of a policy anyone could follow is a lower bound instead, and the search above
// the leaves improves on it (ABT's max backup turns the tree into a policy-improvement step on
// top).
//
// The policy works on the exact belief b over a tabular model's states (identification shape: the
// state stays fixed while sensing, terminal actions end the episode;
// solvers/identification_solver.h says which models qualify). At b:
//   loss(b) = Σ_s b(s) best_commit(s) − max_a Σ_s b(s) R(s, a)   (a over terminal actions)
// is what committing now loses against committing knowing the state. The policy commits when
// loss(b) ≤ ε and otherwise takes the sensing action with the largest expected drop of the entropy
// of "which terminal action is right" (information about the decision, not about distinctions that
// do not change it). One rollout follows a family of thresholds ε at once: the policies differ only
// in when they stop, so with the same random numbers they share one trajectory, and each
// threshold's return is read off where it would have committed. Rewards are taken as expectations
// under the current belief (Σ_s b(s) R(s, a)) rather than sampled, which leaves the mean unchanged
// and removes most of the variance of a sorting action's +10 / −100.
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "common/rng.h"
#include "pomdp/model.h"
#include "solvers/identification_tables.h"
#include "solvers/sparse_grouped_entropy.h"

namespace echoplan::solvers {

// Not thread-safe (scratch space is shared between calls): one per solver.
class SensingPolicy {
 public:
  // The stopping thresholds ε followed by one rollout (reward units), the first +inf (commit now).
  static constexpr int kThresholds = 12;

  // Reads the tables of `model`, with the use `limits` of the Model they belong to. Throws
  // InputError when the model has no tables or is not an identification problem (the reason in
  // words).
  explicit SensingPolicy(const pomdp::TabularModel& model, const UseLimits& limits = {});
  // The same on tables already read (shared with the exact solver of the same problem).
  explicit SensingPolicy(std::shared_ptr<const IdentificationTables> tables);

  int num_states() const { return num_states_; }
  // Bayes' rule for a sensing action: b'(s) ∝ b(s) stay(s, a) O(a, s, o). Returns P(o | b, a) (live
  // outcomes only); `out` is left unnormalised (all 0) when that is 0.
  double update(const std::vector<double>& belief, int action, int observation,
                std::vector<double>& out) const;
  // True for an action that ends the episode from every live state.
  bool is_terminal(int action) const { return tables_->terminal[action]; }
  // P(o | b, a) for a sensing action, counting only outcomes that keep the episode going.
  double observation_probability(const std::vector<double>& belief, int action,
                                 int observation) const;
  // P(the episode goes on | b, a): Σ_s b(s) stay(s, a).
  double live_probability(const std::vector<double>& belief, int action) const;
  // The value of sensing once with `action` and then committing, without the sensing's own reward
  // or discount: Σ_o P(o | b, a) commit_value(b after o) (an outcome that ends the episode counts
  // 0).
  double commit_after_sensing(const std::vector<double>& belief, int action) const;
  // One outcome's term of that sum, `commit` = P(o | b, a) commit_value(b after o) (0 for an
  // outcome that ends the episode or cannot be heard), with its `probability` P(o | b, a) (the
  // same bits as observation_probability()).
  struct OutcomeTerm {
    double probability, commit;
  };
  OutcomeTerm commit_after(const std::vector<double>& belief, int action, int observation) const;
  // Σ_s b(s) R(s, a).
  double expected_reward(const std::vector<double>& belief, int action) const;
  // The best terminal action's expected reward under `belief`.
  double commit_value(const std::vector<double>& belief) const;
  // The sensing action the policy takes at `belief` after the episode's `uses` (empty: none); -1
  // when the use limits leave none.
  int choose_sensing(const std::vector<double>& belief, const UseCounts& uses = {}) const;
  // One rollout from `belief` (the true state drawn from it), at most `steps` steps, after the
  // episode's `uses` (the policy then senses only with actions still available, and commits when
  // none is): adds the discounted return of each threshold's policy to returns[0..kThresholds).
  void rollout(const std::vector<double>& belief, const UseCounts& uses, int steps, Rng& rng,
               double* returns) const;
  void rollout(const std::vector<double>& belief, int steps, Rng& rng, double* returns) const {
    rollout(belief, UseCounts{}, steps, rng, returns);
  }

 private:
  // Σ_s b(s) best_commit(s) − commit, with commit = commit_value(belief).
  double loss(const std::vector<double>& belief, double commit) const;
  // True when some sensing action is still available after `uses`.
  bool can_sense(const UseCounts& uses) const;
  double decision_entropy(const std::vector<double>& belief) const;
  // choose_sensing() without the memo: the first sensing action, in the problem's order, whose
  // expected decision entropy is within kChoiceMargin of the lowest (the sums' last bits depend
  // on the machine, entropy_kernels.h).
  int choose_sensing_now(const std::vector<double>& belief, const UseCounts& uses) const;
  // expected_[i] by the sparse sum at `belief` (live_belief_ holds its live states), left +inf
  // where a lower bound shows the action cannot be chosen (kPruneMargin keeps the bound's own
  // rounding from pruning a choice).
  void expect_sparse(const std::vector<double>& belief, const UseCounts& uses) const;
  static constexpr double kChoiceMargin = 1e-12, kPruneMargin = 1e-9;
  // Σ_o P(o | b, a) H(decision | b, a, o), outcome by outcome from the normalised posterior (the
  // problems below kLargeAbove: their results stay bit for bit what they were).
  double expected_entropy_by_outcome(const std::vector<double>& belief, int a) const;
  // The same sum rearranged so no posterior is normalised and every log is taken in one
  // vectorised pass, on live_belief_ (the large problems: equal up to rounding, several times
  // faster at 100 states x 100 outcomes).
  double expected_entropy_grouped(int a) const;

  // Σ_o P(o | b, a) value_after(b after o) over the outcomes that keep the episode going (defined
  // and used in the .cpp only).
  template <class ValueAfter>
  double expect_over_outcomes(const std::vector<double>& belief, int action,
                              ValueAfter value_after) const;
  // P(o | s, a) stay(s, a) over the live states, for a sensing action.
  const double* emission(int action, int observation) const;

  std::shared_ptr<const IdentificationTables> tables_;           // the problem, over live states
  int num_states_ = 0, num_actions_ = 0, num_observations_ = 0;  // states: the model's, all
  double discount_ = 0.0;
  std::vector<int> sensing_, terminal_;  // the non-terminal actions, the terminal ones
  // [l * terminal_.size() + j]: R(l, terminal_[j]).
  std::vector<double> terminal_reward_by_state_;
  std::vector<double> best_commit_;  // [l]: max over terminal a of R(l, a)
  std::vector<int> best_terminal_;   // [l]: that action
  std::vector<double> thresholds_;   // kThresholds values, decreasing
  mutable std::vector<double> scratch2_, groups_, commit_sums_;

  // The large problems (sensing actions x outcomes x states >= kLargeAbove) take the grouped sum,
  // or the sparse one below.
  static constexpr double kLargeAbove = 4096;
  bool large_ = false;
  // The choices already made, by the exact bits of (belief, uses): a rollout from a leaf the
  // search visits again, or one that hears what an earlier rollout heard, asks the same question,
  // and the answer is a pure function of it (so the memo never changes a result). Kept where a
  // choice is costly, the large problems' dense sums (about a tenth of the questions come again;
  // on the sparse sum, looking up costs more than it saves); emptied when it reaches
  // kMaxMemoizedChoices (about 1 KB each at 100 states).
  static constexpr std::size_t kMaxMemoizedChoices = 1 << 16;
  bool memoize_ = false;
  mutable std::unordered_map<std::string, int> choices_;
  mutable std::string choice_key_;
  // expected_entropy_grouped()'s tables and scratch (empty below kLargeAbove).
  int num_groups_ = 0;              // the terminal actions
  std::vector<int> group_of_live_;  // [l]: best_terminal_[l]'s group, or -1 (no terminal action)
  std::vector<int> sensing_index_;  // [a]: a's index in sensing_, or -1
  // [(i * L + l) * O + o]: emission(sensing_[i], o)[l] (emptied when sparse_ takes over).
  std::vector<double> emission_by_state_;
  // The same sum on tables whose rows are mostly one value, when they are.
  std::unique_ptr<const SparseGroupedEntropy> sparse_;
  bool prune_ = false;  // expect_sparse may prune (every sensing row a distribution)
  mutable std::vector<double> expected_;                       // by sensing index
  mutable std::vector<std::pair<double, std::size_t>> order_;  // (bound, sensing index)
  mutable std::vector<double> live_belief_, grouped_, totals_;
};

}  // namespace echoplan::solvers
