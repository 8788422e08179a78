#include "experiment/campaign_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>

#include "experiment/campaign_runner.h"
#include "experiment/trial_log.h"

namespace echoplan::experiment {

namespace {

namespace fs = std::filesystem;

// The seed report's trials, per object: Table 5.1 (the four objects, the tuned table) and Table 5.3
// (the weighted can and mug, no retraining). Means computed from the tables' rows.
const std::map<std::string, ReportedResult>& reported_results() {
  static const std::map<std::string, ReportedResult> table = {
      {"pringles_can", {10, 10, 8.24879, 2.6}},
      {"coffee_mug", {10, 10, 8.24658, 2.5}},
      {"plastic_cup", {10, 10, 7.59650, 3.2}},
      {"paper_base", {10, 10, 6.97004, 3.8}},
      {"original objects", {40, 40, 7.76548, 3.025}},
      {"pringles_can_weighted", {10, 7, -13.52690, 2.7}},
      {"coffee_mug_weighted", {10, 9, -2.64229, 2.9}},
      {"variants", {20, 16, -8.08459, 2.8}},
  };
  return table;
}

std::vector<TrialRecord> records_where(const CampaignResults& results, const std::string& arm,
                                       const std::function<bool(const ObjectGroup&)>& keep) {
  std::map<std::string, const ObjectGroup*> groups;
  for (const ObjectGroup& g : results.config.groups) groups[g.object] = &g;
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
  const std::vector<TrialJob> jobs = campaign_jobs(results.config);
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

std::optional<ReportedResult> reported_result(const std::string& object) {
  auto it = reported_results().find(object);
  if (it == reported_results().end()) return std::nullopt;
  return it->second;
}

std::vector<SummaryRow> summary_rows(const CampaignResults& results) {
  const int num_actions = static_cast<int>(results.spec.action_names.size());
  std::vector<SummaryRow> rows;
  for (const ArmConfig& arm : results.config.arms) {
    auto add = [&](const std::string& label, const std::function<bool(const ObjectGroup&)>& keep,
                   bool compare) {
      const std::vector<TrialRecord> records = records_where(results, arm.name, keep);
      if (records.empty()) return;
      rows.push_back({arm.name, label, summarize(records, num_actions),
                      compare ? reported_result(label) : std::nullopt});
    };
    bool originals = false;
    bool variants = false;
    for (const ObjectGroup& g : results.config.groups) {
      add(
          g.object, [&](const ObjectGroup& other) { return other.object == g.object; }, true);
      (g.object == g.plays ? originals : variants) = true;
    }
    // The report's aggregates hold exactly its four objects and two variants; compare only then.
    std::vector<std::string> original_names, variant_names;
    for (const ObjectGroup& g : results.config.groups)
      (g.object == g.plays ? original_names : variant_names).push_back(g.object);
    const bool report_originals =
        original_names ==
        std::vector<std::string>{"pringles_can", "coffee_mug", "plastic_cup", "paper_base"};
    const bool report_variants =
        variant_names == std::vector<std::string>{"pringles_can_weighted", "coffee_mug_weighted"};
    if (originals && variants) {
      add(
          "original objects", [](const ObjectGroup& g) { return g.object == g.plays; },
          report_originals);
      add(
          "variants", [](const ObjectGroup& g) { return g.object != g.plays; }, report_variants);
    }
    add(
        "all", [](const ObjectGroup&) { return true; }, false);
  }
  return rows;
}

std::vector<ConfusionCounts> confusion_counts(const CampaignResults& results) {
  const auto& symbols = results.spec.observation.names;
  std::vector<std::string> classes;
  for (const std::string& s : symbols)
    if (s != "none") classes.push_back(s);
  std::vector<ConfusionCounts> all;
  for (const ArmConfig& arm : results.config.arms) {
    // Sensing actions: those that were ever followed by a heard class in this campaign, in action
    // order.
    for (std::size_t a = 0; a < results.spec.action_names.size(); ++a) {
      ConfusionCounts c;
      c.arm = arm.name;
      c.action = results.spec.action_names[a];
      c.columns = classes;
      for (const ObjectGroup& g : results.config.groups) c.rows.push_back(g.object);
      c.counts.assign(c.rows.size(), std::vector<int>(classes.size(), 0));
      bool any = false;
      for (const JournalEntry& e : results.entries) {
        if (e.arm != arm.name) continue;
        const std::size_t row = std::find(c.rows.begin(), c.rows.end(), e.object) - c.rows.begin();
        if (row >= c.rows.size()) continue;
        for (const StepRecord& s : e.result.steps) {
          const int o = s.observation.index;
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

void write_tables(const fs::path& directory, const CampaignResults& results) {
  TrialLog all(directory, results.spec, results.belief_particles, {"arm", "object"});
  for (const JournalEntry& e : results.entries)
    all.write_trial(e.result.record, e.result.steps, {e.arm, e.object});
  for (const ArmConfig& arm : results.config.arms) {
    TrialLog per_arm(directory / "arms" / arm.name, results.spec, results.belief_particles,
                     {"object"});
    for (const JournalEntry& e : results.entries)
      if (e.arm == arm.name) per_arm.write_trial(e.result.record, e.result.steps, {e.object});
  }
}

nlohmann::json summary_json(const CampaignResults& results) {
  nlohmann::json j;
  j["campaign"] = results.config.identity();
  j["trials_planned"] = results.planned_trials;
  j["trials_finished"] = results.entries.size();
  j["complete"] = static_cast<int>(results.entries.size()) == results.planned_trials;
  nlohmann::json rows = nlohmann::json::array();
  for (const SummaryRow& row : summary_rows(results)) {
    nlohmann::json r = summary_json(row.summary, results.spec);
    r["arm"] = row.arm;
    r["objects"] = row.label;
    if (row.reported)
      r["report"] = {
          {"trials", row.reported->trials},
          {"correct", row.reported->correct},
          {"accuracy", static_cast<double>(row.reported->correct) / row.reported->trials},
          {"mean_discounted_reward", row.reported->mean_discounted_reward},
          {"mean_steps", row.reported->mean_steps}};
    rows.push_back(std::move(r));
  }
  j["results"] = std::move(rows);
  const auto& arms = results.config.arms;
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
  return j;
}

std::string summary_text(const CampaignResults& results) {
  std::string out;
  const auto& actions = results.spec.action_names;
  out += fmt::format("{} of {} trials; planner {} with {}\n", results.entries.size(),
                     results.planned_trials, results.config.planner.solver,
                     results.config.planner.episodes > 0
                         ? fmt::format("{} episodes per step", results.config.planner.episodes)
                         : fmt::format("{} ms per step", results.config.planner.step_ms));
  std::string current_arm;
  for (const SummaryRow& row : summary_rows(results)) {
    if (row.arm != current_arm) {
      current_arm = row.arm;
      std::string problem;
      for (const ArmConfig& a : results.config.arms)
        if (a.name == row.arm) problem = a.problem;
      out += fmt::format("\narm {} (plans with {})\n", row.arm, problem);
      out += fmt::format("  {:<24}{:>7}{:>10}{:>22}{:>7}", "objects", "trials", "accuracy",
                         "reward (95% CI)", "steps");
      for (const auto& a : actions) out += fmt::format("{:>10}", a.substr(0, 9));
      out += fmt::format("   | report: {:>7}{:>8}\n", "correct", "reward");
    }
    const TrialSummary& s = row.summary;
    out +=
        fmt::format("  {:<24}{:>7}{:>10}{:>22}{:>7.2f}", row.label, s.trials, percent(s.accuracy),
                    fmt::format("{:.2f} ± {:.2f}", s.mean_discounted_reward, s.ci95), s.mean_steps);
    for (double c : s.mean_action_counts) out += fmt::format("{:>10.2f}", c);
    if (row.reported)
      out += fmt::format("   |         {:>7}{:>8.2f}",
                         fmt::format("{}/{}", row.reported->correct, row.reported->trials),
                         row.reported->mean_discounted_reward);
    out += '\n';
  }
  const auto& arms = results.config.arms;
  for (std::size_t k = 1; k < arms.size(); ++k) {
    const TrialSummary d = paired_difference(results, arms[0].name, arms[k].name);
    if (d.trials == 0) continue;
    out += fmt::format(
        "\n{} minus {}, paired trials (same objects, same world noise): {:+.2f} ± {:.2f} (95% CI, "
        "{} pairs)\n",
        arms[k].name, arms[0].name, d.mean_discounted_reward, d.ci95, d.trials);
  }
  return out;
}

}  // namespace echoplan::experiment
