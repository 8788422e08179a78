#include "experiment/trial_log.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "common/error.h"

namespace echoplan::experiment {

namespace {
std::ofstream open_for_writing(const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::trunc);
  if (!out) throw InputError(path.string(), 0, "cannot open for writing");
  return out;
}

// Shortest round-trip text of a double: deterministic and exact.
std::string number(double x) { return fmt::format("{}", x); }

// CSV-safe value: names come from problem files, so quote them if they contain separators.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}
}  // namespace

TrialLog::TrialLog(const std::filesystem::path& directory, const pomdp::ModelSpec& spec,
                   int belief_particles, std::vector<std::string> extra_columns)
    : directory_(directory),
      spec_(spec),
      belief_particles_(belief_particles),
      extra_columns_(std::move(extra_columns)) {
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error)
    throw InputError(directory_.string(), 0, "cannot create output folder: " + error.message());
  trials_ = open_for_writing(directory_ / "trials.csv");
  steps_ = open_for_writing(directory_ / "steps.csv");

  trials_ << "trial,true_state,believed_state,steps";
  for (const auto& action : spec_.action_names) trials_ << ",n_" << csv_field(action);
  trials_ << ",discounted_reward,collision";
  for (const auto& column : extra_columns_) trials_ << ',' << csv_field(column);
  trials_ << '\n';
  steps_ << "trial,step,action,observation";
  const char* prefix = belief_particles_ > 0 ? ",particles_" : ",p_";
  if (!spec_.state.discrete_value_names.empty())
    for (const auto& value : spec_.state.discrete_value_names[0])
      steps_ << prefix << csv_field(value);
  steps_ << ",reward,episodes,heard_probability";
  for (const auto& column : extra_columns_) steps_ << ',' << csv_field(column);
  steps_ << '\n';
  trials_.flush();
  steps_.flush();
}

std::string TrialLog::state_name(int value) const {
  const auto& names = spec_.state.discrete_value_names;
  if (!names.empty() && value >= 0 && value < static_cast<int>(names[0].size()))
    return csv_field(names[0][value]);
  return std::to_string(value);
}

std::string TrialLog::observation_text(const pomdp::Observation& observation) const {
  if (observation.index >= 0) {
    const auto& names = spec_.observation.names;
    if (observation.index < static_cast<int>(names.size()))
      return csv_field(names[observation.index]);
    return std::to_string(observation.index);
  }
  // A continuous observation: its components separated by spaces, in one field.
  std::string text;
  for (double v : observation.values) text += (text.empty() ? "" : " ") + number(v);
  return text;
}

void TrialLog::trial_finished(const TrialRecord& trial, const std::vector<StepRecord>& steps) {
  write_trial(trial, steps, std::vector<std::string>(extra_columns_.size()));
}

void TrialLog::write_trial(const TrialRecord& trial, const std::vector<StepRecord>& steps,
                           const std::vector<std::string>& extra_values) {
  if (extra_values.size() != extra_columns_.size())
    throw std::invalid_argument("TrialLog::write_trial: one value per extra column expected");
  std::string extras;
  for (const auto& value : extra_values) extras += ',' + csv_field(value);
  for (const StepRecord& s : steps) {
    steps_ << s.trial << ',' << s.step << ',' << csv_field(spec_.action_names[s.action]) << ','
           << observation_text(s.observation);
    for (double p : s.belief) {
      if (belief_particles_ > 0)
        steps_ << ',' << std::llround(p * belief_particles_);
      else
        steps_ << ',' << number(p);
    }
    steps_ << ',' << number(s.reward) << ',' << s.episodes << ','
           << (s.heard_probability ? number(*s.heard_probability) : std::string()) << extras
           << '\n';
  }
  trials_ << trial.trial << ',' << state_name(trial.true_state) << ','
          << state_name(trial.believed_state) << ',' << trial.steps;
  for (int count : trial.action_counts) trials_ << ',' << count;
  trials_ << ',' << number(trial.discounted_reward) << ',' << (trial.collision ? 1 : 0) << extras
          << '\n';
  // Flush per trial: an interrupted run keeps every finished trial, and no half rows.
  steps_.flush();
  trials_.flush();
  if (!steps_ || !trials_) throw InputError(directory_.string(), 0, "writing trial results failed");
}

nlohmann::json summary_json(const TrialSummary& summary, const pomdp::ModelSpec& spec) {
  nlohmann::json j;
  j["trials"] = summary.trials;
  j["accuracy"] = summary.accuracy;
  j["mean_discounted_reward"] = summary.mean_discounted_reward;
  j["sd_discounted_reward"] = summary.sd_discounted_reward;
  j["ci95"] = summary.ci95;
  j["mean_steps"] = summary.mean_steps;
  j["collisions"] = summary.collisions;
  j["capped"] = summary.capped;
  nlohmann::json counts = nlohmann::json::object();
  for (std::size_t a = 0; a < spec.action_names.size(); ++a)
    counts[spec.action_names[a]] = summary.mean_action_counts[a];
  j["mean_action_counts"] = counts;
  return j;
}

void TrialLog::write_summary(const TrialSummary& summary, const nlohmann::json& run) const {
  nlohmann::json j = summary_json(summary, spec_);
  j["run"] = run;
  std::ofstream out = open_for_writing(directory_ / "summary.json");
  out << j.dump(2) << '\n';
  if (!out) throw InputError((directory_ / "summary.json").string(), 0, "writing failed");
}

}  // namespace echoplan::experiment
