#include "loop/step_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace echoplan::loop {

namespace {

std::string bar(double p, int width = 24) {
  const int filled = std::clamp(static_cast<int>(std::lround(p * width)), 0, width);
  std::string s;
  for (int i = 0; i < width; ++i) s += i < filled ? "█" : "░";
  return s;
}

// What the robot's part of a step says: how the action went and what was heard.
std::string robot_text(const RobotStep& r) {
  if (r.fault) return fmt::format(" -> {}: {}", r.fault->kind, r.fault->detail);
  if (r.report.status != robot::ActionStatus::done)
    return fmt::format(" -> {}: {}", robot::to_string(r.report.status), r.report.reason);
  if (!r.classified) return "";
  if (r.heard.unknown) {
    // Unlike every class: say which one it was nearest to, and how likely that one was.
    const auto nearest =
        std::max_element(r.heard.probabilities.begin(), r.heard.probabilities.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; });
    return fmt::format(" -> heard unknown (nearest {}, p {:.2f}), {:.1f} ms to classify",
                       nearest == r.heard.probabilities.end() ? "?" : nearest->first,
                       r.heard.probability, r.observe_ms);
  }
  return fmt::format(" -> heard {} (p {:.2f}), {:.1f} ms to classify", r.heard.label,
                     r.heard.probability, r.observe_ms);
}

}  // namespace

std::string step_text(const Step& step, const pomdp::ModelSpec& spec) {
  const StepRecord& r = step.record;
  std::string text = fmt::format("step {}: {}", r.step + 1, spec.action_names[r.action]);
  if (step.robot)
    text += robot_text(*step.robot);
  else
    text += " -> observed " + spec.observation.names[r.observation.index];
  return text + fmt::format(", reward {:g}", r.reward);
}

std::string step_report(const Step& step, const pomdp::ModelSpec& spec) {
  const std::vector<std::string>& objects = spec.state.discrete_value_names.at(0);
  std::string text;
  if (step.record.step == 0)
    text += "belief before the first action:\n" + belief_text(objects, step.record.belief);
  text += step_text(step, spec) + "\n";
  if (step.belief_after) text += belief_text(objects, *step.belief_after);
  return text;
}

std::string trial_text(const Trial& trial, const pomdp::ModelSpec& spec) {
  const TrialRecord& r = trial.record;
  std::string text;
  if (r.collision)
    text = "ended in a collision";
  else if (r.capped || trial.steps.empty())
    text = "no sorting action within the step cap";
  else
    text = fmt::format("sorted by {} (believed {})",
                       spec.action_names[trial.steps.back().record.action],
                       spec.state.discrete_value_names.empty()
                           ? std::to_string(r.believed_state)
                           : spec.state.discrete_value_names[0][r.believed_state]);
  return text + fmt::format("; {} steps, discounted reward {:.3f}", r.steps, r.discounted_reward);
}

std::string belief_text(const std::vector<std::string>& objects,
                        const std::vector<double>& belief) {
  std::size_t width = 0;
  for (const auto& o : objects) width = std::max(width, o.size());
  std::string text;
  for (std::size_t k = 0; k < objects.size(); ++k)
    text += fmt::format("    {:<{}}  {}  {:.3f}\n", objects[k], width, bar(belief[k]), belief[k]);
  return text;
}

}  // namespace echoplan::loop
