#include "experiment/campaign_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>

#include "experiment/campaign_runner.h"
#include "experiment/noise_levels.h"
#include "experiment/trial_log.h"
#include "perception/observation_model.h"
#include "pomdp/object_identification_model.h"

namespace echoplan::experiment {

namespace {

namespace fs = std::filesystem;

using GroupFilter = std::function<bool(const ObjectGroup&)>;

// An original object (it plays itself), not a variant of one.
bool plays_itself(const ObjectGroup& g) { return g.object == g.plays; }

// The reference's result for a row of `scope` over the groups of `objects`: the object's own, or a
// total that covers exactly these objects (in any order); none when the reference has no such one.
std::optional<ReferenceResult> reference_for(const std::optional<ReferenceResults>& reference,
                                             RowScope scope, std::vector<std::string> objects) {
  if (!reference) return std::nullopt;
  if (scope == RowScope::object) {
    auto it = reference->objects.find(objects.at(0));
    if (it == reference->objects.end()) return std::nullopt;
    return it->second;
  }
  const std::optional<ReferenceTotal>& total =
      scope == RowScope::original_objects
          ? reference->original_objects
          : (scope == RowScope::variants ? reference->variants : reference->all);
  if (!total) return std::nullopt;
  std::vector<std::string> covered = total->objects;
  std::sort(covered.begin(), covered.end());
  std::sort(objects.begin(), objects.end());
  if (covered != objects) return std::nullopt;
  return total->result;
}

// The records of `arm`'s trials whose group `keep` accepts.
std::vector<TrialRecord> records_where(const CampaignResults& results, const std::string& arm,
                                       const GroupFilter& keep) {
  std::map<std::string, const ObjectGroup*> groups;
  for (const ObjectGroup& g : results.groups) groups[g.object] = &g;
  std::vector<TrialRecord> records;
  for (const JournalEntry& e : results.entries) {
    auto it = groups.find(e.object);
    if (e.arm == arm && it != groups.end() && keep(*it->second)) records.push_back(e.result.record);
  }
  return records;
}

std::string percent(double fraction) { return fmt::format("{:.0f}%", 100.0 * fraction); }

// Paired differences of discounted reward between arm `b` and arm `a`: trials with the same group
// and index saw the same true object and world noise. Summarised like rewards (mean and 95% CI).
TrialSummary paired_difference(const CampaignResults& results, const std::string& a,
                               const std::string& b) {
  const std::vector<TrialJob> jobs =
      campaign_jobs(static_cast<int>(results.config.arms.size()), results.groups);
  std::vector<TrialRecord> differences;
  std::map<std::pair<std::string, int>, double> reward_a;
  std::map<std::pair<std::string, int>, double> reward_b;
  for (const JournalEntry& e : results.entries) {
    const int index = jobs.at(e.id).index;
    if (e.arm == a) reward_a[{e.object, index}] = e.result.record.discounted_reward;
    if (e.arm == b) reward_b[{e.object, index}] = e.result.record.discounted_reward;
  }
  for (const auto& [key, value] : reward_b) {
    auto it = reward_a.find(key);
    if (it == reward_a.end()) continue;
    TrialRecord r;
    r.discounted_reward = value - it->second;
    differences.push_back(r);
  }
  return summarize(differences, 0);
}

}  // namespace

std::vector<SummaryRow> summary_rows(const CampaignResults& results) {
  const int num_actions = static_cast<int>(results.spec.action_names.size());
  const std::vector<ObjectGroup>& groups = results.groups;
  const bool originals = std::any_of(groups.begin(), groups.end(), plays_itself);
  const bool variants = !std::all_of(groups.begin(), groups.end(), plays_itself);
  std::vector<SummaryRow> rows;
  for (const ResolvedArm& arm : results.arms) {
    auto add = [&](RowScope scope, const std::string& label, const GroupFilter& keep) {
      const std::vector<TrialRecord> records = records_where(results, arm.name, keep);
      if (records.empty()) return;
      std::vector<std::string> covered;
      for (const ObjectGroup& g : groups)
        if (keep(g)) covered.push_back(g.object);
      rows.push_back({arm.name, scope, label,
                      summarize(records, num_actions, results.right_action, results.action_costs),
                      reference_for(results.config.reference, scope, covered)});
    };
    for (const ObjectGroup& g : groups)
      if (results.world.per_object)
        add(RowScope::object, g.object,
            [&](const ObjectGroup& other) { return other.object == g.object; });
    if (originals && variants) {
      add(RowScope::original_objects, "original objects", plays_itself);
      add(RowScope::variants, "variants", [](const ObjectGroup& g) { return !plays_itself(g); });
    }
    add(RowScope::all, "all", [](const ObjectGroup&) { return true; });
  }
  return rows;
}

std::vector<std::string> observation_names(const CampaignResults& results, const std::string& arm) {
  const std::vector<std::string>& names = results.spec.observation.names;
  const auto it = std::find_if(results.arms.begin(), results.arms.end(),
                               [&](const ResolvedArm& a) { return a.name == arm; });
  if (it == results.arms.end() || it->hearing() == perception::ObservationKind::labels)
    return names;
  std::vector<std::string> graded;
  for (const std::string& name : names) {
    if (name == "none" || name == perception::kUnknownSymbol) {
      graded.push_back(name);
      continue;
    }
    for (int g = 0; g < perception::kGrades; ++g)
      graded.push_back(perception::graded_name(name, g, it->hearing()));
  }
  return graded;
}

std::map<std::string, std::vector<std::string>> observation_names(const CampaignResults& results) {
  std::map<std::string, std::vector<std::string>> names;
  for (const ResolvedArm& arm : results.arms)
    names[arm.name] = observation_names(results, arm.name);
  return names;
}

std::vector<ConfusionCounts> confusion_counts(const CampaignResults& results) {
  const auto& symbols = results.spec.observation.names;
  std::vector<std::string> classes;
  for (const std::string& s : symbols)
    if (s != "none") classes.push_back(s);
  std::vector<ConfusionCounts> all;
  for (const ResolvedArm& arm : results.arms) {
    // A graded arm's symbol o is class o / kGrades (its grades are counted together).
    const int per_class =
        arm.hearing() == perception::ObservationKind::labels ? 1 : perception::kGrades;
    // Sensing actions: those that were ever followed by a heard class in this campaign, in action
    // order.
    for (std::size_t a = 0; a < results.spec.action_names.size(); ++a) {
      ConfusionCounts c;
      c.arm = arm.name;
      c.action = results.spec.action_names[a];
      c.columns = classes;
      for (const ObjectGroup& g : results.groups) c.rows.push_back(g.object);
      c.counts.assign(c.rows.size(), std::vector<int>(classes.size(), 0));
      bool any = false;
      for (const JournalEntry& e : results.entries) {
        if (e.arm != arm.name) continue;
        const std::size_t row = std::find(c.rows.begin(), c.rows.end(), e.object) - c.rows.begin();
        if (row >= c.rows.size()) continue;
        for (const StepRecord& s : e.result.steps) {
          const int o = s.observation.index / per_class;
          if (s.action != static_cast<int>(a) || o < 0 || o >= static_cast<int>(classes.size()))
            continue;
          ++c.counts[row][o];
          any = true;
        }
      }
      if (any) all.push_back(std::move(c));
    }
  }
  return all;
}

// The seed a trial's random streams came from, with its number among its object's trials (a
// dataset world: its session's place among the object's sessions): `echoplan run --seed`.
std::string trial_seed(const CampaignResults& results, const std::string& object) {
  for (const ObjectGroup& group : results.groups)
    if (group.object == object) return std::to_string(group_seed(results.config.seed, group));
  return {};
}

namespace {

// arms/<arm>/{trials,steps}.csv under `directory`, of the entries `keep` accepts.
void write_arm_tables(const fs::path& directory, const CampaignResults& results,
                      const std::function<bool(const JournalEntry&)>& keep) {
  for (const ResolvedArm& arm : results.arms) {
    pomdp::ModelSpec spec = results.spec;
    spec.observation.names = observation_names(results, arm.name);
    TrialLog per_arm(directory / "arms" / arm.name, spec, results.belief_particles,
                     {"object", "session"}, {"seed"});
    for (const JournalEntry& e : results.entries)
      if (e.arm == arm.name && keep(e))
        per_arm.write_trial(e.result.record, e.result.steps, {e.object, e.session},
                            {trial_seed(results, e.object)});
  }
}

}  // namespace

void write_tables(const fs::path& directory, const CampaignResults& results) {
  TrialLog all(directory, results.spec, results.belief_particles, {"arm", "object", "session"},
               {"seed"});
  const auto names = observation_names(results);
  for (const JournalEntry& e : results.entries)
    all.write_trial(e.result.record, e.result.steps, {e.arm, e.object, e.session},
                    {trial_seed(results, e.object)}, &names.at(e.arm));
  write_arm_tables(directory, results, [](const JournalEntry&) { return true; });
  std::set<std::string> folds;
  for (const auto& [session, fold] : results.fold_of_session) folds.insert(fold);
  // Each fold's trials beside its problem: `certify --campaign` judges them with that problem.
  for (const std::string& fold : folds)
    write_arm_tables(directory / "folds" / fold, results, [&](const JournalEntry& e) {
      const auto it = results.fold_of_session.find({e.object, e.session});
      return it != results.fold_of_session.end() && it->second == fold;
    });
}

std::vector<double> action_costs(const pomdp::Model& model) {
  const pomdp::ObjectIdentificationModel* problem = model.object_identification();
  if (problem == nullptr) return {};
  std::vector<double> costs(model.num_actions(), 0.0);
  for (std::size_t a = 0; a < problem->data().sensing.size(); ++a)
    costs[a] = -problem->data().sensing[a].reward;
  return costs;
}

namespace {

// The arms' names, in the configuration's order.
std::vector<std::string> arm_names(const CampaignResults& results) {
  std::vector<std::string> names;
  for (const ResolvedArm& arm : results.arms) names.push_back(arm.name);
  return names;
}

// One arm's trials under one condition, as summary.txt lists them.
std::string shares_line(const std::string& arm, const std::string& condition,
                        const ConditionShares& c) {
  return fmt::format(
      "  {:<24} {:<14} {:>4} trials  right {:.3f} at {:.3f}  heard {:.2f}  behaviours {:.2f}  "
      "cost {:.2f}\n",
      arm, condition, c.trials, c.share_right, c.mean_belief, c.mean_heard, c.mean_behaviours,
      c.mean_cost);
}

}  // namespace

std::vector<ArmNoiseBands> noise_bands(const CampaignResults& results) {
  if (!results.config.world.noise.given()) return {};
  std::vector<ArmNoiseBands> bands = arm_noise_bands(arm_names(results), results.entries,
                                                     results.right_share, results.action_costs);
  const bool heard = std::any_of(bands.begin(), bands.end(), [](const ArmNoiseBands& a) {
    return std::any_of(a.bands.begin(), a.bands.end(),
                       [](const NoiseBand& b) { return b.trials > 0; });
  });
  return heard ? bands : std::vector<ArmNoiseBands>{};
}

std::vector<ArmSurfaces> surface_shares(const CampaignResults& results) {
  return arm_surfaces(arm_names(results), results.entries, results.right_share,
                      results.action_costs);
}

std::vector<ArmConfidence> arm_confidence(const CampaignResults& results) {
  return arm_confidence(arm_names(results), results.entries, results.right_share);
}

namespace {

// Per arm: the belief at the sort beside the share sorted right, overall and per confidence bin.
nlohmann::json sort_confidence_json(const CampaignResults& results) {
  nlohmann::json all = nlohmann::json::array();
  for (const ArmConfidence& c : arm_confidence(results)) {
    nlohmann::json bins = nlohmann::json::array();
    for (const ReliabilityBin& b : c.bins)
      bins.push_back({{"low", b.low},
                      {"high", b.high},
                      {"sorts", b.sorts},
                      {"mean_belief", b.mean_belief},
                      {"share_right", b.share_right}});
    all.push_back({{"arm", c.arm},
                   {"sorts", c.sorts},
                   {"mean_belief", c.mean_belief},
                   {"share_right", c.share_right},
                   {"reliability", std::move(bins)}});
  }
  return all;
}

nlohmann::json shares_json(const ConditionShares& c) {
  return {{"trials", c.trials},
          {"sorts", c.sorts},
          {"share_right", c.share_right},
          {"mean_belief", c.mean_belief},
          {"mean_recordings_heard", c.mean_heard},
          {"mean_behaviours", c.mean_behaviours},
          {"mean_cost", c.mean_cost}};
}

nlohmann::json surfaces_json(const std::vector<ArmSurfaces>& all) {
  nlohmann::json j = nlohmann::json::array();
  for (const ArmSurfaces& a : all) {
    nlohmann::json surfaces = nlohmann::json::array();
    for (const SurfaceShares& s : a.surfaces) {
      nlohmann::json one = shares_json(s);
      one["surface"] = s.surface;
      surfaces.push_back(std::move(one));
    }
    j.push_back({{"arm", a.arm}, {"surfaces", std::move(surfaces)}});
  }
  return j;
}

nlohmann::json noise_bands_json(const std::vector<ArmNoiseBands>& all) {
  nlohmann::json j = nlohmann::json::array();
  for (const ArmNoiseBands& a : all) {
    nlohmann::json bands = nlohmann::json::array();
    for (const NoiseBand& b : a.bands) {
      nlohmann::json band = shares_json(b);
      band["band"] = b.label();
      band["low_db"] = b.low ? nlohmann::json(*b.low) : nlohmann::json();
      band["high_db"] = b.high ? nlohmann::json(*b.high) : nlohmann::json();
      bands.push_back(std::move(band));
    }
    j.push_back({{"arm", a.arm}, {"bands", std::move(bands)}});
  }
  return j;
}

}  // namespace

nlohmann::json summary_json(const CampaignResults& results) {
  nlohmann::json j;
  j["campaign"] = results.identity;
  j["trials_planned"] = results.planned_trials;
  j["trials_finished"] = results.entries.size();
  j["complete"] = static_cast<int>(results.entries.size()) == results.planned_trials;
  nlohmann::json rows = nlohmann::json::array();
  for (const SummaryRow& row : summary_rows(results)) {
    nlohmann::json r = summary_json(row.summary, results.spec);
    r["arm"] = row.arm;
    r["objects"] = row.label;
    if (!results.action_costs.empty()) r["mean_cost"] = row.summary.mean_cost;
    // Under "report" whatever the reference's label: the key readers of summary.json know.
    if (row.reference)
      r["report"] = {
          {"trials", row.reference->trials},
          {"correct", row.reference->correct},
          {"accuracy", static_cast<double>(row.reference->correct) / row.reference->trials},
          {"mean_discounted_reward", row.reference->mean_discounted_reward},
          {"mean_steps", row.reference->mean_steps}};
    rows.push_back(std::move(r));
  }
  j["results"] = std::move(rows);
  if (!results.unheard_choices.empty()) j["unheard_choices"] = results.unheard_choices;
  const auto& arms = results.arms;
  for (std::size_t k = 1; k < arms.size(); ++k) {
    const TrialSummary d = paired_difference(results, arms[0].name, arms[k].name);
    j["paired_differences"].push_back(
        {{"arm", arms[k].name},
         {"minus", arms[0].name},
         {"pairs", d.trials},
         {"mean_discounted_reward_difference", d.mean_discounted_reward},
         {"ci95", d.ci95}});
  }
  nlohmann::json confusion = nlohmann::json::array();
  for (const ConfusionCounts& c : confusion_counts(results))
    confusion.push_back({{"arm", c.arm},
                         {"action", c.action},
                         {"objects", c.rows},
                         {"heard", c.columns},
                         {"counts", c.counts}});
  j["confusion"] = std::move(confusion);
  j["sort_confidence"] = sort_confidence_json(results);
  // Only when the world is heard through noise: other campaigns' summaries stay as they were.
  if (const auto bands = noise_bands(results); !bands.empty())
    j["by_noise_level"] = noise_bands_json(bands);
  // Only when the world chose tables: the lab's campaigns keep their summaries.
  if (const auto surfaces = surface_shares(results); !surfaces.empty())
    j["by_surface"] = surfaces_json(surfaces);
  const std::optional<ReferenceResults>& reference = results.config.reference;
  if (!results.heard.empty() && reference && reference->heard) {
    nlohmann::json heard = {{"classifier", reference->heard->classifier},
                            {"simulated", nlohmann::json::array()},
                            {"lab", to_json(*reference->heard)["actions"]}};
    for (const HeardCounts& h : results.heard) heard["simulated"].push_back(to_json(h));
    j["heard"] = std::move(heard);
  }
  return j;
}

namespace {

// How an arm decides, for the summary's heading.
std::string arm_text(const CampaignResults& results, const ResolvedArm& arm) {
  std::string problem =
      !results.world.arm_problem.empty()
          ? results.world.arm_problem
          : (arm.calibrate ? arm.problem + ", its observation table calibrated on the training set"
                           : arm.problem);
  if (arm.hearing() == perception::ObservationKind::graded)
    problem += ", hearing graded observations (the class and how sure the classifier was)";
  if (arm.hearing() == perception::ObservationKind::levels)
    problem += ", hearing observations graded by level (the class and how noisy its recording was)";
  if (arm.plans()) return "plans with " + problem;
  return fmt::format("fixed strategy {} with {}", arm.strategy, problem);
}

}  // namespace

int shown_actions(const CampaignResults& results) {
  const int all = static_cast<int>(results.spec.action_names.size());
  return results.world.per_object ? all : std::min(all, results.sensing_actions);
}

std::string summary_text(const CampaignResults& results) {
  std::string out;
  const std::vector<std::string> actions(
      results.spec.action_names.begin(),
      results.spec.action_names.begin() + shown_actions(results));
  const std::optional<ReferenceResults>& reference = results.config.reference;
  const bool costed = !results.action_costs.empty();  // a mean cost per trial beside the steps
  out += fmt::format("{} of {} trials; planner {} with {}\n", results.entries.size(),
                     results.planned_trials, results.config.planner.solver,
                     results.config.planner.episodes > 0
                         ? fmt::format("{} episodes per step", results.config.planner.episodes)
                         : fmt::format("{} ms per step", results.config.planner.step_ms));
  std::string current_arm;
  for (const SummaryRow& row : summary_rows(results)) {
    if (row.arm != current_arm) {
      current_arm = row.arm;
      for (const ResolvedArm& a : results.arms)
        if (a.name == row.arm) out += fmt::format("\narm {} ({})\n", row.arm, arm_text(results, a));
      out += fmt::format("  {:<24}{:>7}{:>10}{:>22}{:>7}", "objects", "trials", "accuracy",
                         "reward (95% CI)", "steps");
      if (costed) out += fmt::format("{:>8}", "cost");
      for (const auto& a : actions) out += fmt::format("{:>10}", a.substr(0, 9));
      if (reference)
        out += fmt::format("   | {}: {:>7}{:>8}", reference->label, "correct", "reward");
      out += '\n';
    }
    const TrialSummary& s = row.summary;
    out +=
        fmt::format("  {:<24}{:>7}{:>10}{:>22}{:>7.2f}", row.label, s.trials, percent(s.accuracy),
                    fmt::format("{:.2f} ± {:.2f}", s.mean_discounted_reward, s.ci95), s.mean_steps);
    if (costed) out += fmt::format("{:>8.2f}", s.mean_cost);
    for (std::size_t a = 0; a < actions.size(); ++a)
      out += fmt::format("{:>10.2f}", s.mean_action_counts[a]);
    if (row.reference)
      out += fmt::format("   | {:{}}{:>7}{:>8.2f}", "", reference->label.size() + 2,
                         fmt::format("{}/{}", row.reference->correct, row.reference->trials),
                         row.reference->mean_discounted_reward);
    out += '\n';
  }
  const auto& arms = results.arms;
  for (std::size_t k = 1; k < arms.size(); ++k) {
    const TrialSummary d = paired_difference(results, arms[0].name, arms[k].name);
    if (d.trials == 0) continue;
    out += fmt::format("\n{} minus {}, paired trials ({}): {:+.2f} ± {:.2f} (95% CI, {} pairs)\n",
                       arms[k].name, arms[0].name, results.world.pairing, d.mean_discounted_reward,
                       d.ci95, d.trials);
  }
  out += "\nhow sure each arm was when it sorted (belief in its choice at the sort):\n";
  for (const ArmConfidence& c : arm_confidence(results))
    if (c.sorts > 0)
      out += fmt::format("  {:<24} belief {:.3f}, sorted right {:.3f} ({:+.1f} points, {} sorts)\n",
                         c.arm, c.mean_belief, c.share_right,
                         100.0 * (c.mean_belief - c.share_right), c.sorts);
  const std::vector<ArmNoiseBands> bands = noise_bands(results);
  if (!bands.empty())
    out +=
        "\nper noise level (each trial's median measured event-to-background ratio): sorted "
        "right at belief; recordings heard, behaviours and their cost per trial\n";
  for (const ArmNoiseBands& a : bands)
    for (const NoiseBand& b : a.bands)
      if (b.trials > 0) out += shares_line(a.arm, b.label(), b);
  const std::vector<ArmSurfaces> surfaces = surface_shares(results);
  if (!surfaces.empty())
    out +=
        "\nper table the trials stood on: sorted right at belief; recordings heard, behaviours "
        "and their cost per trial\n";
  for (const ArmSurfaces& a : surfaces)
    for (const SurfaceShares& s : a.surfaces)
      if (s.trials > 0) out += shares_line(a.arm, s.surface, s);
  if (!results.unheard_choices.empty())
    out +=
        "\nhow each arm with unheard: auto counts outcomes it has not heard (self-play on its own "
        "problems):\n";
  for (const nlohmann::json& c : results.unheard_choices)
    out += fmt::format(
        "  {:<24} {} (commit minus share {:+.2f} ± {:.2f} expected reward per trial, {} pairs)\n",
        c.at("arm").get<std::string>(), c.at("chosen").get<std::string>(),
        c.at("commit_minus_share").get<double>(), c.at("ci95").get<double>(),
        c.at("self_play_trials").get<int>());
  return out;
}

}  // namespace echoplan::experiment
