#include "loop/robot_world.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "audio/levels.h"
#include "common/error.h"
#include "loop/object_problem.h"
#include "perception/observation_grades.h"
#include "robot/transient_error.h"

namespace echoplan::loop {

namespace {

constexpr const char* kUnknownSymbol = "unknown";

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Runs `part` and returns the message of a failure of this call alone (robot/transient_error.h: a
// device gone, a service timed out); none when it succeeded. Anything else goes on up.
template <typename Part>
std::optional<std::string> transient_failure(Part&& part) {
  try {
    part();
  } catch (const robot::TransientError& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

}  // namespace

RobotWorld::RobotWorld(pomdp::ModelPtr model, RobotParts parts,
                       std::map<std::string, std::string> world_objects)
    : model_(std::move(model)), parts_(std::move(parts)), world_objects_(std::move(world_objects)) {
  if (!model_ || !parts_.robot || !parts_.service)
    throw std::invalid_argument("RobotWorld: a model, a robot and a service are all needed");
  problem_ = &object_problem(*model_);
  const pomdp::ObjectProblemData& data = problem_->data();
  for (std::size_t i = 0; i < data.observation_symbols.size(); ++i)
    symbol_index_[data.observation_symbols[i]] = static_cast<int>(i);
  for (const auto& [object, world] : world_objects_)
    if (!contains(data.objects, object))
      throw InputError(
          fmt::format("object variant '{}' stands for '{}', which is not an object of problem '{}' "
                      "(objects: {})",
                      world, object, data.name, fmt::join(data.objects, ", ")));

  // A service that says what it reports is checked now, so no trial starts with a mismatch.
  const auto vocabulary = parts_.service->vocabulary();
  if (!vocabulary) return;
  std::vector<std::string> trained;
  for (const auto& [action, labels] : vocabulary->labels) trained.push_back(action);
  for (const auto& act : data.sensing) {
    const auto it = vocabulary->labels.find(act.name);
    if (it == vocabulary->labels.end())
      throw InputError(fmt::format(
          "the observation model has no classifier for sensing action '{}' of problem "
          "'{}' (it was trained for: {}); train it on recordings of every sensing action",
          act.name, data.name, fmt::join(trained, ", ")));
    for (const std::string& label : it->second)
      if (!symbol_index_.count(label) && !symbol_index_.count(perception::graded_name(label, 0)) &&
          !symbol_index_.count(
              perception::graded_name(label, 0, perception::ObservationKind::levels)))
        throw InputError(
            fmt::format("the observation model reports '{}' for '{}', which is not an observation "
                        "symbol of problem '{}' (symbols: {}); the model was trained for other "
                        "objects - plan on the problem `echoplan train --problem-out` wrote for it",
                        label, act.name, data.name, fmt::join(data.observation_symbols, ", ")));
    for (const std::string& symbol : data.observation_symbols) {
      if (symbol != kUnknownSymbol && !contains(it->second, perception::class_of_symbol(symbol)))
        throw InputError(fmt::format(
            "problem '{}' expects to hear '{}' after '{}', but the observation model was "
            "not trained for it (its classes: {}); train it on recordings of the "
            "problem's objects",
            data.name, symbol, act.name, fmt::join(it->second, ", ")));
      if (symbol != perception::class_of_symbol(symbol) && !vocabulary->grades &&
          !vocabulary->levels)
        throw InputError(fmt::format(
            "problem '{}' plans with graded observations ('{}'), but the observation model does "
            "not grade what it hears (trained before grades existed): train it again, or plan "
            "with `observations: labels`",
            data.name, symbol));
    }
  }
  if (vocabulary->may_report_unknown && !symbol_index_.count(kUnknownSymbol))
    throw InputError(fmt::format(
        "the observation model can report 'unknown' (its reject option is on) but problem "
        "'{}' has no 'unknown' observation symbol; plan on the problem `echoplan train "
        "--problem-out` wrote, or train without the reject option",
        data.name));
}

void RobotWorld::reset(const pomdp::State& true_state, Rng& rng) {
  const pomdp::ObjectProblemData& data = problem_->data();
  if (true_state.discrete.empty() || true_state.discrete[0] < 0 ||
      true_state.discrete[0] >= static_cast<int>(data.objects.size()))
    throw std::invalid_argument("RobotWorld::reset: the state names no object of the problem");
  state_ = true_state;
  const std::string& object = data.objects[state_.discrete[0]];
  const auto variant = world_objects_.find(object);
  world_object_ = variant == world_objects_.end() ? object : variant->second;
  ++trial_;
  robot::TrialContext context;
  context.trial = trial_;
  context.object = world_object_;
  context.seed = rng();
  parts_.robot->begin_trial(context);
  if (parts_.recorder) parts_.recorder->begin_trial(context);
  ended_ = false;
}

std::optional<pomdp::Observation> RobotWorld::symbol_for(
    const robot::HeardObservation& heard) const {
  const std::string label = heard.unknown ? std::string(kUnknownSymbol) : heard.label;
  // A graded problem hears `<label>@<grade>`, a levels problem `<label>@<level>`; a problem of
  // labels the label alone.
  auto it = symbol_index_.end();
  if (!heard.unknown && heard.level_grade >= 0 && heard.level_grade < perception::kGrades)
    it = symbol_index_.find(
        perception::graded_name(label, heard.level_grade, perception::ObservationKind::levels));
  if (it == symbol_index_.end() && !heard.unknown && heard.grade >= 0 &&
      heard.grade < perception::kGrades)
    it = symbol_index_.find(perception::graded_name(label, heard.grade));
  if (it == symbol_index_.end()) it = symbol_index_.find(label);
  if (it == symbol_index_.end()) return std::nullopt;
  pomdp::Observation o;
  o.index = it->second;
  return o;
}

WorldStep RobotWorld::execute(int action, Rng& /*rng*/) {
  if (ended_) throw std::logic_error("RobotWorld::execute after the trial ended; call reset()");
  if (action < 0 || action >= problem_->num_actions())
    throw std::out_of_range("RobotWorld: no such action");
  const pomdp::ObjectProblemData& data = problem_->data();
  const int object = state_.discrete[0];
  const std::string& name = model_->spec().action_names[action];

  WorldStep step;
  pomdp::Outcome& outcome = step.outcome;
  RobotStep& acted = step.robot.emplace();
  outcome.observation.index = problem_->none_symbol();
  // No microphone: no clip for the service, which observes through the robot's other sensors.
  const bool sensing = problem_->is_sensing(action);
  perform(acted, name, sensing && parts_.recorder != nullptr);
  const bool failed = acted.report.status == robot::ActionStatus::failed;
  if (failed || (sensing && acted.report.status == robot::ActionStatus::collision)) {
    // A collision while sensing or a failed action ends the trial as the model's collision does:
    // an object the arm did not put in its bin is not sorted. (A sort that touched something on
    // its way still put the object in the bin, as the model's sorting actions have it.)
    outcome.reward = data.collision_reward;
    outcome.terminal = true;
    if (failed)
      acted.fault = StepFault{"action failed",
                              fmt::format("{} ({} attempt{})", acted.report.reason, acted.attempts,
                                          acted.attempts == 1 ? "" : "s"),
                              FaultEffect::trial_failed};
  } else if (!sensing) {
    outcome.reward = data.sorting_reward[action - problem_->num_sensing()][object];
    outcome.terminal = true;
  } else {
    hear(acted, name, outcome);
    outcome.reward = data.sensing[action].reward;
    // The model's kinematic transition, so the true state follows the world (a slide moves the
    // object).
    const auto& change = data.sensing[action].offset_change;
    if (state_.continuous.size() == pomdp::ObjectIdentificationModel::kNumContinuous)
      for (int i = 0; i < 3; ++i)
        state_.continuous[pomdp::ObjectIdentificationModel::kOffsetX + i] += change[i];
  }
  outcome.collision = acted.report.status != robot::ActionStatus::done;
  ended_ = outcome.terminal;
  return step;
}

void RobotWorld::perform(RobotStep& acted, const std::string& action, bool record) {
  for (acted.attempts = 1;; ++acted.attempts) {
    // Only the last attempt's recording is kept.
    acted.fault.reset();
    acted.recorded = false;
    acted.clip = {};
    acted.capture = {};
    std::optional<std::string> lost;
    if (record) lost = transient_failure([&] { parts_.recorder->start(action); });
    acted.report = parts_.robot->execute(action);
    if (record && !lost) {
      lost = transient_failure([&] { acted.clip = parts_.recorder->stop(); });
      acted.capture = parts_.recorder->capture_report();
      acted.recorded = !lost;
    }
    // A recorder that failed leaves the action done but unheard; the next step starts it anew
    // (a device that came back records again).
    if (lost) acted.fault = StepFault{"recorder failed", *lost, FaultEffect::observation_skipped};
    const bool again = acted.report.status == robot::ActionStatus::failed &&
                       acted.report.retry_safe && acted.attempts < kMaxAttempts;
    if (!again) return;
  }
}

void RobotWorld::hear(RobotStep& acted, const std::string& action, pomdp::Outcome& outcome) {
  if (acted.recorded && !acted.fault)
    acted.fault = check_recording(acted.clip, acted.report, acted.capture, parts_.checks);
  if (acted.fault) return;
  // What the latency target measures: from the clip in hand to the planner's observation.
  const auto heard_from = std::chrono::steady_clock::now();
  if (auto failed =
          transient_failure([&] { acted.heard = parts_.service->observe(acted.clip, action); })) {
    acted.fault =
        StepFault{"observation service failed", *failed, FaultEffect::observation_skipped};
    return;
  }
  const auto symbol = symbol_for(acted.heard);
  if (!symbol) {
    const auto& data = problem_->data();
    acted.fault = StepFault{
        "class unknown to the problem",
        fmt::format("the service heard '{}', not an observation symbol of problem '{}' (symbols: "
                    "{})",
                    acted.heard.unknown ? kUnknownSymbol : acted.heard.label, data.name,
                    fmt::join(data.observation_symbols, ", ")),
        FaultEffect::observation_skipped};
    return;
  }
  outcome.observation = *symbol;
  acted.observe_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - heard_from)
          .count();
  acted.classified = true;
  outcome.heard_probability = acted.heard.probability;
  if (acted.clip.frames() > 0) outcome.heard_ebr_db = audio::measured_ebr_db(acted.clip);
}

}  // namespace echoplan::loop
