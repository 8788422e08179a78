#include "experiment/regret_certificate.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"

namespace echoplan::experiment {

double share_of_vstar(const solvers::Bounds& vstar, double regret) {
  const double v = 0.5 * (vstar.lower + vstar.upper);
  return v != 0.0 ? 1.0 - regret / std::abs(v) : 0.0;
}

double Certificate::share_of_vstar() const {
  return experiment::share_of_vstar(vstar, regret.mean);
}

namespace {

// An upper bound on max over a' != action of Q*(b, a') at `node`: V*(b) - Q*(b, action) =
// max(0, that - Q*(b, action)), so when the action taken is the best one this bound, not V*'s
// upper end, is what its loss is measured against (a decision proven optimal loses 0, however
// loose V*'s own bounds are). The rival with the highest upper bound is refined while it still
// overlaps `taken_lower`.
double best_rival_upper(solvers::IdentificationSolver& solver,
                        solvers::IdentificationSolver::NodeId node, int action, double taken_lower,
                        const solvers::RefineLimits& limits) {
  auto rival = [&](int* which) {
    double best = -std::numeric_limits<double>::infinity();
    for (int a = 0; a < solver.num_actions(); ++a)
      if (a != action && solver.action_value(node, a).upper > best)
        best = solver.action_value(node, a).upper, *which = a;
    return best;
  };
  int which = -1;
  const double before = rival(&which);
  if (which < 0 || before <= taken_lower) return before;
  solver.refine_action(node, which, limits);
  return rival(&which);
}

}  // namespace

namespace {

using NodeId = solvers::IdentificationSolver::NodeId;

// A decision's loss with its node, to list the worst at the end.
struct Visited {
  DecisionLoss loss;
  NodeId node;
};

// The loss of taking `step`'s action at `node` (bounded by refining there); counts beliefs whose
// bounds missed the target in `unconverged`. InputError for an action past its use limit.
DecisionLoss judge_decision(solvers::IdentificationSolver& solver, NodeId node, int trial,
                            const LoggedStep& step, const solvers::RefineLimits& limits,
                            const std::string& steps_file, int& unconverged) {
  if (!solver.available(node, step.action))
    throw InputError(steps_file, step.line,
                     fmt::format("trial {} takes action {} more often than the problem's use "
                                 "limit allows",
                                 trial, step.action));
  if (!solver.refine(node, limits)) ++unconverged;
  if (!solver.refine_action(node, step.action, limits)) ++unconverged;
  const solvers::Bounds v = solver.value(node);
  const solvers::Bounds q = solver.action_value(node, step.action);
  DecisionLoss d;
  d.trial = trial;
  d.step = step.step;
  d.line = step.line;
  d.action = step.action;
  d.loss = std::max(
      0.0,
      std::min(v.upper, best_rival_upper(solver, node, step.action, q.lower, limits)) - q.lower);
  d.loss_lower = std::max(0.0, v.lower - q.upper);
  return d;
}

// The `count` largest losses, each with the action that was best at its belief.
std::vector<DecisionLoss> worst_decisions(solvers::IdentificationSolver& solver,
                                          std::vector<Visited> visited, int count,
                                          const solvers::RefineLimits& limits) {
  std::sort(visited.begin(), visited.end(),
            [](const Visited& a, const Visited& b) { return a.loss.loss > b.loss.loss; });
  const std::size_t n = std::min<std::size_t>(visited.size(), std::max(0, count));
  std::vector<DecisionLoss> worst;
  for (std::size_t i = 0; i < n; ++i) {
    Visited& w = visited[i];
    double best = -1e300;
    for (int a = 0; a < solver.num_actions(); ++a) {
      solver.refine_action(w.node, a, limits);
      const double lower = solver.action_value(w.node, a).lower;
      if (lower > best) best = lower, w.loss.best_action = a;
    }
    w.loss.belief = solver.belief(w.node);
    worst.push_back(w.loss);
  }
  return worst;
}

}  // namespace

Certificate certify_trials(solvers::IdentificationSolver& solver,
                           const std::vector<LoggedTrial>& trials, const CertifyOptions& options,
                           const std::string& steps_file) {
  solvers::RefineLimits limits;
  limits.target_gap = options.decision_gap;
  limits.expansions = options.expansions_per_belief;

  Certificate c;
  solvers::RefineLimits root_limits = limits;
  root_limits.expansions = std::max(options.root_expansions, options.expansions_per_belief);
  if (!solver.refine(solver.root(), root_limits)) ++c.unconverged_beliefs;
  const double gamma = solver.discount();
  std::vector<double> regrets;
  std::vector<Visited> visited;

  for (const LoggedTrial& trial : trials) {
    TrialRegret r;
    r.trial = trial.trial;
    NodeId node = solver.root();
    double weight = 1.0;  // γ^t
    for (const LoggedStep& step : trial.steps) {
      if (r.ended)
        throw InputError(steps_file, step.line,
                         fmt::format("trial {} goes on after its episode ended", trial.trial));
      const DecisionLoss d = judge_decision(solver, node, trial.trial, step, limits, steps_file,
                                            c.unconverged_beliefs);
      r.regret += weight * d.loss;
      r.regret_lower += weight * d.loss_lower;
      r.bound_gap += weight * (d.loss - d.loss_lower);
      visited.push_back({d, node});
      ++c.decisions;
      weight *= gamma;
      if (solver.is_terminal_action(step.action)) {
        r.ended = true;
        continue;
      }
      const NodeId next = solver.child(node, step.action, step.observation);
      if (next == solvers::IdentificationSolver::kEnded) {
        // Heard only when the episode ends (a collision's "none"); impossible otherwise.
        if (&step != &trial.steps.back())
          throw InputError(steps_file, step.line,
                           fmt::format("trial {}: this observation cannot follow the logged "
                                       "history under the problem's model",
                                       trial.trial));
        r.ended = true;
        continue;
      }
      node = next;
    }
    if (!r.ended) {
      // Cut short (step cap): the value the planner never collected is part of its regret.
      if (!solver.refine(node, limits)) ++c.unconverged_beliefs;
      r.regret += weight * solver.value(node).upper;
      r.regret_lower += weight * solver.value(node).lower;
      r.bound_gap += weight * solver.value(node).gap();  // the cut-short term's looseness
    }
    regrets.push_back(r.regret);
    c.regret_lower_mean += r.regret_lower / static_cast<double>(trials.size());
    c.bound_gap_mean += r.bound_gap / static_cast<double>(trials.size());
    c.trials.push_back(r);
  }
  c.regret = mean_ci95(regrets);
  c.vstar = solver.value(solver.root());
  c.worst = worst_decisions(solver, std::move(visited), options.worst, limits);
  return c;
}

nlohmann::ordered_json to_json(const Certificate& c) {
  nlohmann::ordered_json out;
  out["vstar_lower"] = c.vstar.lower;
  out["vstar_upper"] = c.vstar.upper;
  out["regret_mean"] = c.regret.mean;
  out["regret_ci95"] = c.regret.half_width;
  out["trials"] = c.regret.n;
  out["regret_lower_mean"] = c.regret_lower_mean;
  out["bound_gap_mean"] = c.bound_gap_mean;
  out["share_of_vstar"] = c.share_of_vstar();
  out["decisions"] = c.decisions;
  out["unconverged_beliefs"] = c.unconverged_beliefs;
  return out;
}

}  // namespace echoplan::experiment
