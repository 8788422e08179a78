// A campaign's results as tables and numbers: trials.csv and steps.csv (Tables 5.1 and 5.2 of the
// report, plus arm and object), per-arm copies that `echoplan certify` reads with the arm's
// problem, summary.json and the terminal summary, each next to the campaign's reference results
// when it names some.
//
// Everything here is a pure function of the campaign's configuration and its journal entries sorted
// by id, so a resumed, parallel, sharded-and-merged or one-core run writes the same bytes.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "experiment/campaign_arms.h"
#include "experiment/campaign_config.h"
#include "experiment/noise_levels.h"
#include "experiment/sort_confidence.h"
#include "experiment/trial_journal.h"
#include "experiment/trial_summary.h"
#include "pomdp/model.h"

namespace echoplan::experiment {

// What the report needs besides the entries: the campaign and the planning problems' shared names.
// How the report presents the campaign's world (the world fills it: campaign_world.h), so the
// report layer never asks which kind of world it reports.
struct WorldPresentation {
  std::string title = "echoplan campaign";  // the page's heading
  std::string note;                         // what the world is, what its numbers show
  // How an arm's problem is named when it is not the arm's file ("each fold's problem"); empty:
  // the file.
  std::string arm_problem;
  std::string pairing = "same objects, same world noise";  // what paired trials share
  // A results row, belief panels and a confusion figure per object, and every decision on the
  // page; false for recorded data (hundreds of objects, a belief over every class per decision):
  // the page compares the arms instead, with only the sensing actions' counts in its tables.
  bool per_object = true;
};

struct CampaignResults {
  CampaignConfig config;          // as the file wrote it
  std::vector<ResolvedArm> arms;  // what each arm of config ran (campaign_arms.h)
  // The world's trial groups: the file's, or a dataset world's, one per object (a trial per
  // session).
  std::vector<ObjectGroup> groups;
  WorldPresentation world;
  pomdp::ModelSpec spec;     // objects, actions and observation names, the same for every arm
  int belief_particles = 0;  // > 0: steps.csv shows particle counts (Table 5.2); 0: probabilities
  std::vector<JournalEntry> entries;  // sorted by id, at most one per id
  int planned_trials = 0;             // what the campaign (all shards) asks for
  nlohmann::json identity;            // config.identity() with the groups, from the files read
  // A dataset world's sorting: right_action[s] sorts true state s right (summarize()); empty for
  // other worlds, whose accuracy is the final belief's mode.
  std::vector<int> right_action;
  // A dataset world's sorts: right_share[s][a], the chance that action a sorts state s right
  // (right_shares()), what the belief at a sort is measured in; empty for other worlds.
  std::vector<std::vector<double>> right_share;
  int sensing_actions = 0;  // a dataset world's sensing actions (the first actions), for figures
  // What one use of each action costs (action_costs()): the summaries' mean cost per trial; empty
  // when the world's problem is not an object-identification problem (no costs reported).
  std::vector<double> action_costs;
  // A dataset world's fold of each trial, (object, session) -> fold name ("1", "2", ...):
  // write_tables() writes each fold's trials beside the fold's problem (folds/<fold>/), for
  // `echoplan certify --campaign`. Empty in other worlds.
  std::map<std::pair<std::string, std::string>, std::string> fold_of_session;
  // A simulated world's training set heard by the reference's classifier (leave-one-out, per
  // action; perception::heard_confusion), shown beside the reference's `heard` counts; empty when
  // the world is not simulated or the reference has no such counts.
  std::vector<HeardCounts> heard;
  // The arms with unheard: auto and what their self-play chose (unheard.json's
  // "arms": arm, chosen, commit_minus_share, ci95, self_play_trials); empty otherwise.
  nlohmann::json unheard_choices = nlohmann::json::array();
};

// What one use of each of the model's actions costs: minus a sensing action's reward (its
// collisions aside), 0 for a sorting action; empty when `model` is not an object-identification
// problem.
std::vector<double> action_costs(const pomdp::Model& model);

// How many of the spec's actions (the first ones) the results tables give a column: all of them,
// or only the sensing actions when the world does not present objects one by one (recorded data:
// a column per bin would run off the page; accuracy says how the sorting went).
int shown_actions(const CampaignResults& results);

// Which trials a summary row covers.
enum class RowScope {
  object,            // one trial group (the object in the world)
  original_objects,  // the groups whose object plays itself
  variants,          // the groups whose object plays another
  all,
};

// One line of the summary: an arm's trials of one group, or of several.
struct SummaryRow {
  std::string arm;
  RowScope scope = RowScope::object;
  std::string label;  // the object, "original objects", "variants" or "all"
  TrialSummary summary;
  // The campaign reference's result for the same trials, when it has one (reference_results.h).
  std::optional<ReferenceResult> reference;
};

// The rows: per arm, each group, then the original objects together and the variants together
// (when the campaign has both), and all. A dataset world, with a group per object of the data,
// has the "all" row only.
std::vector<SummaryRow> summary_rows(const CampaignResults& results);

// Confusion counts of one arm and sensing action: counts[group][symbol], symbol over the
// observation names (the heard classes), over every sensing step of the arm's trials.
struct ConfusionCounts {
  std::string arm;
  std::string action;
  std::vector<std::string> rows;     // the groups' objects
  std::vector<std::string> columns;  // the heard classes
  std::vector<std::vector<int>> counts;
};
std::vector<ConfusionCounts> confusion_counts(const CampaignResults& results);

// The names of the observations the steps of arm `arm` hold: the world's (results.spec), or for an
// arm that hears graded observations each class's graded symbols in its place ("mug" becomes
// "mug@low", "mug@mid", "mug@high"; `unknown` and `none` stay), in the problems' order.
std::vector<std::string> observation_names(const CampaignResults& results, const std::string& arm);
// The same for every arm of the campaign: arm -> names.
std::map<std::string, std::vector<std::string>> observation_names(const CampaignResults& results);

// How sure each arm was when it sorted (sort_confidence.h), in the configuration's arm order.
std::vector<ArmConfidence> arm_confidence(const CampaignResults& results);
// With world.noise, each arm's trials per band of their measured noise level (noise_levels.h);
// otherwise, or when no trial heard a recording, none.
std::vector<ArmNoiseBands> noise_bands(const CampaignResults& results);
// Each arm's trials per table, when the world chose tables (noise_levels.h); otherwise none.
std::vector<ArmSurfaces> surface_shares(const CampaignResults& results);

// Writes trials.csv, steps.csv and arms/<arm>/{trials,steps}.csv into `directory`; with
// fold_of_session, also each fold's folds/<fold>/arms/<arm>/{trials,steps}.csv.
void write_tables(const std::filesystem::path& directory, const CampaignResults& results);

// The content of summary.json.
nlohmann::json summary_json(const CampaignResults& results);

// The summary as the terminal shows it (also saved as summary.txt).
std::string summary_text(const CampaignResults& results);

}  // namespace echoplan::experiment
