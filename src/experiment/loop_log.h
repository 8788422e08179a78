// The log of closed-loop trials, step by step: what the robot did, the clip the recorder heard, how
// the service classified it, what the planner was told, the belief and the reward.
//
// Files in DIR (rows flushed after every step, so an interrupted run keeps every finished step):
//   clips/TTT_SS_<action>.wav  the recording of each sensing action (trial TTT, step SS), as heard
//   loop_steps.csv             trial, step, action, status, heard, probability, observation,
//                              p_<object>... (the belief after the step; empty when the trial ended
//                              with it), reward, clip
//   loop_steps.jsonl           one JSON object per step with everything above plus the robot's
//                              reason and duration, every class probability, the classifier's
//                              distance and time to answer (observe_ms), the clip's features and
//                              the belief before the step
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "experiment/robot_environment.h"
#include "pomdp/object_identification_model.h"

namespace echoplan::experiment {

class LoopLog {
 public:
  // Creates DIR and DIR/clips; throws InputError naming the file when either cannot be written.
  LoopLog(const std::filesystem::path& directory, const pomdp::ObjectIdentificationModel& model);

  // Writes one step. `belief_before` is the object marginal the action was chosen from;
  // `belief_after` the marginal after the update, or nullptr when the step ended the trial.
  // Returns the step's JSON object (what loop_steps.jsonl got).
  nlohmann::json write_step(const LoopStep& step, const std::vector<double>& belief_before,
                            const std::vector<double>* belief_after);

  const std::filesystem::path& directory() const { return directory_; }

 private:
  std::filesystem::path directory_;
  std::vector<std::string> objects_;
  std::ofstream csv_;
  std::ofstream jsonl_;
};

}  // namespace echoplan::experiment
