// A campaign's arms as they run: what the file says of each arm, resolved once into what the arm
// really does. Every rule that defaults, accepts or refuses an arm is here; everything downstream
// (the planner, the fold problems, the loops, the report, campaign.json) reads the resolved arm.
//
// The rules, in the order they are applied (each error names the file, the arm's line and the arm):
// - a fixed strategy (all_actions, best_single, ...) has no leaf and no unheard estimate;
// - grades come from a classifier: in a model world they need `calibrate: true`, and a model world
//   draws labels from its problem's table anyway;
// - a planner sorting novel objects (a dataset world holding out objects) plans with lookalikes
//   and counts unheard outcomes at commit (ABT with a leaf that follows the exact belief) unless
//   its arm names them (why: docs/BENCHMARKS.md, "How the planner counts outcomes it has not
//   heard");
// - with the problem it plans on (check_arm_problem): its solver builds, and `unheard: auto` can
//   play the problem (a table) and plan with either estimate.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiment/campaign_config.h"
#include "perception/observation_grades.h"
#include "pomdp/problem.h"
#include "solvers/planner_overrides.h"

namespace echoplan::experiment {

// What an arm's problem depends on besides the world (a dataset world: besides the fold): what it
// hears, whether it plans with objects that sound like another class (lookalikes) and whether its
// classifier was trained in noise too (its table is that classifier's), and which of the data's
// modalities that classifier was fitted on.
struct ArmProblemKind {
  perception::ObservationKind kind = perception::ObservationKind::labels;
  bool lookalike = false;
  bool in_noise = false;
  std::vector<std::string> modalities{};  // sorted, distinct; empty: every modality
  friend auto operator<=>(const ArmProblemKind&, const ArmProblemKind&) = default;
};

struct ResolvedArm {
  std::string name;
  std::string strategy = kPlanStrategy;  // kPlanStrategy or a fixed strategy's solver name
  std::string problem;                   // a problem-file world's arm problem; empty: the data's
  bool calibrate = false;                // plans with the trained classifier's table
  bool trained_on_surfaces = false;      // hears with the classifier trained on other tables
  ArmProblemKind plans_with;             // hearing and copies of its problem (defaults applied)
  // What its planner runs: the campaign's solver (or the fixed strategy) and budget, the leaf, the
  // unheard estimate as defaulted, or as self-play chose it once the campaign is prepared.
  solvers::PlannerOverrides planner;
  bool unheard_by_play = false;  // the file said `unheard: auto`
  int line = 0;                  // the arm's line in the campaign file (0: unknown)

  bool plans() const { return strategy == kPlanStrategy; }
  perception::ObservationKind hearing() const { return plans_with.kind; }
  // Hears with the classifier trained in noise too (training_set.noise), not the quiet one.
  bool trained_in_noise() const { return plans_with.in_noise; }
};

// Every arm of `config` resolved, in the file's order. Throws InputError(config.source, line,
// "arm 'NAME': ...") naming the rule an arm breaks.
std::vector<ResolvedArm> resolve_arms(const CampaignConfig& config);

// The checks that need the problem `arm` plans on (its own file, or a dataset world's names
// problem): its planner builds on it and, with `unheard: auto`, can play it with either estimate.
// InputError naming the campaign file, the arm and the problem otherwise.
void check_arm_problem(const CampaignConfig& config, const ResolvedArm& arm,
                       const pomdp::Problem& problem);

// The arm in the campaign file's words, its defaults written out (`unheard: auto` stays auto): the
// arms section of the campaign's identity.
CampaignArm as_written(const ResolvedArm& arm);

// Some arm plans with lookalikes: every arm's problem then has those copies (with a share of 0 for
// the arms that do not plan with them).
bool any_lookalike(const std::vector<ResolvedArm>& arms);

// What campaign.json says each arm ran: name, strategy, solver, budget, leaf, unheard (and whether
// self-play chose it), hearing, the copies it plans with and, in a dataset world, its fold
// problems' file name.
nlohmann::json to_json(const ResolvedArm& arm, bool recorded_data);

// The file name of a dataset world's fold problem of that kind:
// problem[-graded|-levels][-lookalike][-in-noise][-hears-<modality>-...].yaml.
std::string fold_problem_name(const ArmProblemKind& kind);

}  // namespace echoplan::experiment
