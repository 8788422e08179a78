#include "experiment/trial_log.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "common/csv_reader.h"
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
int index_of(const std::vector<std::string>& names, const std::string& name) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  return -1;
}
}  // namespace

std::vector<LoggedTrial> read_steps_csv(const std::filesystem::path& path,
                                        const pomdp::ModelSpec& spec) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), 0, "cannot open the steps file");
  return read_steps_csv(in, path.string(), spec);
}

std::vector<LoggedTrial> read_steps_csv(std::istream& in, const std::string& file,
                                        const pomdp::ModelSpec& spec) {
  if (!spec.observation.discrete)
    throw InputError(file, 0, "the problem's observations are continuous; steps need symbols");
  std::string line;
  std::vector<std::string> header, fields;
  if (!std::getline(in, line) || !split_csv_line(line, header))
    throw InputError(file, 1, "empty file or broken header (expected trial,step,action,...)");
  const int c_trial = index_of(header, "trial"), c_step = index_of(header, "step");
  const int c_action = index_of(header, "action"), c_obs = index_of(header, "observation");
  const int c_reward = index_of(header, "reward");
  for (const char* needed : {"trial", "step", "action", "observation"})
    if (index_of(header, needed) < 0)
      throw InputError(file, 1, fmt::format("no '{}' column in the header", needed));

  auto integer = [&](const std::string& text, int line_no, const char* what) {
    std::size_t used = 0;
    int value = 0;
    try {
      value = std::stoi(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != text.size() || value < 0)
      throw InputError(file, line_no, fmt::format("{} '{}' is not a count >= 0", what, text));
    return value;
  };

  std::vector<LoggedTrial> trials;
  for (int line_no = 2; std::getline(in, line); ++line_no) {
    if (line.empty() || line == "\r") continue;
    if (!split_csv_line(line, fields)) throw InputError(file, line_no, "unterminated quote");
    if (fields.size() != header.size())
      throw InputError(file, line_no,
                       fmt::format("{} fields, the header has {}", fields.size(), header.size()));
    LoggedStep step;
    step.line = line_no;
    const int trial = integer(fields[c_trial], line_no, "trial");
    step.step = integer(fields[c_step], line_no, "step");
    step.action = index_of(spec.action_names, fields[c_action]);
    if (step.action < 0)
      throw InputError(file, line_no,
                       fmt::format("unknown action '{}' for this problem", fields[c_action]));
    step.observation = index_of(spec.observation.names, fields[c_obs]);
    if (step.observation < 0)
      throw InputError(file, line_no,
                       fmt::format("unknown observation '{}' for this problem", fields[c_obs]));
    if (c_reward >= 0) {
      std::size_t used = 0;
      try {
        step.reward = std::stod(fields[c_reward], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != fields[c_reward].size())
        throw InputError(file, line_no,
                         fmt::format("reward '{}' is not a number", fields[c_reward]));
    }
    if (trials.empty() || trials.back().trial != trial) {
      for (const LoggedTrial& t : trials)
        if (t.trial == trial)
          throw InputError(file, line_no,
                           fmt::format("trial {} continues after another trial's rows", trial));
      trials.push_back(LoggedTrial{trial, {}});
    }
    LoggedTrial& current = trials.back();
    if (step.step != static_cast<int>(current.steps.size()))
      throw InputError(file, line_no,
                       fmt::format("trial {}: step {} where step {} was expected", trial, step.step,
                                   current.steps.size()));
    current.steps.push_back(step);
  }
  return trials;
}

TrialLog::TrialLog(const std::filesystem::path& directory, const pomdp::ModelSpec& spec,
                   int belief_particles, std::vector<std::string> extra_columns,
                   std::vector<std::string> trial_columns)
    : directory_(directory),
      spec_(spec),
      belief_particles_(belief_particles),
      extra_columns_(std::move(extra_columns)),
      trial_columns_(std::move(trial_columns)) {
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error)
    throw InputError(directory_.string(), 0, "cannot create output folder: " + error.message());
  trials_ = open_for_writing(directory_ / "trials.csv");
  steps_ = open_for_writing(directory_ / "steps.csv");

  trials_ << "trial,true_state,believed_state,steps";
  // The whole field is quoted when a name holds a separator ("n_open,left" -> "\"n_open,left\"").
  for (const auto& action : spec_.action_names) trials_ << ',' << csv_field("n_" + action);
  trials_ << ",discounted_reward,collision";
  for (const auto& column : extra_columns_) trials_ << ',' << csv_field(column);
  for (const auto& column : trial_columns_) trials_ << ',' << csv_field(column);
  trials_ << '\n';
  steps_ << "trial,step,action,observation";
  const std::string prefix = belief_particles_ > 0 ? "particles_" : "p_";
  if (!spec_.state.discrete_value_names.empty())
    for (const auto& value : spec_.state.discrete_value_names[0])
      steps_ << ',' << csv_field(prefix + value);
  steps_ << ",reward,episodes,heard_probability,heard_ebr_db";
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

std::string TrialLog::observation_text(const pomdp::Observation& observation,
                                       const std::vector<std::string>& names) const {
  if (observation.index >= 0) {
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
  write_trial(trial, steps, std::vector<std::string>(extra_columns_.size()),
              std::vector<std::string>(trial_columns_.size()));
}

void TrialLog::write_trial(const TrialRecord& trial, const std::vector<StepRecord>& steps,
                           const std::vector<std::string>& extra_values,
                           const std::vector<std::string>& trial_values,
                           const std::vector<std::string>* observation_names) {
  if (extra_values.size() != extra_columns_.size() || trial_values.size() != trial_columns_.size())
    throw std::invalid_argument("TrialLog::write_trial: one value per extra column expected");
  std::string extras, trial_extras;
  for (const auto& value : extra_values) extras += ',' + csv_field(value);
  for (const auto& value : trial_values) trial_extras += ',' + csv_field(value);
  for (const StepRecord& s : steps) {
    steps_ << s.trial << ',' << s.step << ',' << csv_field(spec_.action_names[s.action]) << ','
           << observation_text(s.observation,
                               observation_names ? *observation_names : spec_.observation.names);
    for (double p : s.belief) {
      if (belief_particles_ > 0)
        steps_ << ',' << std::llround(p * belief_particles_);
      else
        steps_ << ',' << number(p);
    }
    steps_ << ',' << number(s.reward) << ',' << s.episodes << ','
           << (s.heard_probability ? number(*s.heard_probability) : std::string()) << ','
           << (s.heard_ebr_db ? number(*s.heard_ebr_db) : std::string()) << extras << '\n';
  }
  trials_ << trial.trial << ',' << state_name(trial.true_state) << ','
          << state_name(trial.believed_state) << ',' << trial.steps;
  for (int count : trial.action_counts) trials_ << ',' << count;
  trials_ << ',' << number(trial.discounted_reward) << ',' << (trial.collision ? 1 : 0) << extras
          << trial_extras << '\n';
  // Flush per trial: an interrupted run keeps every finished trial, and no half rows.
  steps_.flush();
  trials_.flush();
  if (!steps_ || !trials_) throw InputError(directory_.string(), 0, "writing trial results failed");
}

nlohmann::json summary_json(const TrialSummary& summary, const pomdp::ModelSpec& spec) {
  nlohmann::json j;
  j["trials"] = summary.trials;
  j["accuracy"] = summary.accuracy;
  if (summary.sorted_right) j["sorted_right"] = *summary.sorted_right;
  j["mean_discounted_reward"] = summary.mean_discounted_reward;
  j["sd_discounted_reward"] = summary.sd_discounted_reward;
  j["ci95"] = summary.ci95;
  j["mean_steps"] = summary.mean_steps;
  j["collisions"] = summary.collisions;
  j["capped"] = summary.capped;
  if (summary.expected_reward.n > 0)
    j["expected_discounted_reward"] = {{"mean", summary.expected_reward.mean},
                                       {"sd", summary.expected_reward.sd},
                                       {"ci95", summary.expected_reward.half_width},
                                       {"trials", summary.expected_reward.n}};
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

void TrialLog::write_expected_rewards(const std::vector<double>& values) const {
  const std::filesystem::path path = directory_ / "expected_rewards.csv";
  std::ofstream out = open_for_writing(path);
  out << "trial,expected_reward\n";
  for (std::size_t t = 0; t < values.size(); ++t) out << t << ',' << number(values[t]) << '\n';
  if (!out) throw InputError(path.string(), 0, "writing failed");
}

}  // namespace echoplan::experiment
