// `echoplan run`: one trial of the whole loop, printed as it goes: the planner picks an action, the
// (simulated) robot executes it while the recorder listens, the classifier says what it heard, the
// belief is updated, until the robot sorts the object. Everything is saved per step in DIR.
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "commands/planner_options.h"
#include "commands/sim_options.h"
#include "common/data_dir.h"
#include "common/error.h"
#include "common/file_io.h"
#include "common/stop_signal.h"
#include "loop/calibrated_problem.h"
#include "loop/loop.h"
#include "loop/loop_log.h"
#include "loop/object_problem.h"
#include "loop/prepare_observation.h"
#include "loop/step_text.h"
#include "loop/streams.h"
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

// Everything that can be wrong with the flags alone, checked before any work.
void check_flags(const RunFlags& f) {
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
  if (!f.recordings.empty() && !fs::is_directory(f.recordings))
    throw InputError(f.recordings, 0, "the recordings folder does not exist");
}

// The model the loop classifies with: --model, or one trained now on simulated recordings of the
// problem's objects (DIR/training); with the shipped problem calibrated to it unless --problem.
loop::PreparedObservation prepare(const RunFlags& f, const pomdp::Problem& base,
                                  const loop::SimulatedWorldSpec& sim, const StopSignal& stop) {
  const std::string problem_path = (fs::path(f.out) / "problem.yaml").string();
  const pomdp::Problem* calibrate = f.problem.empty() ? &base : nullptr;
  if (!f.model.empty())
    return loop::prepare_observation(loop::ModelFile{f.model}, calibrate, problem_path, {},
                                     stop.flag());
  const auto& data = loop::object_problem(*base.model).data();
  loop::SimulatedTraining training;
  training.catalogue = sim.catalogue;
  training.config = sim.config;
  training.objects = data.objects;
  for (const auto& a : data.sensing) training.actions.push_back(a.name);
  training.per_pair = f.train_per_pair;
  training.seed = loop::stream_seed(f.seed, loop::Stream::run_training);
  training.directory = fs::path(f.out) / "training";
  spdlog::info("no --model: training {} on {} simulated recordings per object and action in {}",
               training.train.classifier, training.per_pair, training.directory.string());
  auto prepared = loop::prepare_observation(
      training, calibrate, problem_path,
      [](const std::string& stage, int done, int total) {
        if (done == total || done % 20 == 0) spdlog::info("  {} {}/{}", stage, done, total);
      },
      stop.flag());
  if (!prepared.model) throw Interrupted{};
  const std::string path = (fs::path(f.out) / "model.json").string();
  perception::save_observation_model(*prepared.model, path);
  for (const auto& action : prepared.model->actions())
    spdlog::info("  {}: cross-validated accuracy {:.0f}%", action,
                 100.0 * prepared.model->calibration(action).confusion.accuracy());
  spdlog::info("saved {} (reuse it with --model)", path);
  return prepared;
}

// The loop: the planning problem in the simulator or replaying --recordings.
loop::LoopSettings loop_settings(const RunFlags& f, const loop::PreparedObservation& prepared,
                                 std::shared_ptr<const pomdp::Problem> base,
                                 const loop::SimulatedWorldSpec& sim, const TrueObject& truth) {
  loop::LoopSettings settings;
  settings.problem = prepared.problem ? prepared.problem : std::move(base);
  if (f.recordings.empty())
    settings.world = sim;
  else
    settings.world = loop::ReplayWorldSpec{f.recordings};
  settings.classifier = prepared.model;
  const auto& objects = loop::object_problem(*settings.problem->model).data().objects;
  if (truth.world != objects[truth.index])
    settings.world_objects[objects[truth.index]] = truth.world;
  settings.planner = f.planner;
  settings.max_steps = f.max_steps;
  return settings;
}

