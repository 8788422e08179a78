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
// Both files may end with extra columns named at construction (a campaign adds arm and object); a
// reader of the columns above finds them where they always were.
//   belief columns are particle counts ("particles_<value>", the columns of the seed's Table 5.2)
//   when the belief holds `belief_particles` > 0 particles, probabilities ("p_<value>") otherwise.
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiment/trial_runner.h"
#include "experiment/trial_summary.h"

namespace echoplan::experiment {

class TrialLog final : public TrialObserver {
 public:
  // Creates `directory` if needed; throws InputError when it cannot be written.
  TrialLog(const std::filesystem::path& directory, const pomdp::ModelSpec& spec,
           int belief_particles, std::vector<std::string> extra_columns = {});

  void trial_finished(const TrialRecord& trial, const std::vector<StepRecord>& steps) override;
  // As trial_finished, with one value per extra column, repeated on the trial's row and each
  // step's.
  void write_trial(const TrialRecord& trial, const std::vector<StepRecord>& steps,
                   const std::vector<std::string>& extra_values);

  // Writes summary.json: the summary's fields plus everything in `run` (problem, solver, seed,
  // ...).
  void write_summary(const TrialSummary& summary, const nlohmann::json& run) const;

 private:
  std::string state_name(int value) const;
  std::string observation_text(const pomdp::Observation& observation) const;

  std::filesystem::path directory_;
  pomdp::ModelSpec spec_;
  int belief_particles_;
  std::vector<std::string> extra_columns_;
  std::ofstream trials_;
  std::ofstream steps_;
};

// The summary as JSON (the content of summary.json without the run description).
nlohmann::json summary_json(const TrialSummary& summary, const pomdp::ModelSpec& spec);

}  // namespace echoplan::experiment
