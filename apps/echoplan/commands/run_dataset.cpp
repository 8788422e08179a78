#include "commands/run_dataset.h"

#include <fmt/core.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "common/error.h"
#include "common/stop_signal.h"
#include "loop/dataset_world.h"
#include "loop/loop.h"
#include "loop/loop_log.h"
#include "loop/step_text.h"
#include "perception/feature_set.h"
#include "perception/observation_model_json.h"
#include "perception/recording_features.h"
#include "pomdp/problem.h"

namespace echoplan::cli {
namespace {

namespace fs = std::filesystem;

// The session to replay and its place among its object's sessions (the trial's index).
struct SessionChoice {
  int session = 0;
  int index = 0;
};

SessionChoice find_session(const perception::FeatureSet& data, const RunDatasetFlags& f) {
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
int true_class(const RunDatasetFlags& f, const pomdp::ObjectProblemData& problem) {
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
// trial plans with it.
std::shared_ptr<const pomdp::Problem> session_problem(const pomdp::Problem& base,
                                                      const perception::FeatureSet& data,
                                                      int session) {
  const auto* object_model = base.model->object_identification();
  if (object_model == nullptr)
    throw InputError(base.source_path, 0,
                     "not an object-identification problem (`train --problem-out` writes one)");
  pomdp::ObjectProblemData limited = object_model->data();
  const std::vector<int> uses = loop::session_uses(limited, data, session);
  for (std::size_t a = 0; a < uses.size(); ++a) limited.sensing[a].uses = uses[a];
  auto problem = std::make_shared<pomdp::Problem>(base);
  problem->model = std::make_shared<const pomdp::ObjectIdentificationModel>(std::move(limited));
  return problem;
}

nlohmann::json trial_settings(const RunDatasetFlags& f, const loop::Loop& run, int index) {
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

}  // namespace

void run_dataset_session(const RunDatasetFlags& f) {
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
  auto data = std::make_shared<const perception::FeatureSet>(perception::load_data(f.data));
  const SessionChoice choice = find_session(*data, f);
  loop::LoopSettings s;
  s.problem = session_problem(base, *data, choice.session);
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
  log.write_trial(trial_settings(f, run, choice.index), trial);
  if (!trial) {
    spdlog::warn("interrupted: {} finished steps are in {}", log.steps_written(), f.out);
    throw Interrupted{};
  }
  fmt::print("result: {} {}\nfiles: {}\n", f.object,
             loop::trial_text(*trial, problem.model->spec()), f.out);
}

}  // namespace echoplan::cli
