#include "loop_trials.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>

#include "common/error.h"
#include "loop/loop.h"
#include "loop/loop_log.h"
#include "loop/object_problem.h"
#include "loop/step_text.h"
#include "loop/streams.h"
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

// The loop over the caller's parts, each wrapped to time the latencies.
loop::LoopSettings loop_settings(const LoopTrialSettings& settings, loop::RobotParts parts,
                                 TimedRobot*& robot_clock, TimedRecorder*& recorder_clock) {
  auto timed_robot = std::make_unique<TimedRobot>(std::move(parts.robot));
  robot_clock = timed_robot.get();
  parts.robot = std::move(timed_robot);
  if (parts.recorder) {  // none: a robot without a microphone
    auto timed_recorder = std::make_unique<TimedRecorder>(std::move(parts.recorder));
    recorder_clock = timed_recorder.get();
    parts.recorder = std::move(timed_recorder);
  }
  // The parts exist once: the one loop built from these settings takes them.
  auto shared = std::make_shared<loop::RobotParts>(std::move(parts));
  loop::LoopSettings s;
  s.problem = std::make_shared<const pomdp::Problem>(pomdp::load_problem(settings.problem));
  s.world = loop::PartsWorldSpec{[shared] { return std::move(*shared); }, "robot"};
  s.planner.solver = settings.solver;
  s.planner.episodes = settings.episodes;
  s.planner.step_ms = settings.step_ms;
  s.max_steps = settings.max_steps;
  return s;
}

}  // namespace

std::vector<loop::TrialRecord> run_loop_trials(const LoopTrialSettings& settings,
                                               loop::RobotParts parts,
                                               const std::function<void(const std::string&)>& say,
                                               const std::atomic<bool>* stop_requested,
                                               LoopTimings* timings_out) {
  if (settings.out.empty()) throw InputError("", 0, "an output folder is required");
  if (settings.trials < 1) throw InputError("--trials must be >= 1");
  TimedRobot* robot_clock = nullptr;
  TimedRecorder* recorder_clock = nullptr;
  loop::Loop trials(std::make_shared<const loop::LoopSpec>(
      loop_settings(settings, std::move(parts), robot_clock, recorder_clock)));
  const pomdp::Problem& problem = trials.spec().problem();
  loop::LoopLog log(settings.out, loop::object_problem(*problem.model));
  // With an object, the streams of `echoplan run --object` (loop/streams.h); without, the trial's
  // object is drawn from the initial belief.
  const int object = settings.object.empty() ? -1 : loop::object_index(problem, settings.object);
  const std::uint64_t seed = settings.object.empty()
                                 ? settings.seed
                                 : loop::stream_seed(settings.seed, loop::Stream::run_trial);
  say(fmt::format("planning on {} ({}), {} trial(s), seed {}", settings.problem,
                  trials.planner().describe(), settings.trials, settings.seed));
  LoopTimings timings;
  const auto on_step = [&](const loop::Step& s) {
    // Called right after the belief update: the end of the round trip.
    if (s.belief_after && s.robot && s.robot->classified) {
      timings.action_end_to_belief_ms.push_back(ms_between(robot_clock->action_end, Clock::now()));
      timings.observe_ms.push_back(s.robot->observe_ms);
    }
    say(fmt::format("trial {} {}", s.record.trial, loop::step_text(s, problem.model->spec())));
    log.write_step(s);
  };
  std::vector<loop::TrialRecord> records;
  for (int t = 0; t < settings.trials; ++t) {
    const auto trial = trials.run({t, object, seed}, on_step, stop_requested);
    if (!trial) break;
    say(fmt::format("trial {}: {}", t, loop::trial_text(*trial, problem.model->spec())));
    records.push_back(trial->record);
  }
  if (recorder_clock) timings.capture_start_ms = recorder_clock->start_ms;
  if (!timings.observe_ms.empty())
    say(fmt::format(
        "latency, median of {} sensing steps: end of action -> belief updated {:.2f} ms, of which "
        "the observation service call {:.2f} ms{}",
        timings.observe_ms.size(), median(timings.action_end_to_belief_ms),
        median(timings.observe_ms),
        recorder_clock ? fmt::format("; recorder start {:.2f} ms", median(timings.capture_start_ms))
                       : std::string()));
  if (timings_out) *timings_out = std::move(timings);
  return records;
}

}  // namespace echoplan::ros_app
