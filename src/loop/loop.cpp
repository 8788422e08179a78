#include "loop/loop.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>

#include "common/error.h"
#include "pomdp/make_belief.h"

namespace echoplan::loop {

namespace {

// The names a problem shares with the world: objects, actions, heard classes.
std::string names_of(const pomdp::ModelSpec& spec) {
  std::string text = "objects";
  for (const auto& o : spec.state.discrete_value_names.at(0)) text += " " + o;
  text += "; actions";
  for (const auto& a : spec.action_names) text += " " + a;
  text += "; observations";
  for (const auto& o : spec.observation.names) text += " " + o;
  return text;
}

}  // namespace

void check_same_names(const pomdp::Problem& plan, const pomdp::Problem& world) {
  const pomdp::ModelSpec& spec = world.model->spec();
  if (spec.state.discrete_value_names.empty())
    throw InputError(world.source_path, 0,
                     "a loop needs an object-identification problem (objects as its state)");
  if (plan.model->spec().state.discrete_value_names.empty() ||
      names_of(plan.model->spec()) != names_of(spec))
    throw InputError(plan.source_path, 0,
                     fmt::format("the planner's problem and the world's must share objects, "
                                 "actions and observations: this one has {}, the world's {} has {}",
                                 plan.model->spec().state.discrete_value_names.empty()
                                     ? std::string("no objects")
                                     : names_of(plan.model->spec()),
                                 world.source_path, names_of(spec)));
}

LoopSpec::LoopSpec(LoopSettings settings) : settings_(std::move(settings)) {
  if (!settings_.problem) throw std::invalid_argument("LoopSpec: no problem");
  if (!settings_.world_problem) settings_.world_problem = settings_.problem;
  if (settings_.max_steps < 1) throw InputError("--max-steps must be >= 1");
  check_planner(settings_.planner, *settings_.problem);
  if (settings_.world_problem != settings_.problem)
    check_same_names(*settings_.problem, *settings_.world_problem);
  world_factory_ =
      make_world_factory({settings_.world, settings_.world_problem->model,
                          settings_.observation_model, settings_.world_objects, settings_.noise});
}

Loop::Loop(std::shared_ptr<const LoopSpec> spec)
    : spec_(std::move(spec)),
      planner_(
          make_planner(spec_->settings().planner, spec_->problem(), spec_->problem().source_path)),
      world_(spec_->world_factory()()) {}

std::optional<Trial> Loop::run(const TrialRequest& request, const StepFn& on_step,
                               const std::atomic<bool>* stop) {
  const pomdp::Problem& problem = spec_->problem();
  TrialParts parts;
  parts.model = problem.model.get();
  parts.world = world_.get();
  parts.solver = planner_.solver.get();
  parts.make_belief = [&problem](Rng& rng) { return pomdp::make_belief(problem, rng); };
  TrialOptions options;
  options.budget = planner_.budget;
  options.max_steps = spec_->settings().max_steps;
  options.seed = request.seed;
  return run_trial(parts, options, request.index, request.object, on_step, stop);
}

int object_index(const pomdp::Problem& problem, const std::string& object) {
  const auto& names = problem.model->spec().state.discrete_value_names;
  if (!names.empty()) {
    const auto it = std::find(names[0].begin(), names[0].end(), object);
    if (it != names[0].end()) return static_cast<int>(it - names[0].begin());
  }
  throw InputError(
      problem.source_path, 0,
      fmt::format("has no object '{}' (objects: {})", object,
                  names.empty() ? "none" : fmt::format("{}", fmt::join(names[0], ", "))));
}

}  // namespace echoplan::loop
