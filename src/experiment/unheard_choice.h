// Which of ABT's two estimates of the outcomes no episode has heard yet (share or commit,
// solvers/search_tree.h) an arm plans with when its campaign leaves the choice to self-play
// (`unheard: auto` on an arm of strategy plan).
//
// Why a choice: neither estimate wins on every problem. On a problem whose behaviours have few
// outcomes (the report's: four symbols) share is nearly exact and commit's lower bound costs
// (in certified regret); where they have many (a recorded-data fold with
// lookalikes) most outcomes stay unheard at the search's budget, share lets the heard ones speak
// for them, the planner keeps sensing, and commit earns more (docs/BENCHMARKS.md, "How the planner
// counts outcomes it has not heard"). Why this measure: the arm's problem is the planner's model of
// the world, so playing the two estimates on it, with the problem as the world and the exact
// belief, scores them on what the planner believes it faces, paired (trial t of both draws the
// same object and random streams) and with each reward replaced by its expectation under the
// belief (experiment/expected_reward.h). It never looks at the world the campaign runs in: the
// choice is the planner's, made before the first trial. What it cannot see: a world unlike the
// model (on recorded data the two can differ; the campaign's own arms measure that).
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/progress.h"
#include "experiment/campaign_arms.h"
#include "experiment/campaign_config.h"
#include "pomdp/problem.h"
#include "solvers/planner_overrides.h"
#include "solvers/search_tree.h"

namespace echoplan::experiment {

struct UnheardSelfPlay {
  // The problems the arm plans with (one per fold; each needs a tabular model and an exact belief).
  // Trial t plays on problems[t % size], so the trials are dealt evenly.
  std::vector<std::shared_ptr<const pomdp::Problem>> problems;
  solvers::PlannerOverrides planner;  // the arm's; its `unheard` is set per estimate
  int trials = 200;                   // paired trials, >= 2
  int max_steps = 100;
  std::uint64_t seed = 1;
  int workers = 1;
};

struct UnheardChoice {
  solvers::UnheardOutcomes chosen = solvers::UnheardOutcomes::share;
  // Expected discounted reward per trial with commit minus with share, paired, and its 95% CI.
  double difference = 0.0;
  double ci95 = 0.0;
  int trials = 0;
};

// Plays `play.trials` paired trials with each estimate and chooses the one with the higher mean
// (share on a tie: the search's default). `progress` hears "choose unheard" per trial. Returns
// nothing when stopped. Throws InputError for a problem without a tabular model or exact belief.
std::optional<UnheardChoice> choose_unheard(const UnheardSelfPlay& play, const ProgressFn& progress,
                                            const std::atomic<bool>& stop);

// The problems arm number `arm` of a campaign plays on to choose (each with a table and an exact
// belief): a dataset world's fold problems, a problem file world's arm problem.
using ArmSelfPlayProblems =
    std::function<std::vector<std::shared_ptr<const pomdp::Problem>>(std::size_t arm)>;

// Chooses the unheard estimate of every arm with `unheard: auto` (ResolvedArm::unheard_by_play) by
// choose_unheard on its problems (planner.self_play_trials trials, the arm's planner, the
// campaign_unheard stream of the campaign's seed) and puts it in the arm's planner; arms that play
// the same problems with the same leaf share one choice. Writes the choices to
// `directory`/kUnheardChoices when an arm chose. False when stopped (the arms then unchanged).
bool choose_arms_unheard(const CampaignConfig& config, std::vector<ResolvedArm>& arms,
                         const ArmSelfPlayProblems& problems_of,
                         const std::filesystem::path& directory, const ProgressFn& progress,
                         const std::atomic<bool>& stop, int workers);

// Puts the choices kept in a campaign folder's kUnheardChoices (read_unheard_choices) in the
// arms' planners, as choose_arms_unheard did when the campaign was prepared.
void apply_unheard_choices(const nlohmann::json& choices, std::vector<ResolvedArm>& arms);

// `problem` with an exact belief (what the self-play tracks), the same problem when it has one.
std::shared_ptr<const pomdp::Problem> with_exact_belief(
    const std::shared_ptr<const pomdp::Problem>& problem);

// A campaign's choices, in its folder (the report reads them back: summary.txt and summary.json).
inline constexpr const char* kUnheardChoices = "unheard.json";
struct ArmUnheardChoice {
  std::string arm;
  UnheardChoice choice;
};
// Writes {"what": ..., "arms": [{arm, chosen, commit_minus_share, ci95, self_play_trials}, ...]}.
void write_unheard_choices(const std::filesystem::path& file,
                           const std::vector<ArmUnheardChoice>& choices);
// The file's "arms"; InputError naming the file when it is not what write_unheard_choices wrote.
nlohmann::json read_unheard_choices(const std::filesystem::path& file);

}  // namespace echoplan::experiment
