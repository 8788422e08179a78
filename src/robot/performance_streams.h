// A robot's sensor streams (joint efforts, a wrist's force), live, cut into performances: the
// samples that arrived between the marker saying an action began and the one saying it ended, as
// a bag import cuts a recorded bag (robot/ros/bag_import.h), so what is heard live is what a bag of
// the same run replays. The ROS observation node adds each stream's messages and each marker as
// they arrive and takes, per observation request, the series of the performance just ended; nothing
// here knows about ROS.
//
// Which performance a request gets: the planner marks each sensing action (start, execute, end)
// and asks for its observation right after the end, before the next action starts, so the request
// for action A takes the last performance that ended, which must be one of A; the next take()
// waits for a new one. Times are seconds on one clock for markers and messages (their arrival),
// each series' from its performance's start.
//
// What cannot be heard is an InputError naming the source (the marker topic or the stream's topic),
// which the node answers as a fault of that performance (the planner skips its observation):
//   - no performance of A ended within the timeout (no end marker; the planner publishes none);
//   - the last performance that ended was of another action;
//   - a stream with no message during the performance (it stopped: says how long before the
//     performance began its last message came), or with one (fewer than the two a series needs);
//   - a message of a stream during the performance that could not be read (a joint missing): the
//     first such problem, as the reader stated it.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "signal/series.h"

namespace echoplan::robot {

class PerformanceStreams {
 public:
  // `streams`: where each stream's messages come from (the topic), by stream index; `markers`:
  // where the markers come from. Both name the source in messages.
  PerformanceStreams(std::vector<std::string> streams, std::string markers);

  // A start marker of `action` at `time`. Returns what it cut short (a performance under way,
  // dropped), or empty. Thread-safe, as are the others.
  std::string begin(const std::string& action, double time);
  // An end marker at `time`: the performance under way is complete. Returns why it was ignored (no
  // performance under way), or empty.
  std::string end(double time);
  // One message of stream `stream` at `time`: its channels' names (fixed by the stream's first
  // message) and values, one per channel. Outside a performance it only tells when the stream last
  // spoke.
  void add(std::size_t stream, double time, const std::vector<std::string>& channels,
           const std::vector<double>& values);
  // A message of stream `stream` at `time` that could not be read (`problem` says why): the
  // performance under way cannot be heard through that stream.
  void bad_message(std::size_t stream, double time, const std::string& problem);

  // The series of `streams` (indices) in the performance of `action` that ended last, waiting up
  // to `timeout` for its end marker; throws InputError as described above. Either way the
  // performance is used up.
  std::vector<signal::Series> take(const std::string& action,
                                   const std::vector<std::size_t>& streams,
                                   std::chrono::milliseconds timeout);

 private:
  struct Performance {
    std::string action;
    double start = 0, end = 0;
    std::vector<signal::Series> series;  // per stream
    std::vector<std::string> problems;   // per stream: the first message that could not be read
    std::vector<std::optional<double>> last_before;  // per stream: its last message before start
  };
  // The series of stream `s` in `done`, or the InputError saying why it cannot be heard (caller
  // holds mutex_).
  signal::Series stream_series(const Performance& done, std::size_t s) const;

  const std::vector<std::string> streams_;
  const std::string markers_;
  std::mutex mutex_;
  std::condition_variable ended_;
  std::optional<Performance> open_;                  // guarded by mutex_
  std::optional<Performance> finished_;              // the last ended, not yet taken
  std::vector<std::optional<double>> last_message_;  // per stream: when it last spoke
};

}  // namespace echoplan::robot