// DIR/trial.json: the settings and, unless interrupted, the result.
void write_trial_json(const RunFlags& f, const loop::Loop& run, const TrueObject& truth,
                      const std::optional<loop::Trial>& trial) {
  const pomdp::Problem& problem = run.spec().problem();
  const auto& objects = loop::object_problem(*problem.model).data().objects;
  nlohmann::json j = run.planner().to_json();
  j.update({{"object", truth.world},
            {"true_state", objects[truth.index]},
            {"world", loop::world_name(run.spec().settings().world)},
            {"recordings", f.recordings},
            {"problem", problem.source_path},
            {"model", f.model.empty() ? (fs::path(f.out) / "model.json").string() : f.model},
            {"seed", f.seed},
            {"max_steps", f.max_steps},
            {"interrupted", !trial.has_value()}});
  if (trial) {
    const loop::TrialRecord& r = trial->record;
    j.update(
        {{"believed_state", objects[r.believed_state]},
         {"steps", r.steps},
         {"discounted_reward", r.discounted_reward},
         {"collision", r.collision},
         {"capped", r.capped},
         {"final_action", problem.model->spec().action_names[trial->steps.back().record.action]}});
  }
  write_file_atomically(fs::path(f.out) / "trial.json", j.dump(2) + "\n");
}

void print_result(const RunFlags& f, const loop::Loop& run, const TrueObject& truth,
                  const loop::Trial& trial) {
  const pomdp::Problem& problem = run.spec().problem();
  const loop::TrialRecord& r = trial.record;
  if (r.collision)
    fmt::print("result: the trial ended in a collision after {} steps", r.steps);
  else if (r.capped)
    fmt::print("result: no sorting action within --max-steps {}", f.max_steps);
  else
    fmt::print("result: {} sorted by {} (believed {})", truth.world,
               problem.model->spec().action_names[trial.steps.back().record.action],
               loop::object_problem(*problem.model).data().objects[r.believed_state]);
  fmt::print("; {} steps, discounted reward {:.3f}\nfiles: {}\n", r.steps, r.discounted_reward,
             f.out);
}

void run_command(const RunFlags& f) {
  check_flags(f);
  const SimSetup setup = load_sim_setup(f.sim);
  const loop::SimulatedWorldSpec sim{std::make_shared<const sim::Catalogue>(setup.catalogue),
                                     std::make_shared<const sim::SimConfig>(setup.config)};
  const auto base = std::make_shared<const pomdp::Problem>(pomdp::load_problem(
      f.problem.empty() ? shipped_file("problems/audio_objects.yaml") : f.problem));
  const TrueObject truth =
      resolve_object(f.object, loop::object_problem(*base->model).data(), *sim.catalogue);

  const StopSignal stop;
  const loop::PreparedObservation prepared = prepare(f, *base, sim, stop);
  loop::Loop run(
      std::make_shared<const loop::LoopSpec>(loop_settings(f, prepared, base, sim, truth)));
  const pomdp::Problem& problem = run.spec().problem();
  // Only now that everything fits are files written.
  if (prepared.problem) loop::save_problem(problem, problem.source_path);
  const auto& objects = loop::object_problem(*problem.model).data().objects;
  loop::LoopLog log(f.out, loop::object_problem(*problem.model));

  fmt::print("{} {}, planning on {} ({}), seed {}\n", truth.world,
             f.recordings.empty() ? "in the simulator" : "replayed from " + f.recordings,
             problem.source_path, run.planner().describe(), f.seed);
  int logged = 0;
  const auto trial = run.run(
      {0, truth.index, loop::stream_seed(f.seed, loop::Stream::run_trial)},
      [&](const loop::Step& s) {
        if (s.record.step == 0)
          fmt::print("belief before the first action:\n{}",
                     loop::belief_text(objects, s.record.belief));
        fmt::print("{}\n", loop::step_text(s, problem.model->spec()));
        if (s.belief_after) fmt::print("{}", loop::belief_text(objects, *s.belief_after));
        log.write_step(s);
        ++logged;
      },
      &stop.flag());
  write_trial_json(f, run, truth, trial);
  if (!trial) {
    spdlog::warn("interrupted: {} finished steps are in {}", logged, f.out);
    throw Interrupted{};
  }
  print_result(f, run, truth, *trial);
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
