// `echoplan run`: one trial of the whole loop, printed as it goes: the planner picks an action, the
// (simulated) robot executes it while the recorder listens, the classifier says what it heard, the
// belief is updated, until the robot sorts the object. Everything is saved per step in DIR.
#include <fmt/core.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "commands/noise_options.h"
#include "commands/planner_options.h"
#include "commands/sim_options.h"
#include "common/data_dir.h"
#include "common/error.h"
#include "common/stop_signal.h"
#include "loop/calibrated_problem.h"
#include "loop/dataset_world.h"
#include "loop/loop.h"
#include "loop/loop_log.h"
#include "loop/object_problem.h"
#include "loop/prepare_observation.h"
#include "loop/step_text.h"
#include "loop/streams.h"
#include "perception/feature_set.h"
#include "perception/observation_model_json.h"
#include "perception/performance_reader.h"
#include "perception/recording_features.h"
#include "pomdp/problem.h"

namespace echoplan::cli {

namespace {

namespace fs = std::filesystem;

struct RunFlags {
  std::string object;
  std::string problem;     // empty: the shipped problem with the model's calibrated table
  std::string model;       // empty: train one on freshly synthesised recordings
  std::string recordings;  // non-empty: replay these instead of simulating
  std::string data;        // non-empty: replay this session of recorded data (replay_session)
  std::string session;
  std::string uses = "session";  // with data: whose use limits the planner plans with
  std::string groups;
  std::uint64_t seed = 1;
  int max_steps = 100;
  int train_per_pair = 10;
  std::string out;
  SimFiles sim;
  NoiseFlags noise;
  solvers::PlannerOverrides planner;
};

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
  loop::SimulatedTraining training = loop::training_for(
      loop::object_problem(*base.model).data(), sim.catalogue, sim.config, f.train_per_pair,
      loop::stream_seed(f.seed, loop::Stream::run_training), fs::path(f.out) / "training");
  training.save_to = (fs::path(f.out) / "model.json").string();
  spdlog::info("no --model: training {} on {} simulated recordings per object and action in {}",
               training.train.classifier, training.per_pair, training.directory.string());
  auto prepared = loop::prepare_observation(
      training, calibrate, problem_path,
      [](const std::string& stage, int done, int total) {
        if (done == total || done % 20 == 0) spdlog::info("  {} {}/{}", stage, done, total);
      },
      stop.flag());
  if (!prepared.model) throw Interrupted{};
  for (const auto& action : prepared.model->actions())
    spdlog::info("  {}: cross-validated accuracy {:.0f}%", action,
                 100.0 * prepared.model->calibration(action).confusion.accuracy());
  spdlog::info("saved {} (reuse it with --model)", training.save_to);
  return prepared;
}

// The loop: the planning problem in the simulator or replaying --recordings.
loop::LoopSettings loop_settings(const RunFlags& f, const loop::PreparedObservation& prepared,
                                 std::shared_ptr<const pomdp::Problem> base,
                                 const loop::SimulatedWorldSpec& sim, const loop::TrueObject& truth,
                                 std::optional<robot::WorldNoise> noise) {
  loop::LoopSettings s;
  s.problem = prepared.problem ? prepared.problem : std::move(base);
  s.world = f.recordings.empty() ? loop::WorldSpec{sim} : loop::ReplayWorldSpec{f.recordings};
  s.observation_model = prepared.model;
  s.noise = std::move(noise);
  s.world_objects = loop::world_objects_for(truth, loop::object_problem(*s.problem->model).data());
  s.planner = f.planner;
  s.max_steps = f.max_steps;
  return s;
}

// What trial.json says the run was asked to do.
nlohmann::json run_settings(const RunFlags& f, const loop::Loop& run, const loop::TrueObject& truth,
                            const loop::SimulatedWorldSpec& sim) {
  const pomdp::Problem& problem = run.spec().problem();
  nlohmann::json j = run.planner().to_json();
  j.update({{"object", truth.world},
            {"true_state", loop::object_problem(*problem.model).data().objects[truth.index]},
            {"world", loop::world_name(run.spec().settings().world)},
            {"recordings", f.recordings},
            {"problem", problem.source_path},
            {"model", f.model.empty() ? (fs::path(f.out) / "model.json").string() : f.model},
            {"seed", f.seed},
            {"max_steps", f.max_steps}});
  if (!f.noise.sources.empty())
    j["noise"] = {{"sources", f.noise.sources}, {"ebr_db", f.noise.ebr}};
  // The simulator's table: the lab's unless one was chosen (the trial then names it itself).
  if (f.recordings.empty()) j["surface"] = sim.catalogue->table.name;
  return j;
}

// The session to replay and its place among its object's sessions (the trial's index).
struct SessionChoice {
  int session = 0;
  int index = 0;
};

SessionChoice find_session(const perception::FeatureSet& data, const RunFlags& f) {
  const int object = data.object_index(f.object);
  if (object < 0)
    throw InputError(f.data, 0,
                     fmt::format("--object '{}' is not an object of the data (objects: {})",
                                 f.object, fmt::join(data.objects, ", ")));
  std::vector<std::string> names;
  for (std::size_t s = 0; s < data.sessions.size(); ++s) {
    if (data.sessions[s].object != object) continue;
    if (data.sessions[s].name == f.session)
      return {static_cast<int>(s), static_cast<int>(names.size())};
    names.push_back(data.sessions[s].name);
  }
  throw InputError(f.data, 0,
                   fmt::format("--session '{}' is not a session of '{}' (its sessions: {})",
                               f.session, f.object, fmt::join(names, ", ")));
}

// The problem's class of the object: the object itself, or its group (--groups).
int true_class(const RunFlags& f, const pomdp::ObjectProblemData& problem) {
  std::string name = f.object;
  if (!f.groups.empty()) {
    const perception::ObjectGroups groups = perception::load_groups(f.groups);
    const std::string* group = groups.group_of(f.object);
    if (group == nullptr)
      throw InputError(f.groups, 0, fmt::format("object '{}' has no group here", f.object));
    name = *group;
  }
  for (std::size_t k = 0; k < problem.objects.size(); ++k)
    if (problem.objects[k] == name) return static_cast<int>(k);
  throw InputError(
      f.problem, 0,
      fmt::format("'{}' is not a class of the problem (classes: {}){}", name,
                  fmt::join(problem.objects, ", "),
                  f.groups.empty() ? "; give --groups when the classes are groups" : ""));
}

// The problem with each sensing action limited to what the session recorded, as a campaign's
// trial plans with it; with `limits` "problem", the problem as it is.
std::shared_ptr<const pomdp::Problem> session_problem(const pomdp::Problem& base,
                                                      const perception::FeatureSet& data,
                                                      int session, const std::string& limits) {
  const auto* object_model = base.model->object_identification();
  if (object_model == nullptr)
    throw InputError(base.source_path, 0,
                     "not an object-identification problem (`train --problem-out` writes one)");
  if (limits == "problem") return std::make_shared<const pomdp::Problem>(base);
  pomdp::ObjectProblemData limited = object_model->data();
  const std::vector<int> uses = loop::session_uses(limited, data, session);
  for (std::size_t a = 0; a < uses.size(); ++a) limited.sensing[a].uses = uses[a];
  auto problem = std::make_shared<pomdp::Problem>(base);
  problem->model = std::make_shared<const pomdp::ObjectIdentificationModel>(std::move(limited));
  return problem;
}

nlohmann::json replay_settings(const RunFlags& f, const loop::Loop& run, int index) {
  nlohmann::json j = run.planner().to_json();
  j.update({{"object", f.object},
            {"session", f.session},
            {"trial_index", index},
            {"world", "dataset"},
            {"data", f.data},
            {"problem", f.problem},
            {"model", f.model},
            {"seed", f.seed},
            {"max_steps", f.max_steps}});
  return j;
}

// Replays the session and prints each step. The trial's random streams come from (seed, the
// session's place among the object's sessions): with a campaign's trials.csv seed and the arm's
// solver it logs the campaign trial's steps.
void replay_session(const RunFlags& f) {
  if (f.model.empty() || f.problem.empty())
    throw InputError(
        "--data needs --model (`echoplan train --data TRAINING --out MODEL`) and --problem (its "
        "--problem-out)");
  std::error_code ec;
  fs::create_directories(f.out, ec);
  if (ec) throw InputError(f.out, 0, "cannot create the output folder: " + ec.message());
  const pomdp::Problem base = pomdp::load_problem(f.problem);
  auto model = std::make_shared<const perception::ObservationModel>(
      perception::load_observation_model(f.model));
  // A recordings tree's series become rows as the model's did.
  const bool tree = perception::data_kind(f.data) == perception::DataKind::recordings;
  auto data = std::make_shared<const perception::FeatureSet>(perception::load_data(
      f.data, {}, tree ? perception::series_choices(*model) : perception::SeriesChoices{}));
  const SessionChoice choice = find_session(*data, f);
  loop::LoopSettings s;
  s.problem = session_problem(base, *data, choice.session, f.uses);
  s.world = loop::DatasetWorldSpec{data, model, choice.session};
  s.planner = f.planner;
  s.max_steps = f.max_steps;
  const auto& problem_data = s.problem->model->object_identification()->data();
  const int truth = true_class(f, problem_data);
  loop::Loop run(std::make_shared<const loop::LoopSpec>(std::move(s)));
  const pomdp::Problem& problem = run.spec().problem();
  loop::LoopLog log(f.out, *problem.model->object_identification());
  fmt::print("{}, session {}, replayed from {} with {}, planning on {} ({}), seed {}\n", f.object,
             f.session, f.data, f.model, f.problem, run.planner().describe(), f.seed);
  const StopSignal stop;
  const auto trial = run.run(
      {choice.index, truth, f.seed},
      [&](const loop::Step& step) {
        fmt::print("{}", loop::step_report(step, problem.model->spec()));
        log.write_step(step);
      },
      &stop.flag());
  log.write_trial(replay_settings(f, run, choice.index), trial);
  if (!trial) {
    spdlog::warn("interrupted: {} finished steps are in {}", log.steps_written(), f.out);
    throw Interrupted{};
  }
  fmt::print("result: {} {}\nfiles: {}\n", f.object,
             loop::trial_text(*trial, problem.model->spec()), f.out);
}

// --data: one recorded session instead of the simulator or a recordings folder.
void run_recorded(const RunFlags& f) {
  if (!f.recordings.empty()) throw InputError("--data and --recordings are two worlds: give one");
  if (!f.noise.sources.empty())
    throw InputError(
        "--noise is heard by the simulator and --recordings; recorded features are heard as "
        "recorded (for a recordings tree, write a noisy copy with `echoplan add-noise`)");
  if (f.session.empty()) throw InputError("--data needs --session: the session to replay");
  replay_session(f);
}

void run_command(const RunFlags& f) {
  if (!f.data.empty()) return run_recorded(f);
  if (!f.session.empty() || !f.groups.empty())
    throw InputError("--session and --groups replay recorded data: give --data too");
  check_flags(f);
  std::optional<robot::WorldNoise> noise = world_noise(f.noise);  // read before any training
  const loop::SimulatedWorldSpec sim = load_simulated_world(f.sim, f.seed);
  const auto base = std::make_shared<const pomdp::Problem>(pomdp::load_problem(
      f.problem.empty() ? shipped_file("problems/audio_objects.yaml") : f.problem));
  const loop::TrueObject truth = loop::resolve_true_object(
      f.object, loop::object_problem(*base->model).data(), *sim.catalogue);

  const StopSignal stop;
  const loop::PreparedObservation prepared = prepare(f, *base, sim, stop);
  loop::Loop run(std::make_shared<const loop::LoopSpec>(
      loop_settings(f, prepared, base, sim, truth, std::move(noise))));
  const pomdp::Problem& problem = run.spec().problem();
  // Only now that everything fits are files written.
  if (prepared.problem) loop::save_problem(problem, problem.source_path);
  loop::LoopLog log(f.out, loop::object_problem(*problem.model));

  fmt::print("{} {}{}, planning on {} ({}), seed {}\n", truth.world,
             f.recordings.empty() ? "in the simulator" : "replayed from " + f.recordings,
             f.noise.sources.empty()
                 ? ""
                 : fmt::format(" through {} at {} dB EBR", fmt::join(f.noise.sources, " and "),
                               f.noise.ebr),
             problem.source_path, run.planner().describe(), f.seed);
  const auto trial = run.run(
      {0, truth.index, loop::stream_seed(f.seed, loop::Stream::run_trial)},
      [&](const loop::Step& s) {
        fmt::print("{}", loop::step_report(s, problem.model->spec()));
        log.write_step(s);
      },
      &stop.flag());
  log.write_trial(run_settings(f, run, truth, sim), trial);
  if (!trial) {
    spdlog::warn("interrupted: {} finished steps are in {}", log.steps_written(), f.out);
    throw Interrupted{};
  }
  fmt::print("result: {} {}\nfiles: {}\n", truth.world,
             loop::trial_text(*trial, problem.model->spec()), f.out);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto flags = std::make_shared<RunFlags>();
  auto* cmd = app.add_subcommand(
      "run",
      R"(One trial of the whole loop: plan, act (simulated robot or replayed recordings), listen, classify,
update the belief, until the object is sorted. Prints each step and the belief; writes per step
the clip, the features, the observation, the belief and the reward to DIR (see docs/loop.md).
Without --model, trains one first on --train-per-pair simulated recordings per object and action
and plans on the shipped problem with that model's calibrated table (both saved in DIR).
Examples:
  echoplan run --object coffee_mug --out runs/mug
  echoplan run --object coffee_mug_weighted --model runs/mug/model.json --out runs/heavy_mug
  echoplan run --object plastic_cup --model model.json --recordings recordings/ --out runs/replay
  echoplan run --object coffee_mug --model model.json --noise /usr/share/asterisk/sounds/en_US_f_Allison --ebr 0 --out runs/talk
  echoplan run --data features --object mug3 --session 2 --model model.json --problem dataset.yaml --out runs/mug3
With --data, the session's recorded performances are replayed as a dataset campaign replays
them, and --seed is the trial's seed (a campaign's trials.csv `seed` column).)");
  cmd->add_option("--object", flags->object,
                  "The true object: one of the problem's, or a catalogue variant of one (e.g. "
                  "coffee_mug_weighted); with --data, an object of the data")
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
  cmd->add_option("--data", flags->data,
                  "Replay a session of recorded data (a feature set or a recordings tree) with "
                  "--model and --problem (`echoplan train --out MODEL --problem-out FILE`)");
  cmd->add_option("--session", flags->session, "With --data: the session of --object to replay");
  cmd->add_option(
         "--uses", flags->uses,
         "With --data: the use limits the planner plans with: 'session' (what the session "
         "recorded, as a campaign's trial) or 'problem' (the problem file's, as a live run "
         "planned: for a bag of a live run, which holds only what it used)")
      ->check(CLI::IsMember({"session", "problem"}))
      ->capture_default_str();
  cmd->add_option("--groups", flags->groups,
                  "With --data: groups file (object,group), when the problem's classes are groups");
  cmd->add_option("--seed", flags->seed, "Seed of every random choice")->capture_default_str();
  cmd->add_option("--max-steps", flags->max_steps, "Stop the trial after this many steps")
      ->capture_default_str();
  cmd->add_option("--train-per-pair", flags->train_per_pair,
                  "Without --model: simulated training recordings per object and action")
      ->capture_default_str();
  cmd->add_option("--out", flags->out, "Folder for the clips, loop_steps.csv/.jsonl, trial.json")
      ->required();
  add_sim_file_options(*cmd, flags->sim);
  add_noise_options(*cmd, flags->noise, false);
  add_planner_options(*cmd, flags->planner);
  cmd->callback([flags] { run_command(*flags); });
}

}  // namespace echoplan::cli
