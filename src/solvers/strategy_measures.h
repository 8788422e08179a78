// The numbers the baseline strategies decide by (baseline_strategies.h): a sensing action's
// held-out accuracy (best_single) and, at a belief over the objects, the value of committing now,
// of sensing once and then committing, the expected entropy reduction (information_gain) and the
// expected edge mass a performance removes between decision regions (decision_region).
#pragma once

#include <vector>

#include "pomdp/object_identification_model.h"
#include "solvers/sensing_policy.h"

namespace echoplan::solvers {

// How often one performance of sensing action `a` names the object, read off the problem's
// observation table (which is the classifier's held-out confusion):
//   accuracy_a = Σ_k prior_k P(symbol named like object k | k, a).
// An object with no symbol of its name counts as never named. When no symbol is named like any
// object (the classifier reports something else, e.g. groups), the table is read as what a reader
// of one symbol would get right by Bayes' rule instead: Σ_o max_k prior_k P(o | k, a).
double held_out_accuracy(const pomdp::ObjectProblemData& data, int a);

// What one performance of sensing action `a` is worth before anything is heard, cost included:
// sense once (reward r_a, the action's reward per use) and sort by what was heard, right as often
// as held_out_accuracy() says:
//   value_a = r_a + γ (accuracy_a R_right + (1 − accuracy_a) R_wrong),
// R_right = Σ_k prior_k max_j sorting_reward[j][k] (the right bin), R_wrong the same with min_j (a
// wrong bin; a mistake that lands in the right bin anyway is counted as wrong, so the value is a
// lower bound). With equal costs it orders actions as their accuracy does (best_single's choice
// before costs existed); a costly action must be that much more accurate to be worth it.
double single_action_value(const pomdp::ObjectProblemData& data, int a);

// One-step lookahead at a belief b over the objects (b(k), k < K), by the problem's tables: the
// same Bayes rule and rewards as ABT's default sensing policy (sensing_policy.h), so a sensing
// action's reward counts its collisions, (1-p) r_a + p r_collision, and a collision ends the
// episode. Not thread-safe (one per strategy).
class OneStepLookahead {
 public:
  explicit OneStepLookahead(const pomdp::ObjectIdentificationModel& model);

  // Σ_k b(k) R(k, a).
  double expected_reward(const std::vector<double>& objects, int action) const;
  // max_j Σ_k b(k) sorting_reward[j][k]: the value of committing now.
  double commit_value(const std::vector<double>& objects) const;
  // R(b, a) + γ Σ_o P(o, no collision | b, a) max_j E[sorting_reward[j] | b_ao]: sense with `a`
  // once, then commit.
  double sense_then_commit_value(const std::vector<double>& objects, int a) const;
  // H(b) − Σ_o P(o | b, a, no collision) H(b_ao), in nats: what one performance of `a` is expected
  // to tell about the object (0 when `a` always collides).
  double expected_entropy_reduction(const std::vector<double>& objects, int a) const;

 private:
  std::vector<double> states(const std::vector<double>& objects) const;  // + 'done' at 0

  SensingPolicy tables_;
  int num_observations_;
  double discount_;
  mutable std::vector<double> after_;
};

// Each object's decision region: the bin it belongs in, argmax_j sorting_reward[j][k], the first
// such j on ties (an object two bins suit equally goes to the first one's region, so the
// edge-cutting rule may pay to tell it from objects of the other bin though sorting to that bin
// would be right for both: Javdani et al.'s overlapping regions, which this does not model). j in
// [0, J).
std::vector<int> decision_regions(const pomdp::ObjectProblemData& data);

// The equivalence-class edge-cutting measure of decision_region (baseline_strategies.h), with
// ECED's discounting of noisy outcomes (Chen, Hassani & Krause 2017). Regions are
// decision_regions(); an edge joins two objects of different regions with weight b(k) b(k'). After
// symbol o of sensing action a, ECED multiplies every edge by λ_a(o|k) λ_a(o|k'), with
//   λ_a(o|k) = P(o | k, a) / max_o' P(o' | k, a)   (how consistent o is with k; 1 for k's likeliest
//                                                    symbol, 0 when k never makes o),
// and counts only what exceeds the discount every edge gets from o anyway, m_a(o)² with
// m_a(o) = max_k λ_a(o|k) over all the problem's objects. So
//   expected_cut(b, a) = Σ_o P(o | b, a) Σ_{k<k', r(k)≠r(k')} b(k) b(k') (m_a(o)² − λ_a(o|k)
//   λ_a(o|k'))
// (P(o | b, a) = Σ_k b(k) P(o | k, a): collisions are object-independent, so what is heard when
// none happens is the table's row; 0 for an action that always collides). It is ≥ 0, 0 for an
// action whose rows are all alike (pure noise: the plain soft cut λ = P would count it as cutting,
// ECED's Sec. 3 counterexample), and with 0/1 rows (noise-free) exactly EC2's expected cut
// (Golovin, Krause & Ray 2010). ECED tracks unnormalised weights P0(k) P0(k') Π P(o|k) P(o|k'),
// which are Z² b(k) b(k') for the evidence's probability Z: one factor for every action at a
// belief, so ranking by the normalised belief picks what ECED picks. Not thread-safe (scratch
// space; one per strategy).
class EdgeCut {
 public:
  explicit EdgeCut(const pomdp::ObjectProblemData& data);

  // Σ_{k<k', r(k)≠r(k')} b(k) b(k'): the edge mass still to cut.
  double edge_mass(const std::vector<double>& objects) const;
  double expected_cut(const std::vector<double>& objects, int a) const;

 private:
  // Σ over edges of w(k) w(k'), by region sums: (Σ w)² − Σ_j (Σ_{r(k)=j} w)², halved.
  double cross_mass(const std::vector<double>& w) const;

  std::vector<int> region_;
  int num_regions_ = 0, num_symbols_ = 0;
  std::vector<std::vector<double>> table_;        // [a][k * C + o]: P(o | k, a)
  std::vector<std::vector<double>> consistency_;  // [a][k * C + o]: λ_a(o|k)
  std::vector<std::vector<double>> offset_;       // [a][o]: m_a(o)²
  std::vector<bool> always_collides_;             // [a]
  mutable std::vector<double> weighted_, region_sum_;
};

}  // namespace echoplan::solvers
