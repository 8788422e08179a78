// Faults injected into the running loop through its seams (robot, recorder, observation service;
// faulty_parts.h): what the step says, what the loop does, and that trials the fault did not touch
// run as without it. docs/real-robot.md's fault table states what these tests assert.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "faulty_parts.h"
#include "loop/loop.h"
#include "loop/loop_log.h"
#include "loop/robot_world.h"
#include "loop/trial_runner.h"
#include "pomdp/particle_belief.h"
#include "solvers/abt_solver.h"
#include "solvers/planner_overrides.h"

namespace echoplan::loop {
namespace {

namespace fs = std::filesystem;
using namespace test;

constexpr int kSlide = 0, kStrike = 1;

std::shared_ptr<const pomdp::Problem> problem() {
  static const auto p = calibrated(mug_or_cup());
  return p;
}

const pomdp::ObjectIdentificationModel& identification() {
  return *problem()->model->object_identification();
}

// A world of faulty parts with its first trial begun (the mug).
struct World {
  explicit World(Faults faults)
      : world(problem()->model, faulty_parts(identification(), std::move(faults))) {
    Rng rng(5);
    pomdp::State mug = problem()->model->sample_initial_state(rng);
    mug.discrete[0] = 0;
    world.reset(mug, rng);
  }
  WorldStep execute(int action) {
    Rng rng(1);
    return world.execute(action, rng);
  }
  RobotWorld world;
};

// The fault on the first call of a trial only: the device comes back for the next one.
template <typename Fault>
std::function<std::optional<Fault>(Call)> first_call(Fault fault) {
  return [fault](Call c) { return c.call == 0 ? std::optional<Fault>(fault) : std::nullopt; };
}

// ---- the recording ---------------------------------------------------------------------------

struct RecordingCase {
  std::string name;
  RecordingFault fault;
  RecordingChecks checks;
  std::string kind;  // the fault the step must carry
};

RecordingChecks live() {
  RecordingChecks c;
  c.live = true;
  c.sample_rate = 44100;
  c.channels = 2;
  return c;
}

std::vector<RecordingCase> recording_cases() {
  std::vector<RecordingCase> cases;
  const auto change = [](std::function<void(audio::AudioClip&)> f) {
    RecordingFault fault;
    fault.change_clip = std::move(f);
    return fault;
  };
  cases.push_back({"empty", change([](auto& c) { c.samples.clear(); }), {}, "recording empty"});
  cases.push_back({"silent",
                   change([](auto& c) { std::fill(c.samples.begin(), c.samples.end(), 0.0f); }),
                   live(), "recording silent"});
  cases.push_back({"clipped", change([](auto& c) {
                     for (float& s : c.samples) s = std::clamp(s * 1e4f, -1.0f, 1.0f);
                   }),
                   live(), "recording clipped"});
  // 50 ms from the loudest sample on: sound, but far less than the action.
  cases.push_back(
      {"short", change([](auto& c) {
         const auto loudest =
             std::max_element(c.samples.begin(), c.samples.end(),
                              [](float a, float b) { return std::fabs(a) < std::fabs(b); });
         const std::size_t from = static_cast<std::size_t>(loudest - c.samples.begin()) /
                                  static_cast<std::size_t>(c.channels) *
                                  static_cast<std::size_t>(c.channels);
         const std::size_t keep =
             std::min<std::size_t>(c.sample_rate / 20 * c.channels, c.samples.size() - from);
         c.samples = std::vector<float>(c.samples.begin() + from, c.samples.begin() + from + keep);
       }),
       live(), "recording shorter than the action"});
  cases.push_back({"other_rate", change([](auto& c) { c.sample_rate = 22050; }), live(),
                   "recording of another format"});
  cases.push_back({"other_channels", change([](auto& c) {
                     std::vector<float> left;
                     for (std::size_t i = 0; i < c.samples.size(); i += 2)
                       left.push_back(c.samples[i]);
                     c.samples = left;
                     c.channels = 1;
                   }),
                   live(), "recording of another format"});
  RecordingFault lost = change([](auto& c) { c.samples.resize(c.samples.size() / 2); });
  lost.capture.stream_error = "the input device disappeared (USB unplugged)";
  cases.push_back({"device_lost", lost, {}, "capture device lost"});
  RecordingFault nothing;
  nothing.stop_error = "the input device disappeared before it delivered anything";
  cases.push_back({"nothing_captured", nothing, {}, "recorder failed"});
  RecordingFault cannot_open;
  cannot_open.start_error = "cannot open input device 'USB': no such device";
  cases.push_back({"cannot_open", cannot_open, {}, "recorder failed"});
  return cases;
}

void PrintTo(const RecordingCase& c, std::ostream* os) { *os << c.name; }

class RecordingFaults : public ::testing::TestWithParam<RecordingCase> {};

// The action was done, so its reward counts and the object moved, but nothing was heard: the
// observation is `none`, the service is not asked, and the trial goes on. The next recording (the
// device back) is heard again.
TEST_P(RecordingFaults, SkipTheObservationAndTheNextRecordingIsHeard) {
  const RecordingCase& c = GetParam();
  Faults faults;
  faults.microphone = first_call(c.fault);
  faults.checks = c.checks;
  int observed = 0;
  faults.service = [&observed](Call) {
    ++observed;
    return std::optional<FaultyService::Fault>();
  };
  World w(faults);
  const WorldStep faulty = w.execute(kSlide);
  ASSERT_TRUE(faulty.robot.has_value());
  ASSERT_TRUE(faulty.robot->fault.has_value()) << c.name;
  EXPECT_EQ(faulty.robot->fault->kind, c.kind);
  EXPECT_TRUE(faulty.robot->observation_skipped());
  EXPECT_FALSE(faulty.robot->classified);
  EXPECT_EQ(observed, 0) << "the service heard a recording that failed its checks";
  EXPECT_EQ(faulty.outcome.observation.index, identification().none_symbol());
  EXPECT_FALSE(faulty.outcome.heard_probability.has_value());
  EXPECT_FALSE(faulty.outcome.terminal);
  EXPECT_FALSE(faulty.outcome.collision);
  EXPECT_EQ(faulty.outcome.reward, identification().data().sensing[kSlide].reward);

  const WorldStep next = w.execute(kStrike);
  EXPECT_FALSE(next.robot->fault.has_value()) << next.robot->fault->kind;
  EXPECT_TRUE(next.robot->classified);
  EXPECT_EQ(observed, 1);
}

INSTANTIATE_TEST_SUITE_P(Loop, RecordingFaults, ::testing::ValuesIn(recording_cases()),
                         [](const ::testing::TestParamInfo<RecordingCase>& c) {
                           return c.param.name;
                         });

// The checks pass the simulated microphone's own recordings, so they reject only what is wrong.
TEST(RecordingChecks, TheSimulatedMicrophonesRecordingsPassEveryCheck) {
  Faults faults;
  faults.checks = live();
  World w(faults);
  for (const int action : {kSlide, kStrike, kSlide}) {
    const WorldStep step = w.execute(action);
    EXPECT_FALSE(step.robot->fault.has_value()) << step.robot->fault->kind;
    EXPECT_TRUE(step.robot->classified);
  }
}

// ---- the observation service -----------------------------------------------------------------

TEST(ServiceFaults, ATimeoutOrAClassTheProblemDoesNotKnowSkipsTheObservation) {
  for (const auto& [fault, kind] : std::vector<std::pair<FaultyService::Fault, std::string>>{
           {{"observation service timed out after 2 s", ""}, "observation service failed"},
           {{"", "teapot"}, "class unknown to the problem"}}) {
    Faults faults;
    faults.service = first_call(fault);
    World w(faults);
    const WorldStep faulty = w.execute(kSlide);
    ASSERT_TRUE(faulty.robot->fault.has_value()) << kind;
    EXPECT_EQ(faulty.robot->fault->kind, kind);
    EXPECT_TRUE(faulty.robot->observation_skipped());
    EXPECT_EQ(faulty.outcome.observation.index, identification().none_symbol());
    EXPECT_FALSE(faulty.outcome.terminal);
    if (!fault.error.empty())
      EXPECT_NE(faulty.robot->fault->detail.find(fault.error), std::string::npos);
    else
      EXPECT_NE(faulty.robot->fault->detail.find("'teapot'"), std::string::npos);
    const WorldStep next = w.execute(kSlide);
    EXPECT_FALSE(next.robot->fault.has_value());
    EXPECT_TRUE(next.robot->classified);
  }
}

// ---- the action ------------------------------------------------------------------------------

robot::ActionReport failed(const std::string& action, const std::string& reason, bool safe) {
  robot::ActionReport r{action, robot::ActionStatus::failed, reason, 0.2};
  r.retry_safe = safe;
  return r;
}

TEST(ActionFaults, AFailureTheArmCallsSafeIsRetriedAndTheRetryIsHeard) {
  Faults faults;
  faults.arm = [](Call c, const std::string& action) {
    return c.call == 0 ? std::optional(failed(action, "grasp not confirmed; nothing moved", true))
                       : std::nullopt;
  };
  World w(faults);
  const WorldStep step = w.execute(kStrike);
  EXPECT_EQ(step.robot->attempts, 2);
  EXPECT_EQ(step.robot->report.status, robot::ActionStatus::done);
  EXPECT_FALSE(step.robot->fault.has_value());
  EXPECT_TRUE(step.robot->classified);
  EXPECT_FALSE(step.outcome.terminal);
}

TEST(ActionFaults, AFailureNotSafeToRepeatATimeoutOrRepeatedFailuresEndTheTrialAsFailed) {
  struct Case {
    robot::ActionReport report;
    int attempts;
  };
  for (const Case& c : std::vector<Case>{
           {failed("strike", "stopped midway: the object slipped out of the gripper", false), 1},
           {failed("strike", "no answer from the arm within 5 s (timed out)", false), 1},
           {failed("strike", "grasp not confirmed; nothing moved", true),
            RobotWorld::kMaxAttempts}}) {
    Faults faults;
    faults.arm = [c](Call, const std::string&) { return std::optional(c.report); };
    World w(faults);
    const WorldStep step = w.execute(kStrike);
    SCOPED_TRACE(c.report.reason);
    EXPECT_EQ(step.robot->attempts, c.attempts);
    ASSERT_TRUE(step.robot->fault.has_value());
    EXPECT_EQ(step.robot->fault->kind, "action failed");
    EXPECT_EQ(step.robot->fault->effect, FaultEffect::trial_failed);
    EXPECT_NE(step.robot->fault->detail.find(c.report.reason), std::string::npos);
    EXPECT_FALSE(step.robot->classified);
    EXPECT_TRUE(step.outcome.terminal);
    EXPECT_TRUE(step.outcome.collision);
    EXPECT_EQ(step.outcome.reward, identification().data().collision_reward);
    EXPECT_EQ(step.outcome.observation.index, identification().none_symbol());
  }
}

// A sort the arm could not finish put the object nowhere: the trial ends failed with the
// collision reward, never the bin's reward (the report's problem: action 2 is the first sort).
TEST(ActionFaults, AFailedSortIsNotASortAndEndsTheTrialAsFailed) {
  Faults faults;
  faults.arm = [](Call, const std::string& action) {
    return std::optional(failed(action, "the gripper opened too early", false));
  };
  World w(faults);
  const int sort = identification().num_sensing();
  const WorldStep step = w.execute(sort);
  ASSERT_TRUE(step.robot->fault.has_value());
  EXPECT_EQ(step.robot->fault->kind, "action failed");
  EXPECT_EQ(step.robot->fault->effect, FaultEffect::trial_failed);
  EXPECT_TRUE(step.outcome.terminal);
  EXPECT_EQ(step.outcome.reward, identification().data().collision_reward);
  EXPECT_NE(step.outcome.reward, identification().data().sorting_reward[0][0]);
}

// ---- the whole loop --------------------------------------------------------------------------

Loop faulty_loop(Faults faults, int max_steps = 30) {
  LoopSettings settings;
  settings.problem = problem();
  settings.world = PartsWorldSpec{[faults] { return faulty_parts(identification(), faults); }};
  settings.observation_model = model();
  settings.planner.solver = "abt";
  settings.planner.episodes = 300;
  settings.max_steps = max_steps;
  return Loop(std::make_shared<const LoopSpec>(std::move(settings)));
}

RecordingFault silence() {
  RecordingFault f;
  f.change_clip = [](audio::AudioClip& c) { std::fill(c.samples.begin(), c.samples.end(), 0.0f); };
  return f;
}

// The user is told the fault, the trial and the step; the belief after the faulty step is the one
// before it (which the first, heard, step had moved from the prior), and the trial goes on from
// there.
TEST(LoopFaults, ASkippedObservationLeavesTheBeliefAndIsReportedWithTrialAndStep) {
  Faults faults;
  faults.checks = live();
  faults.microphone = [](Call c) {
    return c.trial == 1 && c.call == 1 ? std::optional(silence()) : std::nullopt;
  };
  Loop loop = faulty_loop(faults);
  ASSERT_TRUE(loop.run({0, 0, 3}));
  const CapturedLog log;
  const auto trial = loop.run({1, 1, 3});
  ASSERT_TRUE(trial);
  ASSERT_GE(trial->steps.size(), 3u);
  const Step& faulty = trial->steps[1];
  ASSERT_TRUE(faulty.robot->observation_skipped());
  ASSERT_NE(faulty.record.belief, trial->steps[0].record.belief) << "the first step was heard";
  ASSERT_TRUE(faulty.belief_after.has_value());
  EXPECT_EQ(*faulty.belief_after, faulty.record.belief);
  EXPECT_EQ(trial->steps[2].record.belief, faulty.record.belief);
  const std::string action = identification().spec().action_names[faulty.record.action];
  EXPECT_NE(log.text().find("trial 1, step 2 (" + action + "): recording silent"),
            std::string::npos)
      << log.text();
  EXPECT_NE(log.text().find("the observation is skipped and the planner re-plans"),
            std::string::npos);
}

// A belief that remembers what it was told.
class TellingBelief final : public pomdp::Belief {
 public:
  TellingBelief(std::unique_ptr<pomdp::Belief> inner, std::shared_ptr<std::vector<int>> told)
      : inner_(std::move(inner)), told_(std::move(told)) {}
  pomdp::State sample(Rng& rng) const override { return inner_->sample(rng); }
  bool update(int action, const pomdp::Observation& observation, Rng& rng) override {
    told_->push_back(observation.index);
    return inner_->update(action, observation, rng);
  }
  std::vector<double> discrete_marginal(int variable) const override {
    return inner_->discrete_marginal(variable);
  }
  std::unique_ptr<pomdp::Belief> clone() const override {
    return std::make_unique<TellingBelief>(inner_->clone(), told_);
  }

