// `echoplan import oppt`: another planner's run logs (OPPT, the original robot's ABT) as echoplan's
// steps.csv and trials.csv, so that `echoplan certify` certifies its decisions
// (experiment/oppt_log.h has the format and how each column is filled).
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "common/error.h"
#include "common/file_io.h"
#include "experiment/oppt_log.h"
#include "experiment/trial_log.h"
#include "experiment/trial_summary.h"
#include "pomdp/problem.h"

namespace echoplan::cli {

namespace {

struct ImportOpptArgs {
  std::vector<std::string> logs;
  std::string actions, observations, objects;
  std::string problem = "problems/audio_objects.yaml";
  std::string out;
};

experiment::OpptCodes codes_for(const ImportOpptArgs& args, const pomdp::ModelSpec& spec) {
  if (spec.state.discrete_value_names.empty() || !spec.observation.discrete)
    throw InputError(args.problem, 0,
                     "import needs a problem with discrete observations and a discrete state "
                     "variable (the object)");
  experiment::OpptCodes codes;
  codes.actions = experiment::parse_code_mapping(args.actions, spec.action_names, "--actions");
  codes.observations =
      experiment::parse_code_mapping(args.observations, spec.observation.names, "--observations");
  codes.objects =
      experiment::parse_code_mapping(args.objects, spec.state.discrete_value_names[0], "--objects");
  return codes;
}

void run_import_oppt(const ImportOpptArgs& args) {
  const pomdp::Problem problem = pomdp::load_problem(args.problem);
  if (problem.model->tabular() == nullptr)
    throw InputError(args.problem, 0, "import needs a discrete problem with tables");
  const pomdp::ModelSpec& spec = problem.model->spec();
  const experiment::OpptCodes codes = codes_for(args, spec);

  // Every log is read and converted before anything is written: a bad log leaves no half output.
  std::vector<experiment::TrialResult> trials;
  experiment::BeliefSources sources;
  double logged_total = 0.0;
  for (const std::string& file : args.logs) {
    const auto runs = experiment::parse_oppt_log(read_text_file(file, "OPPT log"), file);
    for (const experiment::OpptRun& run : runs) {
      const int trial = static_cast<int>(trials.size());
      trials.push_back(experiment::oppt_run_records(run, codes, problem, trial, file, sources));
      logged_total += run.total_discounted_reward;
    }
  }

  experiment::TrialLog log(args.out, spec, problem.belief.particles);
  std::vector<experiment::TrialRecord> records;
  int steps = 0;
  for (const experiment::TrialResult& t : trials) {
    log.trial_finished(t.record, t.steps);
    records.push_back(t.record);
    steps += t.record.steps;
  }
  const experiment::TrialSummary summary = experiment::summarize(records, spec.action_names.size());
  nlohmann::json run;
  run["imported_from"] = args.logs;
  run["problem"] = args.problem;
  run["solver"] = "oppt";
  log.write_summary(summary, run);

  const double n = static_cast<double>(trials.size());
  fmt::print("imported {} runs ({} steps) from {} log(s) into {}\n", trials.size(), steps,
             args.logs.size(), args.out);
  fmt::print("  mean discounted reward: {:.5g} with the problem's discount {:g} (logged: {:.5g})\n",
             summary.mean_discounted_reward, spec.discount, logged_total / n);
  fmt::print(
      "  beliefs: {} from logged particles, {} the problem's initial belief, {} the problem's "
      "exact "
      "belief (empty particle blocks)\n",
      sources.particles, sources.initial, sources.exact);
  fmt::print("  certify with: echoplan certify --problem {} --steps {}/steps.csv\n", args.problem,
             args.out);
}

}  // namespace

void add_import_command(CLI::App& app) {
  auto* import = app.add_subcommand("import", "Read another planner's run logs as echoplan's logs");
  import->require_subcommand(1);
  auto args = std::make_shared<ImportOpptArgs>();
  auto* cmd = import->add_subcommand(
      "oppt",
      "Convert OPPT run logs (the original robot's ABT) into DIR/steps.csv and DIR/trials.csv,\n"
      "the columns `echoplan trials` writes, so `echoplan certify` can certify the run. Each\n"
      "step's belief columns hold the particles logged after the previous step, counted per\n"
      "object (step 0: the problem's initial belief; an empty block: the problem's exact belief).\n"
      "Example (the report's logs):\n"
      "  echoplan import oppt run1.log run2.log --actions "
      "4=slide,5=strike,6=move_to_A,7=move_to_B\n"
      "    --observations 0=pringles_can,1=coffee_mug,2=plastic_cup,3=paper_base,5=none\n"
      "    --objects 0=pringles_can,1=coffee_mug,2=plastic_cup,3=paper_base --out oppt_runs\n"
      "  echoplan certify --problem problems/audio_objects.yaml --steps oppt_runs/steps.csv");
  cmd->add_option("logs", args->logs, "OPPT run logs (each may hold several runs)")->required();
  cmd->add_option("--actions", args->actions, "OPPT action codes as the problem's action names")
      ->required();
  cmd->add_option("--observations", args->observations,
                  "OPPT observation codes as the problem's observation names")
      ->required();
  cmd->add_option("--objects", args->objects,
                  "Object codes (the last number of S: and p: lines) as the problem's objects")
      ->required();
  cmd->add_option("--problem", args->problem, "The problem whose names the mappings use")
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Folder for steps.csv, trials.csv and summary.json")
      ->required();
  cmd->callback([args] { run_import_oppt(*args); });
}

}  // namespace echoplan::cli
