// The policy leaf's expected decision entropy (sensing_policy.h) on tables whose rows are mostly
// one value: a state's row of P(o | s, a) is a base value on every outcome plus a few exceptions.
// The shrunk tables of a feature set's fit are so (docs/feature-sets.md: counts from a few held-out
// sessions shrunk towards a flat row; about 7 exceptions in 100 outcomes). Then
//   g[k][o] = Σ_{s in group k} b(s) P(o | s, a) = C[k] + Σ_{s in k} b(s) d(s, o)
// with C[k] = Σ_{s in k} b(s) base(s) and d = P − base, 0 but on the state's exceptions: a group's
// row is C[k] except on the union of its states' exceptions, so Σ_o g log g needs a log there only.
// The deltas are kept as one small dense block per group (its states x its union), so the sum is a
// few vectorised multiply-adds rather than scattered ones; a delta of 0 adds an exact 0, so each
// g[k][o] is the same sum in the same order as over the exceptions alone. The cost of one action
// falls from states x outcomes multiply-adds and groups x outcomes logs to the blocks' sizes in
// multiply-adds and the unions' sizes in logs.
//
// Graded tables (docs/perception.md) have one base value per grade rather than per row: a class
// heard wrongly at grade g has P(h | s) P(g | wrong), the same for every wrong class h. So the
// outcomes of each action are first split into classes whose cells agree in most rows (each at
// least an eighth of the outcomes; the grades, or all outcomes of a label table), and each row has
// a base value per class: C[k] becomes C[k][class], and everything above holds class by class. A
// label table is one class, summed exactly as before classes existed.
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
  // 1), as Σ_o T[o] log T[o] − Σ_{k,o} g[k][o] log g[k][o] with T[o] = Σ_k g[k][o]:
  // set_belief(b), then outcome_term(i) − group_term(i).
  double expected_entropy(int i, const double* b) const;
  // Takes the live belief b for the terms below (once for every action at that belief), and
  // finds the group it gives the most mass.
  void set_belief(const double* b) const;
  // Σ_o T[o] log T[o] for action i; keeps action i's g[k][o] for group_term(i).
  double outcome_term(int i) const;
  // Σ_{k,o} g[k][o] log g[k][o] for action i, after outcome_term(i) at the same belief.
  double group_term(int i) const;
  // Σ_l b[l] Σ_o P(o | l, i) log P(o | l, i): with outcome_term, the information about the state,
  // I(state; o) = state_term − outcome_term (for b summing to 1).
  double state_term(int i) const;
  // What group_term(i) is below its upper bound Σ_k (m_k log m_k + Σ_{l in k} b[l] Σ_o P log P)
  // (the entropy of a mixture is at least the mixture of the entropies) on the group with the
  // most mass, where most of the bound's slack usually is: ≥ 0, after outcome_term(i). With it,
  // the policy's lower bound on the expected entropy rises by that much, at the cost of one
  // group's logs.
  double top_group_slack(int i) const;

 private:
  void add_action(const double* rows);
  // Σ_o g[k][o] log g[k][o] of group k for action i, after outcome_term(i).
  double one_group_term(int i, int k) const;
  // Its part off the group's union, where g[k][o] = C[k][c] for o of class c: the sum over classes
  // of (c's outcomes off the union) C log C.
  double off_union_term(int i, int k) const;
  // Where action i's quantities by (group, class) are: [(i * groups + k) * kMaxClasses + c].
  std::size_t at(int i, int k, int c) const {
    return (static_cast<std::size_t>(i) * groups_ + k) * kMaxClasses + c;
  }

  // Outcome classes beyond this many fold into the largest (their cells become exceptions).
  static constexpr int kMaxClasses = 4;

  int outcomes_ = 0, groups_ = 0, live_ = 0;
  std::vector<int> members_;       // the live states by group, in order within each
  std::vector<int> member_begin_;  // [k]: group k's first place in members_; one more at the end
  std::vector<int> classes_;       // [i]: action i's outcome classes
  std::vector<int> class_of_;      // [i * outcomes + o]: outcome o's class in action i
  // [(i * members + r) * kMaxClasses + c]: members_[r]'s row's most frequent value on class c
  std::vector<double> base_;
  std::size_t exceptions_ = 0;    // outcomes off their row's base value, over every row
  std::vector<int> union_begin_;  // [i * (groups + 1) + k]: group k's first slot in action i
  // [at(i, k, c)]: the first slot of group k's union on class c (a group's slots are by class, then
  // outcome), and how many outcomes of class c are off the union.
  std::vector<int> segment_begin_, off_union_;
  std::vector<std::size_t> slot_base_;  // [i]: action i's first place in slots_; one more
  std::vector<double> row_x_log_x_;     // [i * live + r]: Σ_o P log P over members_[r]'s row
  // [block_begin_[at(i, k, c)] + r * width + j]: d(members_[member_begin_[k] + r], the outcome of
  // the class's slot j), width the class's slots in the group's union.
  std::vector<std::size_t> block_begin_;
  std::vector<double> blocks_;
  std::vector<int> slot_outcome_;  // [slot_base_[i] + s]: the outcome of action i's slot s
  // C[at(i, k, c)] and g[k][o] by action and slot (slot_base_), kept for group_term; then T[o]
  // and b by member, for one call.
  mutable std::vector<double> constant_, slots_, totals_, member_belief_;
  mutable int top_group_ = 0;  // the group with the most mass at the belief (the first of those)
  mutable double top_mass_ = 0.0;
};

}  // namespace echoplan::solvers
