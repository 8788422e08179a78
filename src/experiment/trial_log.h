// Writes trial results as they finish: DIR/trials.csv, DIR/steps.csv and, at the end,
// DIR/summary.json. Rows are flushed after every trial, so an interrupted run leaves valid CSV
// files holding every finished trial. Numbers are printed with a fixed format, so the same results
// give byte-identical files.
//
// trials.csv: trial, true_state, believed_state, steps, n_<action>... , discounted_reward,
// collision steps.csv:  trial, step, action, observation, <belief column per value of discrete
// variable 0>...,
//             reward, episodes, heard_probability
//   heard_probability: the classifier's calibrated probability of the heard class, empty when the
//   world draws observations from a table.
// Both files may end with extra columns named at construction (a campaign adds arm, object and
// session), and trials.csv with trial columns after them (a campaign adds the trial's seed); a
// reader of the columns above finds them where they always were.
//   belief columns are particle counts ("particles_<value>", the columns of the report's Table 5.2)
//   when the belief holds `belief_particles` > 0 particles, probabilities ("p_<value>") otherwise.
//
// read_steps_csv() reads steps.csv back (the action and observation history of every trial), for
// `echoplan certify`; any writer of the same columns (the closed loop, another planner) can be
// read.
#pragma once

#include <filesystem>
#include <fstream>
#include <istream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiment/trial_records.h"
#include "experiment/trial_summary.h"

namespace echoplan::experiment {

class TrialLog final {
 public:
  // Creates `directory` if needed; throws InputError when it cannot be written.
  TrialLog(const std::filesystem::path& directory, const pomdp::ModelSpec& spec,
           int belief_particles, std::vector<std::string> extra_columns = {},
           std::vector<std::string> trial_columns = {});

  // Writes one finished trial: its row in trials.csv and its steps' rows in steps.csv.
  void trial_finished(const TrialRecord& trial, const std::vector<StepRecord>& steps);
  // As trial_finished, with one value per extra column, repeated on the trial's row and each
  // step's, and one per trial column, on the trial's row.
  // `observation_names`, when given, names the trial's observations instead of the spec's (a
  // campaign arm that hears other symbols than the others, e.g. graded ones).
  void write_trial(const TrialRecord& trial, const std::vector<StepRecord>& steps,
                   const std::vector<std::string>& extra_values,
                   const std::vector<std::string>& trial_values = {},
                   const std::vector<std::string>* observation_names = nullptr);

  // Writes summary.json: the summary's fields plus everything in `run` (problem, solver, seed,
  // ...).
  void write_summary(const TrialSummary& summary, const nlohmann::json& run) const;
  // Writes expected_rewards.csv (`trial,expected_reward`, one row per trial in order): the trials'
  // rewards in expectation given what they heard (expected_reward.h), for pairing two runs.
  void write_expected_rewards(const std::vector<double>& values) const;

 private:
  std::string state_name(int value) const;
  std::string observation_text(const pomdp::Observation& observation,
                               const std::vector<std::string>& names) const;

  std::filesystem::path directory_;
  pomdp::ModelSpec spec_;
  int belief_particles_;
  std::vector<std::string> extra_columns_;
  std::vector<std::string> trial_columns_;
  std::ofstream trials_;
  std::ofstream steps_;
};

// One logged decision: the action taken and what was heard after it.
struct LoggedStep {
  int step = 0;
  int action = 0;       // index into the model's action names
  int observation = 0;  // index into the model's (discrete) observation names
  double reward = 0.0;
  int line = 0;  // 1-based line in steps.csv, for messages
};

struct LoggedTrial {
  int trial = 0;
  std::vector<LoggedStep> steps;  // in step order, 0, 1, 2, ...
};

// Reads steps.csv (columns found by their header names: trial, step, action, observation, reward;
// others are ignored), naming actions and observations as in `spec`. Trials come in file order.
// Throws InputError naming the file and line of a missing column, an unknown action or
// observation, a bad number, or a step out of order.
std::vector<LoggedTrial> read_steps_csv(const std::filesystem::path& path,
                                        const pomdp::ModelSpec& spec);
// The same from a stream; `file` names it in messages.
std::vector<LoggedTrial> read_steps_csv(std::istream& in, const std::string& file,
                                        const pomdp::ModelSpec& spec);

// The summary as JSON (the content of summary.json without the run description).
nlohmann::json summary_json(const TrialSummary& summary, const pomdp::ModelSpec& spec);

}  // namespace echoplan::experiment
