// `echoplan solve`: bounds on the optimal value V*(b0) of a discrete problem, from the exact
// identification solver when the problem has that shape, else from the offline point-based solver
// (which can also save its policy, alpha vectors, for later runs).
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "common/error.h"
#include "pomdp/problem.h"
#include "solvers/identification_solver.h"
#include "solvers/offline/flat_pomdp.h"
#include "solvers/offline/point_based_solver.h"
#include "solvers/offline/policy_file.h"

namespace echoplan::cli {

namespace {

struct SolveArgs {
  std::string problem;
  bool json = false;
  double epsilon = 1e-4;
  double time_limit = 60.0;
  std::uint64_t seed = 1;
  long max_expansions = 0;  // exact solver: node expansions; 0: no limit
  long max_trials = 0;      // point-based solver: trials; 0: no limit
  long max_iterations = 0;  // deprecated --max-iterations: both of the above, unless they are set
  std::string method = "auto";
  std::string out;
  std::string exact_search = "passes";
  std::string exact_frontier = "full";
  std::string pair_relaxation = "on";
  std::string sense_once = "on";
  std::string readings_left = "on";
  int readings_left_budget = solvers::ReadingsLeftOptions{}.budget;
  int readings_left_max = solvers::ReadingsLeftOptions{}.max_readings;
  double frontier_margin = solvers::IdentificationOptions{}.frontier_margin;
  std::size_t frontier_entries = solvers::IdentificationOptions{}.max_frontier_entries;
  std::size_t frontier_plans = solvers::IdentificationOptions{}.max_frontier_plans;
  double expand_within = solvers::IdentificationOptions{}.expand_within;
};

solvers::IdentificationOptions exact_options(const SolveArgs& args) {
  solvers::IdentificationOptions options;
  options.search = args.exact_search == "passes" ? solvers::IdentificationOptions::Search::passes
                                                 : solvers::IdentificationOptions::Search::trials;
  options.plan_lower_bound = args.exact_frontier == "full" || args.exact_frontier == "plans";
  options.sawtooth_upper_bound = args.exact_frontier == "full" || args.exact_frontier == "sawtooth";
  options.pair_upper_bound = args.pair_relaxation == "on";
  options.sense_once_lower_bound = args.sense_once == "on";
  options.readings_left_upper_bound = args.readings_left == "on";
  options.readings_left.budget = args.readings_left_budget;
  options.readings_left.max_readings = args.readings_left_max;
  options.frontier_margin = args.frontier_margin;
  options.max_frontier_entries = args.frontier_entries;
  options.max_frontier_plans = args.frontier_plans;
  options.expand_within = args.expand_within;
  return options;
}

std::string action_label(const pomdp::Problem& problem, int a) {
  const auto& names = problem.model->spec().action_names;
  return a < static_cast<int>(names.size()) ? names[a] : std::to_string(a);
}

// The exact identification solver: refines V*(b0) in one-second slices (for progress), then the
// Q-value of every action at b0 to the same gap.
void run_exact(const SolveArgs& args, const pomdp::Problem& problem,
               const pomdp::TabularModel& tables) {
  // The clock starts before the solver is made: its setup (the two-state sub-problems) counts.
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  // With the problem's use limits (pomdp::Model::max_uses), which the tables alone do not hold.
  solvers::IdentificationSolver solver(
      solvers::read_identification_tables(tables, solvers::UseLimits(*problem.model)),
      exact_options(args));
  const double setup_seconds = elapsed();
  const auto root = solver.root();
  auto target = [&](solvers::Bounds b) {
    return args.epsilon * std::max({1.0, std::abs(b.lower), std::abs(b.upper)});
  };
  spdlog::info(
      "solving {} exactly over count vectors (epsilon {}, time limit {} s{}); setup {:.2f} s, "
      "{} two-state sub-problems",
      args.problem, args.epsilon, args.time_limit,
      args.max_expansions > 0 ? fmt::format(", at most {} expansions", args.max_expansions) : "",
      setup_seconds, solver.num_relaxation_pairs());
  for (;;) {
    const double remaining = args.time_limit - elapsed();
    const long expansions_left =
        args.max_expansions > 0 ? args.max_expansions - solver.expansions() : 0;
    if (remaining <= 0.0 || (args.max_expansions > 0 && expansions_left <= 0)) break;
    solvers::RefineLimits limits;
    limits.target_gap = target(solver.value(root));
    limits.seconds = std::min(1.0, remaining);
    limits.expansions = expansions_left;
    const double slice_start = elapsed();
    const bool reached = solver.refine(root, limits);
    const solvers::Bounds v = solver.value(root);
    spdlog::info(
        "{:7.1f} s  expansions {:8}  V* in [{:.6f}, {:.6f}]  gap {:.3g}  nodes {}  plans {}  "
        "points {}",
        elapsed(), solver.expansions(), v.lower, v.upper, v.gap(), solver.num_nodes(),
        solver.num_plans(), solver.num_upper_points());
    // The relative target shrinks with |V| as the bounds close in: check it again.
    if (reached && v.gap() <= target(v)) break;
    // Otherwise go on only when the slice ran out of time (not stalled, not at the node cap).
    if (!reached && elapsed() - slice_start < limits.seconds) break;
  }
  const solvers::Bounds v = solver.value(root);
  const bool converged = v.gap() <= target(v);
  const double root_seconds = elapsed();
  const long root_expansions = solver.expansions();
  std::vector<solvers::Bounds> q(solver.num_actions());
  for (int a = 0; a < solver.num_actions(); ++a) {
    solvers::RefineLimits limits;
    limits.target_gap = target(v);
    limits.seconds = std::max(0.1, args.time_limit - elapsed());
    limits.expansions = args.max_expansions;  // per action, so that the figures repeat too
    solver.refine_action(root, a, limits);
    q[a] = solver.action_value(root, a);
  }
  int best = 0;
  for (int a = 1; a < solver.num_actions(); ++a)
    if (q[a].lower > q[best].lower) best = a;
  const double seconds = elapsed();

  if (args.json) {
    nlohmann::ordered_json out;
    out["method"] = "exact";
    out["lower"] = v.lower;
    out["upper"] = v.upper;
    out["gap"] = v.gap();
    out["target_gap"] = target(v);
    out["converged"] = converged;
    out["expansions"] = solver.expansions();
    out["root_expansions"] = root_expansions;  // before the per-action refinement
    out["root_seconds"] = root_seconds;
    out["nodes"] = solver.num_nodes();
    out["plans"] = solver.num_plans();
    out["upper_points"] = solver.num_upper_points();
    out["relaxation_pairs"] = solver.num_relaxation_pairs();
    out["setup_seconds"] = setup_seconds;
    out["seconds"] = seconds;
    out["best_action"] = action_label(problem, best);
    nlohmann::ordered_json actions = nlohmann::ordered_json::object();
    for (int a = 0; a < solver.num_actions(); ++a)
      actions[action_label(problem, a)] = {{"lower", q[a].lower}, {"upper", q[a].upper}};
    out["actions"] = std::move(actions);
    fmt::print("{}\n", out.dump());
    return;
  }
  fmt::print("V*(b0) of {} (exact identification solver)\n", args.problem);
  fmt::print("  lower {:.6f}\n  upper {:.6f}\n  gap   {:.3g} ({} target {:.3g})\n", v.lower,
             v.upper, v.gap(), converged ? "reached" : "NOT reached:", target(v));
  fmt::print("  {} expansions in {:.2f} s, {} belief nodes, {} plans, {} upper-bound points\n",
             solver.expansions(), seconds, solver.num_nodes(), solver.num_plans(),
             solver.num_upper_points());
  fmt::print("first action: {} (Q* bounds per action at b0:", action_label(problem, best));
  for (int a = 0; a < solver.num_actions(); ++a)
    fmt::print(" {} [{:.4f}, {:.4f}]", action_label(problem, a), q[a].lower, q[a].upper);
  fmt::print(")\n");
}

// `given` with the deprecated --max-iterations standing in for --max-expansions and --max-trials
// where they were not set (it meant expansions for the exact solver and trials for the other).
SolveArgs with_iteration_alias(const SolveArgs& given) {
  if (given.max_iterations < 0) throw InputError("--max-iterations must be >= 0 (0: no limit)");
  if (given.max_expansions < 0) throw InputError("--max-expansions must be >= 0 (0: no limit)");
  if (given.max_trials < 0) throw InputError("--max-trials must be >= 0 (0: no limit)");
  SolveArgs args = given;
  if (args.max_expansions == 0) args.max_expansions = given.max_iterations;
  if (args.max_trials == 0) args.max_trials = given.max_iterations;
  return args;
}

// The point-based solver's result at b0: its bounds, the best first action and every action's Q*
// bounds, as JSON or text.
void print_point_based(const SolveArgs& args, const pomdp::Problem& problem,
                       const solvers::offline::PointBasedSolver& solver,
                       const solvers::offline::SolverProgress& result,
                       const solvers::BeliefVector& b0) {
  const auto& action_names = problem.model->spec().action_names;
  auto action_name = [&](int a) {
    return a < static_cast<int>(action_names.size()) ? action_names[a] : std::to_string(a);
  };
  const int best = solver.best_action(b0);
  const std::vector<solvers::Bounds> q = solver.action_bounds(b0);
  if (args.json) {
    nlohmann::ordered_json out;
    out["lower"] = result.root.lower;
    out["upper"] = result.root.upper;
    out["gap"] = result.root.upper - result.root.lower;
    out["target_gap"] = result.target_gap;
    out["converged"] = result.converged;
    out["trials"] = result.trials;
    out["seconds"] = result.seconds;
    out["best_action"] = action_name(best);
    nlohmann::ordered_json actions = nlohmann::ordered_json::object();
    for (int a = 0; a < static_cast<int>(q.size()); ++a) {
      actions[action_name(a)] = {{"lower", q[a].lower}, {"upper", q[a].upper}};
    }
    out["actions"] = std::move(actions);
    fmt::print("{}\n", out.dump());
    return;
  }
  fmt::print("V*(b0) of {}\n", args.problem);
  fmt::print("  lower {:.6f}\n  upper {:.6f}\n  gap   {:.3g} ({} target {:.3g})\n",
             result.root.lower, result.root.upper, result.root.upper - result.root.lower,
             result.converged ? "reached" : "NOT reached:", result.target_gap);
  fmt::print("  {} trials in {:.2f} s, {} alpha vectors, {} upper-bound points\n", result.trials,
             result.seconds, result.alpha_vectors, result.upper_points);
  fmt::print("first action: {} (Q* bounds per action at b0:", action_name(best));
  for (int a = 0; a < static_cast<int>(q.size()); ++a) {
    fmt::print(" {} [{:.4f}, {:.4f}]", action_name(a), q[a].lower, q[a].upper);
  }
  fmt::print(")\n");
  if (!args.out.empty()) fmt::print("policy written to {}/policy.json\n", args.out);
}

// The point-based solver on any discrete problem without use limits: solve, save the policy when
// asked, print.
void run_point_based(const SolveArgs& args, const pomdp::Problem& problem,
                     const pomdp::TabularModel& tables) {
  namespace off = solvers::offline;
  if (solvers::UseLimits(*problem.model).any())
    throw InputError(args.problem, 0,
                     "the point-based solver does not support per-action use limits or "
                     "prerequisites (actions.uses, actions.requires); use --method exact "
                     "(identification problems) or an online solver");
  auto dense = std::make_shared<const off::FlatPomdp>(off::make_flat_pomdp(tables, args.problem));

  off::SolverOptions options;
  options.epsilon = args.epsilon;
  options.time_limit_seconds = args.time_limit;
  options.seed = args.seed;
  options.max_trials = args.max_trials;
  off::PointBasedSolver solver(dense, options);
  // Progress through spdlog (stderr, see main.cpp) so that stdout holds only the result.
  spdlog::info("solving {} ({} states, {} actions, {} observations; epsilon {}, time limit {} s)",
               args.problem, dense->num_states, dense->num_actions, dense->num_observations,
               args.epsilon, args.time_limit);
  const off::SolverProgress result = solver.solve([](const off::SolverProgress& p) {
    spdlog::info(
        "{:7.1f} s  trials {:6}  V* in [{:.6f}, {:.6f}]  gap {:.3g}  vectors {}  points {}",
        p.seconds, p.trials, p.root.lower, p.root.upper, p.root.upper - p.root.lower,
        p.alpha_vectors, p.upper_points);
  });

  if (!args.out.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(args.out, ec);
    if (ec) throw InputError(args.out, 0, "cannot create the output folder: " + ec.message());
    off::save_policy(solver, (std::filesystem::path(args.out) / "policy.json").string());
  }
  print_point_based(args, problem, solver, result, dense->initial_belief);
}

void run_solve(const SolveArgs& given) {
  const SolveArgs args = with_iteration_alias(given);
  if (!(args.epsilon >= 0.0)) throw InputError("--epsilon must be >= 0");
  if (!(args.time_limit > 0.0)) throw InputError("--time-limit must be > 0 seconds");
  const pomdp::Problem problem = pomdp::load_problem(args.problem);
  const pomdp::TabularModel* tables = problem.model->tabular();
  if (tables == nullptr) {
    throw InputError(args.problem, 0,
                     "this problem has no tables (continuous observations?); the offline solver "
                     "needs a discrete problem: a .pomdp file or an object-identification YAML");
  }
  const auto shape_problem = solvers::identification_shape_problem(*tables);
  if (args.method == "exact" && shape_problem) {
    throw InputError(args.problem, 0,
                     "--method exact needs an identification problem, and this one is not: " +
                         *shape_problem + " (use --method point-based)");
  }
  if (args.method == "exact" && !args.out.empty()) {
    throw InputError("--out saves a point-based policy; use it with --method point-based");
  }
  if (args.method == "exact" || (args.method == "auto" && args.out.empty() && !shape_problem)) {
    run_exact(args, problem, *tables);
    return;
  }
  if (args.method == "auto" && shape_problem) {
    spdlog::info("not an identification problem ({}): using the point-based solver",
                 *shape_problem);
  }
  run_point_based(args, problem, *tables);
}

}  // namespace

void add_solve_command(CLI::App& app) {
  auto args = std::make_shared<SolveArgs>();
  auto* cmd = app.add_subcommand(
      "solve",
      "Bound the optimal value V*(b0) of a discrete problem (.pomdp or object-identification "
      "YAML).\n"
      "Identification problems (the state stays fixed until an action ends the episode) are "
      "solved\n"
      "by exact search over observation counts; others by the point-based solver (HSVI style), "
      "which\n"
      "can also save its policy. Progress goes to stderr; the bounds to stdout.");
  cmd->add_option("--problem", args->problem, "Problem file (problems/*.yaml or *.pomdp)")
      ->required();
  cmd->add_flag("--json", args->json,
                "Print one JSON object {\"lower\": L, \"upper\": U, ...} instead of text");
  cmd->add_option("--epsilon", args->epsilon,
                  "Target gap, relative: stop when upper - lower <= epsilon * max(1, |V|)")
      ->capture_default_str();
  cmd->add_option("--time-limit", args->time_limit, "Stop after this many seconds")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the point-based solver's random choices")
      ->capture_default_str();
  cmd->add_option("--method", args->method,
                  "auto (exact when the problem qualifies and no --out is given), exact, or "
                  "point-based")
      ->check(CLI::IsMember({"auto", "exact", "point-based"}))
      ->capture_default_str();
  cmd->add_option("--max-expansions", args->max_expansions,
                  "Exact solver: stop after this many node expansions (and spend at most as many "
                  "on each action's Q* at b0), 0: no limit; unlike --time-limit, the result "
                  "repeats on any machine")
      ->capture_default_str();
  cmd->add_option("--max-trials", args->max_trials,
                  "Point-based solver: stop after this many trials, 0: no limit; unlike "
                  "--time-limit, the result repeats on any machine")
      ->capture_default_str();
  cmd->add_option("--max-iterations", args->max_iterations,
                  "Deprecated: --max-expansions (exact) or --max-trials (point-based), whichever "
                  "the method uses and is not given")
      ->capture_default_str();
  cmd->add_option("--exact-search", args->exact_search,
                  "Exact solver's exploration: trials (HSVI-style, gap-directed) or passes "
                  "(every belief whose weighted gap exceeds a shrinking threshold)")
      ->check(CLI::IsMember({"trials", "passes"}))
      ->capture_default_str();
  cmd->add_option("--exact-frontier", args->exact_frontier,
                  "Exact solver's bounds at new beliefs: full (backed-up plans below, sawtooth "
                  "above), plans, sawtooth, or simple (commit now / one more sensing)")
      ->check(CLI::IsMember({"full", "plans", "sawtooth", "simple"}))
      ->capture_default_str();
  cmd->add_option("--pair-relaxation", args->pair_relaxation,
                  "Exact solver: cap every new belief's upper bound by the two-state sub-problems "
                  "solved up front (docs/planning.md, exact solver)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cmd->add_option("--sense-once", args->sense_once,
                  "Exact solver, with use limits: bound every new belief below by its best \"sense "
                  "once, then sort\" among the actions it has left (off: commit now)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cmd->add_option("--readings-left", args->readings_left,
                  "Exact solver, with a use limit on every sensing action: cap every new belief's "
                  "upper bound by what an agent told at once every reading its uses leave could "
                  "earn (docs/planning.md, exact solver)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cmd->add_option("--readings-left-budget", args->readings_left_budget,
                  "Exact solver: expansions of that bound's outcome tree per belief (more: "
                  "tighter and slower; 0: one more sensing)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--readings-left-max", args->readings_left_max,
                  "Exact solver: that bound only at beliefs with at most this many readings left "
                  "(with more it is rarely below one more sensing)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--frontier-margin", args->frontier_margin,
                  "Exact solver: a backed-up plan or point joins the frontier bounds only when it "
                  "improves them by more than this (reward units)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--frontier-entries", args->frontier_entries,
                  "Exact solver: at most this many plans and this many sawtooth points (each "
                  "costs every later frontier evaluation)")
      ->capture_default_str();
  cmd->add_option("--frontier-plans", args->frontier_plans,
                  "Exact solver: at most this many plans (0: --frontier-entries); "
                  "--frontier-entries then caps the sawtooth points")
      ->capture_default_str();
  cmd->add_option("--expand-within", args->expand_within,
                  "Exact solver's passes: at a belief, expand only the actions whose upper bound "
                  "lies within this share of the belief's gap below its upper bound (1: every "
                  "action that can still be optimal)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option(
      "--out", args->out,
      "Folder to write policy.json (alpha vectors) into, for `trials --solver offline`");
  cmd->callback([args] { run_solve(*args); });
}

}  // namespace echoplan::cli
