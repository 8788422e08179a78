// `echoplan solve`: bounds on the optimal value V*(b0) of a discrete problem, from the offline
// point-based solver; optionally the policy (alpha vectors) for later runs.
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "common/error.h"
#include "pomdp/problem.h"
#include "solvers/offline/dense_pomdp.h"
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
  std::string out;
};

void run_solve(const SolveArgs& args) {
  namespace off = solvers::offline;
  if (!(args.epsilon >= 0.0)) throw InputError("--epsilon must be >= 0");
  if (!(args.time_limit > 0.0)) throw InputError("--time-limit must be > 0 seconds");
  const pomdp::Problem problem = pomdp::load_problem(args.problem);
  const pomdp::TabularModel* tables = problem.model->tabular();
  if (tables == nullptr) {
    throw InputError(args.problem, 0,
                     "this problem has no tables (continuous observations?); the offline solver "
                     "needs a discrete problem: a .pomdp file or an object-identification YAML");
  }
  auto dense =
      std::make_shared<const off::DensePomdp>(off::make_dense_pomdp(*tables, args.problem));

  off::SolverOptions options;
  options.epsilon = args.epsilon;
  options.time_limit_seconds = args.time_limit;
  options.seed = args.seed;
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

  const auto& action_names = problem.model->spec().action_names;
  auto action_name = [&](int a) {
    return a < static_cast<int>(action_names.size()) ? action_names[a] : std::to_string(a);
  };
  const off::BeliefVector& b0 = dense->initial_belief;
  const int best = solver.best_action(b0);
  const std::vector<off::ValueBounds> q = solver.action_bounds(b0);

  if (!args.out.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(args.out, ec);
    if (ec) throw InputError(args.out, 0, "cannot create the output folder: " + ec.message());
    off::save_policy(solver, (std::filesystem::path(args.out) / "policy.json").string());
  }

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

}  // namespace

void add_solve_command(CLI::App& app) {
  auto args = std::make_shared<SolveArgs>();
  auto* cmd = app.add_subcommand(
      "solve",
      "Bound the optimal value V*(b0) of a discrete problem (.pomdp or object-identification "
      "YAML)\n"
      "with the offline point-based solver (HSVI style), and optionally save its policy.\n"
      "Progress goes to stderr; the bounds to stdout.");
  cmd->add_option("--problem", args->problem, "Problem file (problems/*.yaml or *.pomdp)")
      ->required();
  cmd->add_flag("--json", args->json,
                "Print one JSON object {\"lower\": L, \"upper\": U, ...} instead of text");
  cmd->add_option("--epsilon", args->epsilon,
                  "Target gap, relative: stop when upper - lower <= epsilon * max(1, |V|)")
      ->capture_default_str();
  cmd->add_option("--time-limit", args->time_limit, "Stop after this many seconds")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the solver's random choices")
      ->capture_default_str();
  cmd->add_option(
      "--out", args->out,
      "Folder to write policy.json (alpha vectors) into, for `trials --solver offline`");
  cmd->callback([args] { run_solve(*args); });
}

}  // namespace echoplan::cli
