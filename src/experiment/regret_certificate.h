// How far a logged run's decisions were from optimal, measured exactly: the regret certificate
// behind `echoplan certify`.
//
// For an identification problem (solvers/identification_solver.h), each logged decision's loss is
//   V*(b_t) − Q*(b_t, a_t) ≥ 0
// at the exact belief b_t recomputed from the trial's action/observation history (the belief the
// log holds is not trusted: a particle filter's is approximate). By the performance-difference
// identity, the discounted sum of losses along a trial, plus γ^T V*(b_T) when the trial was cut
// short before ending, has expectation V*(b0) − V^planner(b0), with far less variance than the
// returns themselves. V* and Q* come as bounds from the exact solver, refined at every visited
// belief to `decision_gap`; the per-trial regret reported is the upper end, so the certified share
// of V* errs on the planner's side only by sampling, never by bounds. The upper end of a loss is
//   max(0, min(U_V, max over a' != a_t of U_Q(a')) − L_Q(a_t)),
// since V* − Q*(a_t) = max(0, max_{a' != a_t} Q*(a') − Q*(a_t)): a decision the bounds prove
// optimal loses 0 however loose V*'s bounds are (with U_V alone every decision would be charged
// its bounds' gap).
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "common/statistics.h"
#include "experiment/trial_log.h"
#include "solvers/identification_solver.h"

namespace echoplan::experiment {

struct CertifyOptions {
  double decision_gap = 1e-3;  // absolute target gap of V* and Q* at every visited belief
  // Refinement limit per belief and per bound, in node expansions (a count, so results repeat);
  // bounds stay valid when it is hit, the regret then counts the remaining gap against the run.
  long expansions_per_belief = 20000;
  // Refinement at b0 before the trials, in node expansions: every logged belief is a descendant of
  // b0, so this work (memoised) tightens the bounds the decisions are judged by.
  long root_expansions = 1000000;
  int worst = 10;  // how many of the largest single losses to list
};

// One decision with its loss (undiscounted) and where it happened.
struct DecisionLoss {
  int trial = 0;
  int step = 0;
  int line = 0;  // in steps.csv
  int action = 0;
  int best_action = 0;         // the action with the highest lower bound on Q* there
  double loss = 0.0;           // upper end: min(V*_upper, best rival's Q*_upper) − Q*_lower, >= 0
  double loss_lower = 0.0;     // lower end: V*_lower − Q*_upper, at least 0
  std::vector<double> belief;  // exact belief over the model's states
};

struct TrialRegret {
  int trial = 0;
  double regret = 0.0;        // Σ γ^t loss_t (+ γ^T V*_upper(b_T) when cut short)
  double regret_lower = 0.0;  // the same from the lower ends
  // The certificate's own looseness on this trial: Σ γ^t (loss − loss_lower) (+ γ^T gap of
  // V*(b_T) when cut short) = regret − regret_lower.
  double bound_gap = 0.0;
  bool ended = false;  // a terminal action (or a collision) ended the trial
};

struct Certificate {
  solvers::Bounds vstar;  // V*(b0), as tight as the whole certification left it
  std::vector<TrialRegret> trials;
  MeanInterval regret;             // over trials, of TrialRegret::regret
  double regret_lower_mean = 0.0;  // mean of TrialRegret::regret_lower
  double bound_gap_mean = 0.0;     // mean of TrialRegret::bound_gap: what the bounds add to regret
  int decisions = 0;
  int unconverged_beliefs = 0;      // beliefs whose bounds missed decision_gap (still valid)
  std::vector<DecisionLoss> worst;  // largest losses first
  // Share of V*(b0) the planner is certified to reach: share_of_vstar(vstar, regret.mean).
  double share_of_vstar() const;
};

// 1 − regret / |V*|, V* at the midpoint of its bounds (0 when V* is 0): the share of V* an arm with
// that regret reaches, below 1 by the regret's share of V*'s size whatever V*'s sign (a task that
// costs more than it earns has V* < 0, and 1 − regret / V* would exceed 1).
double share_of_vstar(const solvers::Bounds& vstar, double regret);

// Certifies `trials` (read from steps.csv) against the exact solver's bounds. With use limits in
// the solver's tables, each decision is bounded at the node the trial's earlier steps reach, whose
// counts are the uses so far: V* and the rivals' Q* there exclude the actions already used up.
// Throws InputError naming the steps.csv line of a history the model cannot produce (an
// observation impossible after the logged history, a step after the episode ended, an action past
// its use limit).
Certificate certify_trials(solvers::IdentificationSolver& solver,
                           const std::vector<LoggedTrial>& trials, const CertifyOptions& options,
                           const std::string& steps_file);

// The certificate's figures as `echoplan certify --json` prints them: vstar_lower, vstar_upper,
// regret_mean, regret_ci95, trials, regret_lower_mean, bound_gap_mean, share_of_vstar, decisions,
// unconverged_beliefs (the worst decisions are left out).
nlohmann::ordered_json to_json(const Certificate& certificate);

}  // namespace echoplan::experiment
