#include "loop_trials.h"

#include <fmt/format.h>

#include "commands/planner_options.h"
#include "common/error.h"
#include "experiment/loop_log.h"
#include "pomdp/make_belief.h"
#include "pomdp/problem.h"

namespace echoplan::ros_app {

namespace {

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
    const std::function<void(const std::string&)>& say, const std::atomic<bool>* stop_requested) {
  if (settings.out.empty()) throw InputError("", 0, "an output folder is required");
  const pomdp::Problem problem = pomdp::load_problem(settings.problem);
  cli::PlannerFlags flags;
  flags.solver = settings.solver;
  flags.episodes = settings.episodes;
  flags.step_ms = settings.step_ms;
  const cli::Planner planner = cli::make_planner(flags, problem, settings.problem);

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
  setup.step_finished = [&](const experiment::StepRecord& s, const pomdp::Belief* after) {
    std::vector<double> marginal;
    if (after) marginal = after->discrete_marginal(0);
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
  return experiment::run_trials(setup, options, sayer);
}

}  // namespace echoplan::ros_app
