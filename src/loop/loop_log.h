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
//                              the belief before the step; the action's attempts, what the
//                              recording lost (`capture`: overflow callbacks, dropped frames, a
//                              stream error; `dropout` marks a clip with a gap) and the step's
//                              fault (loop/step_fault.h), null when none
//   trial.json                 the run's settings and result, with the trial's capture losses
//                              summed and its faults listed (step, kind)
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "loop/trial_runner.h"
#include "pomdp/object_identification_model.h"

namespace echoplan::loop {

class LoopLog {
 public:
  // Creates DIR and DIR/clips; throws InputError naming the file when either cannot be written.
  LoopLog(const std::filesystem::path& directory, const pomdp::ObjectIdentificationModel& model);

  // Writes one step; a world without a robot (recorded data replayed) leaves the robot's fields
  // empty. Returns the step's JSON object (what loop_steps.jsonl got).
  nlohmann::json write_step(const Step& step);

  // Writes DIR/trial.json: `settings` (what the run was asked to do) and, unless the trial was cut
  // short (`trial` empty), its result: believed state, steps, discounted reward, collision, capped,
  // final action; `interrupted` says which.
  void write_trial(nlohmann::json settings, const std::optional<Trial>& trial) const;

  const std::filesystem::path& directory() const { return directory_; }
  int steps_written() const { return steps_written_; }

 private:
  std::filesystem::path directory_;
  const pomdp::ObjectIdentificationModel& model_;
  std::vector<std::string> objects_;
  std::ofstream csv_;
  std::ofstream jsonl_;
  int steps_written_ = 0;
};

}  // namespace echoplan::loop
