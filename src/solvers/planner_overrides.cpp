#include "solvers/planner_overrides.h"

namespace echoplan::solvers {

SearchOptions search_options(const PlannerOverrides& f, const pomdp::Problem& problem) {
  SearchOptions o;
  o.exploration = f.exploration >= 0 ? f.exploration : problem.planner.exploration;
  o.max_depth = f.depth >= 0 ? f.depth : problem.planner.depth;
  const std::string& solver = f.solver.empty() ? problem.planner.solver : f.solver;
  if (!f.leaf.empty())
    o.leaf.mode = parse_leaf_mode(f.leaf);
  else if (problem.model)
    o.leaf.mode = default_leaf_mode(solver, *problem.model);
  if (!f.unheard.empty()) o.unheard = parse_unheard_outcomes(f.unheard);
  o.leaf.expand_after = f.expand_after;
  o.leaf.exact_share = f.exact_share;
  o.leaf.offline_expansions = f.offline_expansions;
  o.root_particles = f.root_particles >= 0 ? f.root_particles : problem.belief.particles;
  o.branching.continuous_threshold = f.branch_threshold;
  o.validate();
  return o;
}

Budget budget(const PlannerOverrides& f, const pomdp::Problem& problem) {
  if (f.episodes > 0) return Budget::episodes(f.episodes);
  if (f.step_ms > 0) return Budget::milliseconds(f.step_ms);
  if (problem.planner.episodes > 0) return Budget::episodes(problem.planner.episodes);
  return Budget::milliseconds(static_cast<std::int64_t>(problem.planner.step_ms));
}

}  // namespace echoplan::solvers
