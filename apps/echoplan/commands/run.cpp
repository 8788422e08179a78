// `echoplan run`: one trial of the whole loop, printed as it goes: the planner picks an action, the
// (simulated) robot executes it while the recorder listens, the classifier says what it heard, the
// belief is updated, until the robot sorts the object. Everything is saved per step in DIR.
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "commands/planner_options.h"
#include "commands/sim_options.h"
#include "common/data_dir.h"
#include "common/error.h"
#include "common/stop_signal.h"
#include "experiment/calibrated_problem.h"
#include "experiment/environment_factory.h"
#include "experiment/loop_log.h"
#include "experiment/planner.h"
#include "experiment/simulated_training.h"
#include "experiment/trial_runner.h"
#include "pomdp/make_belief.h"
#include "pomdp/problem.h"

namespace echoplan::cli {

namespace {

namespace fs = std::filesystem;

struct RunFlags {
  std::string object;
  std::string problem;     // empty: the shipped problem with the model's calibrated table
  std::string model;       // empty: train one on freshly synthesised recordings
  std::string recordings;  // non-empty: replay these instead of simulating
  std::uint64_t seed = 1;
  int max_steps = 100;
  int train_per_pair = 10;
  std::string out;
  SimFiles sim;
  solvers::PlannerOverrides planner;
};

// Independent streams drawn from --seed.
enum RunStream : std::uint64_t { training_stream = 1, trial_stream = 2 };

// Which object the world holds, and which problem object that is the truth for.
struct TrueObject {
  int index = 0;      // in the problem's objects
  std::string world;  // what the world holds: the object itself or a catalogue variant of it
};

TrueObject resolve_object(const std::string& name, const pomdp::ObjectProblemData& problem,
                          const sim::Catalogue& catalogue) {
  const auto& objects = problem.objects;
  auto it = std::find(objects.begin(), objects.end(), name);
  if (it != objects.end()) return {static_cast<int>(it - objects.begin()), name};
  // A variant (e.g. coffee_mug_weighted) stands in for its original, as in the report's
  // section 5.4.
  const auto entry = catalogue.objects.find(name);
  if (entry != catalogue.objects.end()) {
    it = std::find(objects.begin(), objects.end(), entry->second.base_object);
    if (it != objects.end()) return {static_cast<int>(it - objects.begin()), name};
  }
  throw InputError(
      fmt::format("--object {}: not an object of problem '{}' ({}) nor a catalogue variant of one",
                  name, problem.name, fmt::join(objects, ", ")));
}

std::string bar(double p, int width = 24) {
  const int filled = std::clamp(static_cast<int>(std::lround(p * width)), 0, width);
  std::string s;
  for (int i = 0; i < width; ++i) s += i < filled ? "█" : "░";
  return s;
}

void print_belief(const std::vector<std::string>& objects, const std::vector<double>& belief) {
  std::size_t width = 0;
  for (const auto& o : objects) width = std::max(width, o.size());
  for (std::size_t k = 0; k < objects.size(); ++k)
    fmt::print("    {:<{}}  {}  {:.3f}\n", objects[k], width, bar(belief[k]), belief[k]);
}

// One line per action: what the robot did and what was heard.
void print_step(const experiment::LoopStep& s) {
  fmt::print("step {}: {}", s.step + 1, s.action_name);
  if (s.report.status != robot::ActionStatus::done) {
    fmt::print(" -> {}: {}", robot::to_string(s.report.status), s.report.reason);
  } else if (s.classified && s.heard.unknown) {
    // Unlike every class: say which one it was nearest to, and how likely that one was.
    const auto nearest =
        std::max_element(s.heard.probabilities.begin(), s.heard.probabilities.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; });
    fmt::print(" -> heard unknown (nearest {}, p {:.2f}), {:.1f} ms to classify",
               nearest == s.heard.probabilities.end() ? "?" : nearest->first, s.heard.probability,
               s.observe_ms);
  } else if (s.classified) {
    fmt::print(" -> heard {} (p {:.2f}), {:.1f} ms to classify", s.heard.label, s.heard.probability,
               s.observe_ms);
  }
  fmt::print(", reward {:g}\n", s.reward);
}

// The model the loop classifies with: --model, or one trained now on simulated recordings of the
// problem's objects (saved as DIR/model.json).
std::shared_ptr<const perception::ObservationModel> observation_model(
    const RunFlags& f, const pomdp::ObjectProblemData& problem, const SimSetup& sim,
    const std::atomic<bool>& stop) {
  if (!f.model.empty())
    return std::make_shared<const perception::ObservationModel>(
        perception::load_observation_model(f.model));
  experiment::SimulatedTraining training;
  training.objects = problem.objects;
  for (const auto& a : problem.sensing) training.actions.push_back(a.name);
  training.per_pair = f.train_per_pair;
  training.seed = derive_seed(f.seed, {training_stream});
  training.directory = fs::path(f.out) / "training";
  spdlog::info("no --model: training {} on {} simulated recordings per object and action in {}",
               training.train.classifier, training.per_pair, training.directory.string());
  auto model = std::make_shared<const perception::ObservationModel>(
      experiment::train_on_simulated_recordings(
          sim.catalogue, sim.config, training,
          [](const std::string& stage, int done, int total) {
            if (done == total || done % 20 == 0) spdlog::info("  {} {}/{}", stage, done, total);
          },
          stop));
  if (stop.load()) throw Interrupted{};
  const std::string path = (fs::path(f.out) / "model.json").string();
  perception::save_observation_model(*model, path);
  for (const auto& action : model->actions())
    spdlog::info("  {}: cross-validated accuracy {:.0f}%", action,
                 100.0 * model->calibration(action).confusion.accuracy());
  spdlog::info("saved {} (reuse it with --model)", path);
  return model;
}

// The problem the planner plans on: --problem as written, or the shipped problem with the model's
// calibrated observation table (to be saved as DIR/problem.yaml, see save_problem).
pomdp::Problem planning_problem(const RunFlags& f, const pomdp::Problem& base,
                                const perception::ObservationModel& model, std::string& path) {
  if (!f.problem.empty()) {
    path = f.problem;
    return base;
  }
  const auto& data = experiment::object_problem(*base.model).data();
  pomdp::Problem calibrated = base;
  calibrated.model = std::make_shared<pomdp::ObjectIdentificationModel>(
      experiment::calibrated_problem(data, model));
  path = (fs::path(f.out) / "problem.yaml").string();
  calibrated.source_path = path;
  return calibrated;
}

void save_problem(const pomdp::Problem& problem, const std::string& path) {
  std::ofstream out(path);
  pomdp::write_problem_yaml(out, experiment::object_problem(*problem.model).data(), problem.belief,
                            problem.planner);
  if (!out) throw InputError(path, 0, "cannot write the calibrated problem");
}

void run_command(const RunFlags& f) {
  // Everything that can be wrong with the input is checked before any work.
  if (!f.recordings.empty() && f.model.empty())
    throw InputError(
        "--recordings needs --model: train one on recordings that are not replayed "
        "(`echoplan train --data TRAINING_DIR --out model.json`), so the classifier is not tested "
        "on its own training clips");
  if (f.train_per_pair < 2)
    throw InputError("--train-per-pair must be at least 2 (cross-validation needs it)");
  std::error_code ec;
  fs::create_directories(f.out, ec);
  if (ec) throw InputError(f.out, 0, "cannot create the output folder: " + ec.message());
  const SimSetup sim = load_sim_setup(f.sim);
  const std::string base_path =
      f.problem.empty() ? shipped_file("problems/audio_objects.yaml") : f.problem;
  const pomdp::Problem base = pomdp::load_problem(base_path);
  const pomdp::ObjectProblemData& base_data = experiment::object_problem(*base.model).data();
  const TrueObject truth = resolve_object(f.object, base_data, sim.catalogue);
  if (!f.recordings.empty() && !fs::is_directory(f.recordings))
    throw InputError(f.recordings, 0, "the recordings folder does not exist");

  const StopSignal stop;
  const auto model = observation_model(f, base_data, sim, stop.flag());
  std::string problem_path;
  const pomdp::Problem problem = planning_problem(f, base, *model, problem_path);
  const auto& data = experiment::object_problem(*problem.model).data();

  experiment::LoopSettings settings;
  settings.model = problem.model;
  settings.world.kind = f.recordings.empty() ? experiment::WorldSettings::Kind::simulator
                                             : experiment::WorldSettings::Kind::replay;
  settings.world.catalogue = sim.catalogue;
  settings.world.config = sim.config;
  settings.world.recordings = f.recordings;
  settings.classifier = model;
  if (truth.world != data.objects[truth.index])
    settings.world_objects[data.objects[truth.index]] = truth.world;
  auto environment = experiment::make_environment_factory(settings)();
  const experiment::Planner planner = experiment::make_planner(f.planner, problem, problem_path);
  // Only now that everything fits are files written.
  if (f.problem.empty()) save_problem(problem, problem_path);
  experiment::LoopLog log(f.out, experiment::object_problem(*problem.model));

  fmt::print("{} {}, planning on {} ({}), seed {}\n", truth.world,
             f.recordings.empty() ? "in the simulator" : "replayed from " + f.recordings,
             problem_path, planner.describe(), f.seed);

  // The environment reports each action as it happens; the runner then gives the belief after it.
  experiment::LoopStep last;
  environment->set_step_listener([&](const experiment::LoopStep& s) { last = s; });
  nlohmann::json steps = nlohmann::json::array();
  experiment::TrialSetup setup;
  setup.model = problem.model.get();
  setup.environment = environment.get();
  setup.solver = planner.solver.get();
  setup.make_belief = [&problem](Rng& rng) { return pomdp::make_belief(problem, rng); };
  setup.stop_requested = &stop.flag();
  setup.step_finished = [&](const experiment::StepRecord& s, const pomdp::Belief* after) {
    if (s.step == 0) {
      fmt::print("belief before the first action:\n");
      print_belief(data.objects, s.belief);
    }
    print_step(last);
    std::vector<double> marginal;
    if (after) {
      marginal = after->discrete_marginal(0);
      print_belief(data.objects, marginal);
    }
    steps.push_back(log.write_step(last, s.belief, after ? &marginal : nullptr));
  };
  experiment::TrialOptions options;
  options.budget = planner.budget;
  options.max_steps = f.max_steps;
  options.seed = derive_seed(f.seed, {trial_stream});
  options.validate();
  const auto result = experiment::run_trial(setup, options, 0, truth.index);

  nlohmann::json trial = planner.to_json();
  trial.update({{"object", truth.world},
                {"true_state", data.objects[truth.index]},
                {"world", f.recordings.empty() ? "simulator" : "replay"},
                {"recordings", f.recordings},
                {"problem", problem_path},
                {"model", f.model.empty() ? (fs::path(f.out) / "model.json").string() : f.model},
                {"seed", f.seed},
                {"max_steps", f.max_steps},
                {"interrupted", !result.has_value()}});
  if (result) {
    const experiment::TrialRecord& r = result->record;
    trial.update(
        {{"believed_state", data.objects[r.believed_state]},
         {"steps", r.steps},
         {"discounted_reward", r.discounted_reward},
         {"collision", r.collision},
         {"capped", r.capped},
         {"final_action", problem.model->spec().action_names[result->steps.back().action]}});
  }
  std::ofstream(fs::path(f.out) / "trial.json") << trial.dump(2) << '\n';
  if (!result) {
    spdlog::warn("interrupted: {} finished steps are in {}", steps.size(), f.out);
    throw Interrupted{};
  }
  const experiment::TrialRecord& r = result->record;
  const std::string& final_action = problem.model->spec().action_names[result->steps.back().action];
  if (r.collision)
    fmt::print("result: the trial ended in a collision after {} steps", r.steps);
  else if (r.capped)
    fmt::print("result: no sorting action within --max-steps {}", f.max_steps);
  else
    fmt::print("result: {} sorted by {} (believed {})", truth.world, final_action,
               data.objects[r.believed_state]);
  fmt::print("; {} steps, discounted reward {:.3f}\nfiles: {}\n", r.steps, r.discounted_reward,
             f.out);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto flags = std::make_shared<RunFlags>();
  auto* cmd = app.add_subcommand(
      "run",
      "One trial of the whole loop: plan, act (simulated robot or replayed recordings), listen, "
      "classify,\n"
      "update the belief, until the object is sorted. Prints each step and the belief; writes per "
      "step\n"
      "the clip, the features, the observation, the belief and the reward to DIR (see "
      "docs/loop.md).\n"
      "Without --model, trains one first on --train-per-pair simulated recordings per object and "
      "action\n"
      "and plans on the shipped problem with that model's calibrated table (both saved in DIR).\n"
      "Examples:\n"
      "  echoplan run --object coffee_mug --out runs/mug\n"
      "  echoplan run --object coffee_mug_weighted --model runs/mug/model.json --out "
      "runs/heavy_mug\n"
      "  echoplan run --object plastic_cup --model model.json --recordings recordings/ --out "
      "runs/replay");
  cmd->add_option("--object", flags->object,
                  "The true object: one of the problem's, or a catalogue variant of one (e.g. "
                  "coffee_mug_weighted)")
      ->required();
  cmd->add_option(
      "--problem", flags->problem,
      "Problem to plan on, as written (default: problems/audio_objects.yaml with the model's "
      "calibrated table)");
  cmd->add_option(
      "--model", flags->model,
      "Trained observation model (`echoplan train --out`); default: train one now on simulated "
      "recordings");
  cmd->add_option(
      "--recordings", flags->recordings,
      "Replay recordings of the true object from DIR/<object>/<action>/* instead of simulating "
      "(needs --model)");
  cmd->add_option("--seed", flags->seed, "Seed of every random choice")->capture_default_str();
  cmd->add_option("--max-steps", flags->max_steps, "Stop the trial after this many steps")
      ->capture_default_str();
  cmd->add_option("--train-per-pair", flags->train_per_pair,
                  "Without --model: simulated training recordings per object and action")
      ->capture_default_str();
  cmd->add_option("--out", flags->out, "Folder for the clips, loop_steps.csv/.jsonl, trial.json")
      ->required();
  add_sim_file_options(*cmd, flags->sim);
  add_planner_options(*cmd, flags->planner);
  cmd->callback([flags] { run_command(*flags); });
}

}  // namespace echoplan::cli