 private:
  std::unique_ptr<pomdp::Belief> inner_;
  std::shared_ptr<std::vector<int>> told_;
};

// The trial runner tells the belief only what was heard: a skipped observation is not passed on as
// `none` (the beliefs would keep their prediction then too, but a particle belief would keep the
// impossible `none` in the history it draws fresh particles against, and never draw one again).
TEST(LoopFaults, TheBeliefIsNeverToldAnObservationTheLoopDidNotGet) {
  Faults faults;
  faults.checks = live();
  faults.microphone = [](Call c) { return c.call == 1 ? std::optional(silence()) : std::nullopt; };
  RobotWorld world(problem()->model, faulty_parts(identification(), faults));
  solvers::AbtSolver solver(problem()->model, solvers::search_options({}, *problem()));
  auto told = std::make_shared<std::vector<int>>();
  TrialParts parts;
  parts.model = problem()->model.get();
  parts.world = &world;
  parts.solver = &solver;
  parts.make_belief = [told](Rng& rng) {
    return std::make_unique<TellingBelief>(
        std::make_unique<pomdp::ParticleBelief>(problem()->model, 300, rng), told);
  };
  TrialOptions options;
  options.budget = solvers::Budget::episodes(300);
  const auto trial = run_trial(parts, options, 0, 0);
  ASSERT_TRUE(trial);
  int heard = 0, skipped = 0;
  for (const Step& s : trial->steps) {
    heard += s.robot->classified && !s.terminal;
    skipped += s.robot->observation_skipped();
  }
  ASSERT_EQ(skipped, 1);
  EXPECT_EQ(static_cast<int>(told->size()), heard);
  for (const int o : *told) EXPECT_NE(o, identification().none_symbol());
}

// A microphone that hears nothing all trial teaches the planner nothing: the belief stays the
// prior at every step, whatever the planner does.
TEST(LoopFaults, ADeadMicrophoneNeverMovesTheBelief) {
  Faults faults;
  faults.checks = live();
  faults.microphone = [](Call) { return std::optional(silence()); };
  Loop loop = faulty_loop(faults, 6);
  const auto trial = loop.run({0, 0, 3});
  ASSERT_TRUE(trial);
  const std::vector<double> prior = trial->steps[0].record.belief;
  for (const Step& s : trial->steps) {
    EXPECT_EQ(s.record.belief, prior);
    if (s.belief_after) {
      EXPECT_EQ(*s.belief_after, prior);
    }
    EXPECT_FALSE(s.robot->classified);
  }
}

TEST(LoopFaults, AFailedActionEndsTheTrialAsFailedAndSaysSo) {
  Faults faults;
  faults.arm = [](Call c, const std::string& action) {
    return c.call == 1 ? std::optional(failed(action, "stopped midway: wrist force limit", false))
                       : std::nullopt;
  };
  Loop loop = faulty_loop(faults);
  const CapturedLog log;
  const auto trial = loop.run({0, 0, 3});
  ASSERT_TRUE(trial);
  ASSERT_EQ(trial->steps.size(), 2u);
  EXPECT_TRUE(trial->record.collision);
  EXPECT_TRUE(trial->steps[1].terminal);
  EXPECT_FALSE(trial->steps[1].belief_after.has_value());
  EXPECT_NE(log.text().find("trial 0, step 2"), std::string::npos) << log.text();
  EXPECT_NE(log.text().find("action failed: stopped midway: wrist force limit (1 attempt); the "
                            "trial ends as failed"),
            std::string::npos)
      << log.text();
}

void expect_same_steps(const Trial& a, const Trial& b) {
  ASSERT_EQ(a.steps.size(), b.steps.size());
  EXPECT_EQ(a.record.discounted_reward, b.record.discounted_reward);
  EXPECT_EQ(a.record.believed_state, b.record.believed_state);
  for (std::size_t i = 0; i < a.steps.size(); ++i) {
    const Step& x = a.steps[i];
    const Step& y = b.steps[i];
    EXPECT_EQ(x.record.action, y.record.action);
    EXPECT_EQ(x.record.observation.index, y.record.observation.index);
    EXPECT_EQ(x.record.belief, y.record.belief);
    EXPECT_EQ(x.record.heard_probability, y.record.heard_probability);
    EXPECT_EQ(x.belief_after, y.belief_after);
    EXPECT_EQ(x.robot->clip.samples, y.robot->clip.samples);
  }
}

// Faults in trial 1 (a failed-and-retried action, a lost device, a service timeout) leave trials 0
// and 2 exactly as a run without them.
TEST(LoopFaults, TrialsTheFaultDidNotTouchAreTheSameAsWithoutIt) {
  Faults faults;
  faults.arm = [](Call c, const std::string& action) {
    return c.trial == 1 && c.call == 0 ? std::optional(failed(action, "nothing moved", true))
                                       : std::nullopt;
  };
  RecordingFault lost;
  lost.capture.stream_error = "device gone";
  faults.microphone = [lost](Call c) {
    return c.trial == 1 && c.call == 2 ? std::optional(lost) : std::nullopt;
  };
  Loop clean = faulty_loop(Faults{});
  Loop faulty = faulty_loop(faults);
  std::vector<Trial> a, b;
  for (int t = 0; t < 3; ++t) {
    a.push_back(*clean.run({t, t % 2, 3}));
    b.push_back(*faulty.run({t, t % 2, 3}));
  }
  ASSERT_EQ(b[1].steps[0].robot->attempts, 2);  // the fault did happen in trial 1
  for (const int t : {0, 2}) {
    SCOPED_TRACE("trial " + std::to_string(t));
    expect_same_steps(a[t], b[t]);
  }
}

// ---- what capture lost is counted -------------------------------------------------------------

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// Runs trial 0 (the mug) with `faults`, logged as `echoplan run` logs it into `dir`; the trial and
// each step's JSON line.
std::pair<Trial, std::vector<nlohmann::json>> logged_trial(const Faults& faults,
                                                           const fs::path& dir) {
  Loop loop = faulty_loop(faults);
  LoopLog log(dir, identification());
  std::vector<nlohmann::json> lines;
  auto trial = loop.run({0, 0, 3}, [&](const Step& s) { lines.push_back(log.write_step(s)); });
  if (!trial) throw std::logic_error("the trial was not run");
  log.write_trial({}, trial);
  return {std::move(*trial), std::move(lines)};
}

TEST(LoopFaults, OverrunsAndDroppedFramesAreCountedInTheStepLogAndTrialJson) {
  RecordingFault overrun;
  overrun.capture.overflow_callbacks = 2;
  overrun.capture.dropped_frames = 512;
  Faults faults;
  faults.microphone = first_call(overrun);
  const fs::path dir = testing::unique_temp_dir("capture_log");
  const auto [trial, lines] = logged_trial(faults, dir);
  ASSERT_GE(lines.size(), 2u);
  // The clip with a gap is still heard (the rest of the sound is there), and marked.
  EXPECT_TRUE(trial.steps[0].robot->classified);
  EXPECT_EQ(lines[0]["capture"]["overflow_callbacks"], 2);
  EXPECT_EQ(lines[0]["capture"]["dropped_frames"], 512);
  EXPECT_EQ(lines[0]["capture"]["dropout"], true);
  EXPECT_EQ(lines[1]["capture"]["dropout"], false);
  std::ifstream jsonl(dir / "loop_steps.jsonl");
  std::string first;
  std::getline(jsonl, first);
  EXPECT_EQ(nlohmann::json::parse(first)["capture"]["dropout"], true);
  const nlohmann::json summary = read_json(dir / "trial.json");
  EXPECT_EQ(summary["capture"]["overflow_callbacks"], 2);
  EXPECT_EQ(summary["capture"]["dropped_frames"], 512);
  EXPECT_EQ(summary["capture"]["recordings_with_dropout"], 1);
  EXPECT_TRUE(summary["faults"].empty());
  fs::remove_all(dir);
}

TEST(LoopFaults, TheStepLogAndTrialJsonNameEachFault) {
  Faults faults;
  faults.checks = live();
  faults.microphone = first_call(silence());
  const fs::path dir = testing::unique_temp_dir("fault_log");
  const auto [trial, lines] = logged_trial(faults, dir);
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines[0]["fault"]["kind"], "recording silent");
  EXPECT_EQ(lines[0]["fault"]["observation_skipped"], true);
  EXPECT_EQ(lines[1]["fault"], nullptr);
  const nlohmann::json summary = read_json(dir / "trial.json");
  ASSERT_EQ(summary["faults"].size(), 1u);
  EXPECT_EQ(summary["faults"][0]["step"], 0);
  EXPECT_EQ(summary["faults"][0]["kind"], "recording silent");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace echoplan::loop
