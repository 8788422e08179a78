// The rows a robot's sensors other than the microphone report for its performances (a haptic
// sensor's features of one press), matched to the observation requests that need them. The ROS
// observation node adds each row as it arrives on the feature topic and takes, per request, the
// rows of the action being observed; nothing here knows about ROS.
//
// Which rows belong to the performance being observed: the planner asks for one observation per
// sensing action and waits for the answer before the next action starts, so a row that arrived
// after the previous request was answered is of the performance now observed. A request for
// action A therefore takes, for each sensor modality of A, the one row named (A, modality) among
// the rows that arrived since the previous take(), waiting up to a timeout for rows not there yet
// (a robot may publish them just after it answered ExecuteAction); then the window starts anew, so
// rows left in it (another behaviour's) are dropped with the next take().
//
// Errors are InputError naming the source (the topic):
//   - no row of a modality within the timeout: says which rows did arrive, and which were ignored;
//   - two rows of one (action, modality) in the window: one performance gives one row per sensor.
//     A robot that published twice, or published for an action that failed (which the planner
//     does not observe), would otherwise have a row taken for the wrong performance.
// A row no request can use (a behaviour or sensor the model does not read, a non-finite value) is
// refused by add(), which says why, so the node can log it the moment it arrives.
#pragma once

#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace echoplan::robot {

struct PerformanceRow {
  std::string behaviour;  // the action performed
  std::string modality;   // the sensor
  std::vector<double> values;
};

class PerformanceRows {
 public:
  // `sensors`: per action, the modalities whose rows come from other sensors (the model's
  // modalities without a clip extractor). `source` names where rows come from in messages.
  PerformanceRows(std::map<std::string, std::vector<std::string>> sensors, std::string source);

  // Keeps `row` for the next take(). Returns why it was refused (empty: kept). Thread-safe.
  std::string add(PerformanceRow row);

  struct Taken {
    std::vector<std::vector<double>> rows;  // one per requested modality, in its order
    std::vector<std::string> unused;        // "behaviour/modality" of rows dropped with the window
  };
  // The rows of `action`'s sensor modalities (sensors[action], in that order), waiting up to
  // `timeout` for those not there yet; throws InputError as described above. Either way the
  // window starts anew. Thread-safe (one take() at a time is what the protocol makes).
  Taken take(const std::string& action, std::chrono::milliseconds timeout);

 private:
  // Every modality of `action` has a row in the window (caller holds mutex_).
  bool complete(const std::string& action) const;
  std::string missing_text(const std::string& action, std::chrono::milliseconds timeout) const;

  const std::map<std::string, std::vector<std::string>> sensors_;
  const std::string source_;
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::vector<PerformanceRow> window_;  // guarded by mutex_
  std::vector<std::string> ignored_;    // why rows in the window were refused, for messages
};

}  // namespace echoplan::robot
