#include "experiment/campaign_arms.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <set>

#include "common/error.h"
#include "loop/object_problem.h"
#include "loop/planner.h"
#include "solvers/leaf_value.h"
#include "solvers/search_tree.h"

namespace echoplan::experiment {

namespace {

// The error of an arm that breaks `rule`: the campaign file, the arm's line and its name.
template <class Arm>
[[noreturn]] void refuse(const CampaignConfig& config, const Arm& arm, const std::string& rule) {
  throw InputError(config.source, arm.line, fmt::format("arm '{}': {}", arm.name, rule));
}

// What the file's words allow: a fixed strategy does not search, and grades need a classifier.
void check_words(const CampaignConfig& config, const CampaignArm& arm) {
  if (arm.strategy != kPlanStrategy) {
    if (!arm.leaf.empty())
      refuse(config, arm,
             "leaf: only an arm that plans (strategy: plan) has a leaf value; '" + arm.strategy +
                 "' is a fixed strategy");
    if (!arm.unheard.empty())
      refuse(config, arm,
             "unheard: only an arm that plans (strategy: plan) searches; '" + arm.strategy +
                 "' is a fixed strategy");
  }
  if (arm.trained_in_noise && config.world.type == WorldType::model)
    refuse(config, arm,
           "trained_in_noise: the classifier trained in noise hears recordings; a model world "
           "hears none");
  if (arm.trained_in_noise && !config.world.model.empty())
    refuse(config, arm,
           "trained_in_noise: the world's model is frozen (world.model); nothing is trained");
  if (arm.trained_on_surfaces && config.world.type != WorldType::simulated)
    refuse(config, arm,
           "trained_on_surfaces: the classifier trained on other tables hears a simulated "
           "world's recordings; a model world hears none, a dataset world fits its own");
  if (!arm.modalities.empty() && !config.world.model.empty())
    refuse(config, arm,
           "modalities: the world's model is frozen (world.model); nothing is fitted on some "
           "modalities");
  if (std::set<std::string>(arm.modalities.begin(), arm.modalities.end()).size() !=
      arm.modalities.size())
    refuse(config, arm, "modalities: a modality is named twice");
  if (arm.trained_on_surfaces && arm.trained_in_noise)
    refuse(config, arm,
           "trained_on_surfaces and trained_in_noise are two classifiers: an arm hears with one");
  const perception::ObservationKind kind = arm.observation_kind();
  if (kind == perception::ObservationKind::labels) return;
  const char* name = perception::observation_kind_name(kind);
  if (!config.world.recorded_data() && !arm.calibrate)
    refuse(config, arm,
           fmt::format("observations: {} needs calibrate: true (grades come from the trained "
                       "classifier; a problem file's own table has none)",
                       name));
  if (config.world.type == WorldType::model)
    refuse(config, arm,
           fmt::format("observations: {} needs a world that hears (a simulated or dataset "
                       "world); a model world draws labels from its problem's table",
                       name));
}

// A planner sorting novel objects (a dataset world holding out objects) plans with lookalikes and
// counts the outcomes no episode has heard at their commit value (ABT with a leaf that follows the
// exact belief), unless its arm names them (measured: docs/BENCHMARKS.md, "How the planner counts
// outcomes it has not heard"). Holding out sessions, the folds fit no lookalikes and commit ties
// share for more planning time (docs/BENCHMARKS.md, "The planner's defaults on novel objects"):
// there the plain planner stays.
void apply_novel_object_defaults(const CampaignConfig& config, const CampaignArm& arm,
                                 ResolvedArm& resolved) {
  if (!resolved.plans() || !config.world.recorded_data() ||
      config.world.hold_out != perception::HoldOut::object)
    return;
  if (!arm.lookalike) resolved.plans_with.lookalike = true;
  const bool can_commit =
      config.planner.solver == "abt" &&
      (arm.leaf.empty() || solvers::follows_exact_belief(solvers::parse_leaf_mode(arm.leaf)));
  if (arm.unheard.empty() && can_commit)
    resolved.planner.unheard = solvers::unheard_outcomes_name(solvers::UnheardOutcomes::commit);
}

ResolvedArm resolve_arm(const CampaignConfig& config, const CampaignArm& arm) {
  check_words(config, arm);
  ResolvedArm r;
  r.name = arm.name;
  r.strategy = arm.strategy;
  r.problem = arm.problem;
  r.calibrate = arm.calibrate;
  r.trained_on_surfaces = arm.trained_on_surfaces;
  r.line = arm.line;
  std::vector<std::string> modalities = arm.modalities;
  std::sort(modalities.begin(), modalities.end());
  r.plans_with = {arm.observation_kind(), arm.lookalike.value_or(false), arm.trained_in_noise,
                  std::move(modalities)};
  r.planner.solver = r.plans() ? config.planner.solver : arm.strategy;
  r.planner.episodes = config.planner.episodes;
  r.planner.step_ms = config.planner.step_ms;
  if (r.plans()) {
    r.planner.leaf = arm.leaf;
    r.unheard_by_play = arm.unheard == kUnheardByPlay;
    // auto is chosen by self-play when the campaign is prepared (experiment/unheard_choice.h);
    // until then the arm checks as the search's default.
    if (!r.unheard_by_play) r.planner.unheard = arm.unheard;
  }
  apply_novel_object_defaults(config, arm, r);
  return r;
}

}  // namespace

std::vector<ResolvedArm> resolve_arms(const CampaignConfig& config) {
  std::vector<ResolvedArm> arms;
  for (const CampaignArm& arm : config.arms) arms.push_back(resolve_arm(config, arm));
  return arms;
}

void check_arm_problem(const CampaignConfig& config, const ResolvedArm& arm,
                       const pomdp::Problem& problem) {
  // Every solver can be built (unknown names and bad settings fail now, not in a worker).
  loop::check_planner(arm.planner, problem);
  if (arm.calibrate) loop::object_problem(*problem.model);
  if (!arm.unheard_by_play) return;
  if (!problem.model->tabular())
    refuse(config, arm,
           fmt::format("unheard: auto plays the arm's problem as the world, and {} has no table "
                       "(name share or commit)",
                       problem.source_path));
  solvers::PlannerOverrides commit = arm.planner;
  commit.unheard = solvers::unheard_outcomes_name(solvers::UnheardOutcomes::commit);
  try {
    loop::check_planner(commit, problem);
  } catch (const InputError& e) {
    refuse(config, arm, "unheard: auto may choose commit, and " + e.problem());
  }
}

CampaignArm as_written(const ResolvedArm& arm) {
  CampaignArm a;
  a.name = arm.name;
  a.problem = arm.problem;
  a.calibrate = arm.calibrate;
  a.trained_in_noise = arm.trained_in_noise();
  a.trained_on_surfaces = arm.trained_on_surfaces;
  a.modalities = arm.plans_with.modalities;
  a.strategy = arm.strategy;
  a.observations = perception::observation_kind_name(arm.plans_with.kind);
  // Written only when it plans with them (a `lookalike: false` reads as the file not naming it).
  if (arm.plans_with.lookalike) a.lookalike = true;
  a.leaf = arm.planner.leaf;
  a.unheard = arm.unheard_by_play ? kUnheardByPlay : arm.planner.unheard;
  a.line = arm.line;
  return a;
}

bool any_lookalike(const std::vector<ResolvedArm>& arms) {
  return std::any_of(arms.begin(), arms.end(),
                     [](const ResolvedArm& arm) { return arm.plans_with.lookalike; });
}

nlohmann::json to_json(const ResolvedArm& arm, bool recorded_data) {
  nlohmann::json j = {{"name", arm.name}, {"strategy", arm.strategy}};
  if (!arm.problem.empty()) j["problem"] = arm.problem;
  if (arm.calibrate) j["calibrate"] = true;
  if (arm.trained_in_noise()) j["trained_in_noise"] = true;
  if (arm.trained_on_surfaces) j["trained_on_surfaces"] = true;
  if (!arm.plans_with.modalities.empty()) j["modalities"] = arm.plans_with.modalities;
  j["solver"] = arm.planner.solver;
  if (arm.planner.episodes > 0) j["episodes"] = arm.planner.episodes;
  if (arm.planner.step_ms > 0) j["step_ms"] = arm.planner.step_ms;
  if (arm.plans()) {
    j["leaf"] = arm.planner.leaf.empty() ? "default" : arm.planner.leaf;
    j["unheard"] = arm.planner.unheard.empty() ? (arm.unheard_by_play ? kUnheardByPlay : "share")
                                               : arm.planner.unheard;
    if (arm.unheard_by_play) j["unheard_chosen_by"] = "self-play";
  }
  j["observations"] = perception::observation_kind_name(arm.hearing());
  if (recorded_data) {
    j["lookalike"] = arm.plans_with.lookalike;
    j["fold_problem"] = fold_problem_name(arm.plans_with);
  }
  return j;
}

std::string fold_problem_name(const ArmProblemKind& kind) {
  return fmt::format(
      "problem{}{}{}{}.yaml",
      kind.kind == perception::ObservationKind::labels
          ? ""
          : "-" + std::string(perception::observation_kind_name(kind.kind)),
      kind.lookalike ? "-lookalike" : "", kind.in_noise ? "-in-noise" : "",
      kind.modalities.empty() ? "" : fmt::format("-hears-{}", fmt::join(kind.modalities, "-")));
}

}  // namespace echoplan::experiment
