// The policy leaf's expected decision entropy (sensing_policy.h) on tables whose rows are mostly
// one value: a state's row of P(o | s, a) is a base value on every outcome plus a few exceptions.
// The sessions recipe's tables are so (docs/feature-sets.md: counts from a few held-out sessions
// shrunk towards a flat row; about 7 exceptions in 100 outcomes). Then
//   g[k][o] = Σ_{s in group k} b(s) P(o | s, a) = C[k] + Σ_{s in k, o exceptional for s} b(s) d(s,
//   o)
// with C[k] = Σ_{s in k} b(s) base(s) and d = P − base: a group's row is C[k] except on the union
// of its states' exceptions, so Σ_o g log g needs a log there only. The cost of one action falls
// from states x outcomes multiply-adds and groups x outcomes logs to states x exceptions
// multiply-adds and the unions' sizes in logs.
#pragma once

#include <cstddef>
#include <vector>

namespace echoplan::solvers {

class SparseGroupedEntropy {
 public:
  // `emission_by_state[(i * live + l) * outcomes + o]` = P(o | l, sensing action i);
  // `group_of_live[l]` in [0, groups): the state's decision group.
  SparseGroupedEntropy(const std::vector<double>& emission_by_state, int sensing_actions, int live,
                       int outcomes, int groups, const std::vector<int>& group_of_live);

  // The exceptions per state and action, on average (the caller keeps its dense sum when this is
  // not much smaller than the outcomes).
  double mean_exceptions() const;
  // Σ_o P(o) H(group | o) after sensing action i at the live belief b (b[l], summing to at most
  // 1), as Σ_o T[o] log T[o] − Σ_{k,o} g[k][o] log g[k][o] with T[o] = Σ_k g[k][o].
  double expected_entropy(int i, const double* b) const;

 private:
  struct Exception {
    int slot;      // g[k][o]'s place in the action's buffer of its groups' unions
    double delta;  // P(o | s, a) − base(s)
  };
  void add_action(const double* rows);

  int outcomes_ = 0, groups_ = 0, live_ = 0;
  std::vector<int> group_of_live_;
  std::vector<double> base_;            // [i * live + l]: the row's most frequent value
  std::vector<std::size_t> first_;      // [i * live + l]: its first exception; one more at the end
  std::vector<Exception> exceptions_;   // by action, then state
  std::vector<int> union_begin_;        // [i * (groups + 1) + k]: group k's first slot in action i
  std::vector<std::size_t> slot_base_;  // [i]: where action i's slots start in the two below
  std::vector<int> slot_outcome_, slot_group_;  // [slot_base_[i] + slot]: its o and its k
  mutable std::vector<double> constant_, slots_, totals_;
};

}  // namespace echoplan::solvers
