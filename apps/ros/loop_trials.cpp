#include "loop_trials.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>

#include "common/error.h"
#include "common/rng.h"
#include "experiment/loop_log.h"
#include "experiment/planner.h"
#include "pomdp/make_belief.h"
#include "pomdp/problem.h"

namespace echoplan::ros_app {

namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Wrappers that time the loop's latencies without changing what the parts do: when each action
// ended, and how long a recorder took to start (for ROS: parameter set -> listener capturing).
class TimedRobot final : public robot::Robot {
 public:
  explicit TimedRobot(std::unique_ptr<robot::Robot> inner) : inner_(std::move(inner)) {}
  void begin_trial(const robot::TrialContext& context) override { inner_->begin_trial(context); }
  robot::ActionReport execute(const std::string& action) override {
    robot::ActionReport report = inner_->execute(action);
    action_end = Clock::now();
    return report;
  }
  Clock::time_point action_end;

 private:
  std::unique_ptr<robot::Robot> inner_;
};

class TimedRecorder final : public robot::Recorder {
 public:
  explicit TimedRecorder(std::unique_ptr<robot::Recorder> inner) : inner_(std::move(inner)) {}
  void begin_trial(const robot::TrialContext& context) override { inner_->begin_trial(context); }
  void start(const std::string& action) override {
    const auto t0 = Clock::now();
    inner_->start(action);
    start_ms.push_back(ms_between(t0, Clock::now()));
  }
  audio::AudioClip stop() override { return inner_->stop(); }
  std::vector<double> start_ms;

 private:
  std::unique_ptr<robot::Recorder> inner_;
};

// A TrialObserver that says how each trial ended.
class TrialSayer final : public experiment::TrialObserver {
 public:
  TrialSayer(const pomdp::ModelSpec& spec, const std::function<void(const std::string&)>& say)
      : spec_(spec), say_(say) {}
  void trial_finished(const experiment::TrialRecord& r,
                      const std::vector<experiment::StepRecord>& steps) override {
    const std::string last = steps.empty() ? "-" : spec_.action_names[steps.back().action];
    say_(fmt::format(
        "trial {}: {} after {} steps ({}), discounted reward {:.3f}", r.trial,
        r.collision ? "collision"
        : r.capped  ? "no sorting action"
                    : "sorted by " + last,
        r.steps,
        r.collision || r.capped ? "" : "believed state " + std::to_string(r.believed_state),
        r.discounted_reward));
  }

 private:
  const pomdp::ModelSpec& spec_;
  const std::function<void(const std::string&)>& say_;
};

}  // namespace

std::vector<experiment::TrialRecord> run_loop_trials(
    const LoopTrialSettings& settings, experiment::RobotParts parts,
    const std::function<void(const std::string&)>& say, const std::atomic<bool>* stop_requested,
    LoopTimings* timings_out) {
  if (settings.out.empty()) throw InputError("", 0, "an output folder is required");
  const pomdp::Problem problem = pomdp::load_problem(settings.problem);
  solvers::PlannerOverrides overrides;
  overrides.solver = settings.solver;
  overrides.episodes = settings.episodes;
  overrides.step_ms = settings.step_ms;
  const experiment::Planner planner =
      experiment::make_planner(overrides, problem, settings.problem);

  auto timed_robot = std::make_unique<TimedRobot>(std::move(parts.robot));
  auto timed_recorder = std::make_unique<TimedRecorder>(std::move(parts.recorder));
  TimedRobot* robot_clock = timed_robot.get();
  TimedRecorder* recorder_clock = timed_recorder.get();
  parts.robot = std::move(timed_robot);
  parts.recorder = std::move(timed_recorder);
  experiment::RobotEnvironment environment(problem.model, std::move(parts));
  experiment::LoopLog log(settings.out, environment.model());
  experiment::LoopStep last;
  environment.set_step_listener([&](const experiment::LoopStep& s) {
    last = s;
    std::string line = fmt::format("trial {} step {}: {}", s.trial, s.step + 1, s.action_name);
    if (s.report.status != robot::ActionStatus::done)
      line += fmt::format(" -> {}: {}", robot::to_string(s.report.status), s.report.reason);
    else if (s.classified)
      line += fmt::format(" -> heard {} (p {:.2f}{}), {:.1f} ms to classify", s.heard.label,
                          s.heard.probability, s.heard.unknown ? ", unlike every class" : "",
                          s.observe_ms);
    say(line + fmt::format(", reward {:g}", s.reward));
  });

  experiment::TrialSetup setup;
  setup.model = problem.model.get();
  setup.environment = &environment;
  setup.solver = planner.solver.get();
  setup.make_belief = [&problem](Rng& rng) { return pomdp::make_belief(problem, rng); };
  setup.stop_requested = stop_requested;
  LoopTimings timings;
  setup.step_finished = [&](const experiment::StepRecord& s, const pomdp::Belief* after) {
    std::vector<double> marginal;
    if (after) marginal = after->discrete_marginal(0);
    // The runner calls this right after the belief update: the end of the round trip.
    if (after && last.classified) {
      timings.action_end_to_belief_ms.push_back(ms_between(robot_clock->action_end, Clock::now()));
      timings.observe_ms.push_back(last.observe_ms);
    }
    log.write_step(last, s.belief, after ? &marginal : nullptr);
  };
  experiment::TrialOptions options;
  options.trials = settings.trials;
  options.budget = planner.budget;
  options.max_steps = settings.max_steps;
  options.seed = settings.seed;
  options.validate();
  say(fmt::format("planning on {} ({}), {} trial(s), seed {}", settings.problem, planner.describe(),
                  settings.trials, settings.seed));
  TrialSayer sayer(problem.model->spec(), say);
  std::vector<experiment::TrialRecord> records;
  if (settings.object.empty()) {
    records = experiment::run_trials(setup, options, sayer);
  } else {
    const auto& objects = environment.model().data().objects;
    const auto it = std::find(objects.begin(), objects.end(), settings.object);
    if (it == objects.end())
      throw InputError("", 0,
                       fmt::format("object '{}' is not one of the problem's ({})", settings.object,
                                   fmt::join(objects, ", ")));
    // `echoplan run`'s trial stream (apps/echoplan/commands/run.cpp: derive_seed(seed, {2})).
    constexpr std::uint64_t kRunTrialStream = 2;
    options.seed = derive_seed(settings.seed, {kRunTrialStream});
    for (int t = 0; t < settings.trials; ++t) {
      auto result =
          experiment::run_trial(setup, options, t, static_cast<int>(it - objects.begin()));
      if (!result) break;
      sayer.trial_finished(result->record, result->steps);
      records.push_back(result->record);
    }
  }
  timings.capture_start_ms = recorder_clock->start_ms;
  if (!timings.observe_ms.empty())
    say(
        fmt::format("latency, median of {} sensing steps: end of action -> belief updated {:.2f} "
                    "ms, of which the "
                    "observation service call {:.2f} ms; recorder start {:.2f} ms",
                    timings.observe_ms.size(), median(timings.action_end_to_belief_ms),
                    median(timings.observe_ms), median(timings.capture_start_ms)));
  if (timings_out) *timings_out = std::move(timings);
  return records;
}

}  // namespace echoplan::ros_app
