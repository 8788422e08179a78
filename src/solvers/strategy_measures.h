// The numbers the baseline strategies decide by (baseline_strategies.h): a sensing action's
// held-out accuracy (best_single) and, at a belief over the objects, the value of committing now,
// of sensing once and then committing, and the expected entropy reduction (information_gain).
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

}  // namespace echoplan::solvers
