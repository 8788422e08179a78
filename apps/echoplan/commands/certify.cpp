// `echoplan certify`: how far from optimal the decisions of a logged run were, measured exactly
// (experiment/regret_certificate.h): per-trial discounted regret against V*, its mean and 95% CI,
// and the share of V* the planner is certified to reach.
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "common/error.h"
#include "common/file_io.h"
#include "common/stop_signal.h"
#include "experiment/campaign_certificate.h"
#include "experiment/regret_certificate.h"
#include "experiment/trial_log.h"
#include "pomdp/problem.h"

namespace echoplan::cli {

namespace {

struct CertifyArgs {
  std::string problem;
  std::string steps;
  std::string campaign;
  bool json = false;
  double gap = experiment::CertifyOptions{}.decision_gap;
  long expansions = experiment::CertifyOptions{}.expansions_per_belief;
  long root_expansions = experiment::CertifyOptions{}.root_expansions;
  int worst = 5;
};

experiment::CertifyOptions certify_options(const CertifyArgs& args) {
  if (!(args.gap > 0.0)) throw InputError("--gap must be > 0");
  if (args.worst < 0) throw InputError("--worst must be >= 0");
  if (args.expansions < 1) throw InputError("--expansions must be >= 1");
  experiment::CertifyOptions options;
  options.decision_gap = args.gap;
  options.worst = args.worst;
  options.expansions_per_belief = args.expansions;
  options.root_expansions = args.root_expansions;
  return options;
}

// A dataset campaign's folder: every fold's arms, each with its fold's problem; the summary printed
// and saved as DIR/certified/summary.json and summary.txt.
void certify_campaign(const CertifyArgs& args) {
  if (!args.problem.empty() || !args.steps.empty())
    throw InputError("--campaign certifies each fold with its own problem: drop --problem/--steps");
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const auto progress = [&](const experiment::ArmCertificate& a, std::size_t done,
                            std::size_t total) {
    spdlog::info("certified fold {}, arm {} ({} of {}, {:.1f} s): regret {:.4f} ± {:.4f} per trial",
                 a.fold, a.arm, done, total, seconds(), a.certificate.regret.mean,
                 a.certificate.regret.half_width);
  };
  // Ctrl-C stops after the fold and arm in progress; those finished are written.
  const StopSignal stop;
  const std::vector<experiment::ArmCertificate> certificates =
      experiment::certify_campaign(args.campaign, certify_options(args), progress, &stop.flag());
  const std::filesystem::path out = std::filesystem::path(args.campaign) / "certified";
  std::filesystem::create_directories(out);
  const std::string text = experiment::campaign_certificate_text(certificates);
  nlohmann::ordered_json json = experiment::campaign_certificate_json(certificates);
  json["interrupted"] = stop.requested();
  write_file_atomically(out / "summary.json", json.dump(2) + "\n");
  write_file_atomically(out / "summary.txt", text);
  fmt::print("{}", args.json ? json.dump() + "\n" : text);
  if (stop.requested()) {
    spdlog::warn("interrupted: {} folds x arms certified and written to {}", certificates.size(),
                 (out / "summary.json").string());
    throw Interrupted{};
  }
  spdlog::info("certified {} folds x arms in {:.2f} s; {}", certificates.size(), seconds(),
               (out / "summary.json").string());
}

void run_certify(const CertifyArgs& args) {
  if (!args.campaign.empty()) return certify_campaign(args);
  if (args.problem.empty() || args.steps.empty())
    throw InputError("give --problem and --steps (a run's log), or --campaign DIR");
  const experiment::CertifyOptions options = certify_options(args);
  const pomdp::Problem problem = pomdp::load_problem(args.problem);
  const pomdp::ModelSpec& spec = problem.model->spec();
  const auto start = std::chrono::steady_clock::now();
  spdlog::info("certifying {} against {}", args.steps, args.problem);
  const experiment::Certificate c =
      experiment::certify_steps(problem, args.problem, args.steps, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double vstar = 0.5 * (c.vstar.lower + c.vstar.upper);

  if (args.json) {
    fmt::print("{}\n", experiment::to_json(c).dump());
    return;
  }
  fmt::print("Certificate of {} on {}\n", args.steps, args.problem);
  fmt::print("  V*(b0) in [{:.5f}, {:.5f}]\n", c.vstar.lower, c.vstar.upper);
  fmt::print(
      "  regret per trial (discounted, vs V*): {:.4f} ± {:.4f} (95% CI, {} trials, {} "
      "decisions)\n",
      c.regret.mean, c.regret.half_width, c.regret.n, c.decisions);
  fmt::print("  certified share of V*: {:.2f}% (95% CI {:.2f}% to {:.2f}%)\n",
             100.0 * c.share_of_vstar(),
             100.0 * (1.0 - (c.regret.mean + c.regret.half_width) / vstar),
             100.0 * (1.0 - (c.regret.mean - c.regret.half_width) / vstar));
  fmt::print(
      "  certificate looseness (summed, discounted bound gaps per trial): {:.4f}; regret from the "
      "bounds' other ends: {:.4f}\n",
      c.bound_gap_mean, c.regret_lower_mean);
  fmt::print("  (target gap at each belief {:g}{})\n", args.gap,
             c.unconverged_beliefs > 0
                 ? fmt::format("; {} beliefs missed that gap, their bounds still hold",
                               c.unconverged_beliefs)
                 : "");
  const int capped = static_cast<int>(
      std::count_if(c.trials.begin(), c.trials.end(), [](const auto& t) { return !t.ended; }));
  if (capped > 0)
    fmt::print("  {} trials were cut short; γ^T V*(b_T) of each counts as regret\n", capped);
  if (!c.worst.empty()) fmt::print("largest single losses V*(b) - Q*(b, a):\n");
  const auto& states = spec.state.discrete_value_names;
  for (const auto& d : c.worst) {
    std::string belief;
    for (std::size_t s = 0; s < d.belief.size(); ++s) {
      if (d.belief[s] <= 0.0) continue;
      const std::string name =
          !states.empty() && s < states[0].size() ? states[0][s] : std::to_string(s);
      belief += fmt::format("{}{} {:.3f}", belief.empty() ? "" : ", ", name, d.belief[s]);
    }
    fmt::print("  {:.4f}  trial {} step {} (line {}): {} where {} was best; belief {}\n", d.loss,
               d.trial, d.step, d.line, spec.action_names[d.action],
               spec.action_names[d.best_action], belief);
  }
  spdlog::info("certified in {:.2f} s", seconds);
}

}  // namespace

void add_certify_command(CLI::App& app) {
  auto args = std::make_shared<CertifyArgs>();
  auto* cmd = app.add_subcommand(
      "certify",
      "Measure how far a logged run's decisions were from optimal. For an identification problem,\n"
      "each decision's loss V*(b) - Q*(b, a) is computed exactly at the belief recomputed from "
      "the\n"
      "logged actions and observations; the discounted sum per trial estimates V*(b0) minus the\n"
      "planner's value, with its 95% CI and the share of V* it implies.");
  cmd->add_option("--problem", args->problem, "The problem the run used (YAML or .pomdp)");
  cmd->add_option("--steps", args->steps, "steps.csv written by `echoplan trials --out DIR`");
  cmd->add_option("--campaign", args->campaign,
                  "A dataset campaign's folder instead of --problem and --steps: each fold's "
                  "trials (DIR/folds/<fold>/arms/<arm>/steps.csv) with that fold's problem "
                  "(DIR/folds/<fold>/problem.yaml); writes DIR/certified/summary.json");
  cmd->add_flag("--json", args->json,
                "Print {\"vstar_lower\", \"vstar_upper\", \"regret_mean\", \"regret_ci95\", "
                "\"trials\", ...} instead of text");
  cmd->add_option("--gap", args->gap,
                  "Target gap of the V* and Q* bounds at each visited belief (reward units)")
      ->capture_default_str();
  cmd->add_option("--expansions", args->expansions,
                  "Search limit per belief (node expansions): more gives tighter bounds and a "
                  "smaller gap between the two regret figures")
      ->capture_default_str();
  cmd->add_option("--root-expansions", args->root_expansions,
                  "Search at the start belief before the trials (node expansions; the logged "
                  "beliefs lie below it, so this tightens every decision's bounds)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--worst", args->worst, "How many of the largest single losses to list")
      ->capture_default_str();
  cmd->callback([args] { run_certify(*args); });
}

}  // namespace echoplan::cli
