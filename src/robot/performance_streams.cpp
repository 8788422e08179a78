#include "robot/performance_streams.h"

#include <fmt/format.h>

#include <algorithm>

#include "common/error.h"

namespace echoplan::robot {

PerformanceStreams::PerformanceStreams(std::vector<std::string> streams, std::string markers)
    : streams_(std::move(streams)), markers_(std::move(markers)), last_message_(streams_.size()) {}

std::string PerformanceStreams::begin(const std::string& action, double time) {
  std::lock_guard lock(mutex_);
  std::string dropped;
  if (open_)
    dropped = fmt::format(
        "a start of '{}' while '{}' was under way (since {:.3f} s): that "
        "performance had no end and is dropped",
        action, open_->action, time - open_->start);
  open_ = Performance{action,
                      time,
                      time,
                      std::vector<signal::Series>(streams_.size()),
                      std::vector<std::string>(streams_.size()),
                      last_message_};
  return dropped;
}

std::string PerformanceStreams::end(double time) {
  {
    std::lock_guard lock(mutex_);
    if (!open_) return "an end with no start";
    open_->end = time;
    finished_ = std::move(open_);
    open_.reset();
  }
  ended_.notify_all();
  return "";
}

void PerformanceStreams::add(std::size_t stream, double time,
                             const std::vector<std::string>& channels,
                             const std::vector<double>& values) {
  std::lock_guard lock(mutex_);
  last_message_.at(stream) = time;
  if (!open_) return;
  signal::Series& s = open_->series[stream];
  if (s.channels.empty()) {
    s.channels = channels;
    s.values.resize(channels.size());
  }
  // Arrival times from one clock only go forward; a series' times must not go back even if two
  // connections' messages were stamped out of order.
  const double t = std::max(time - open_->start, s.t.empty() ? 0.0 : s.t.back());
  s.t.push_back(t);
  for (std::size_t c = 0; c < s.values.size() && c < values.size(); ++c)
    s.values[c].push_back(values[c]);
}

void PerformanceStreams::bad_message(std::size_t stream, double time, const std::string& problem) {
  std::lock_guard lock(mutex_);
  last_message_.at(stream) = time;
  if (open_ && open_->problems.at(stream).empty())
    open_->problems[stream] = fmt::format("a message {:.3f} s into '{}': {}", time - open_->start,
                                          open_->action, problem);
}

signal::Series PerformanceStreams::stream_series(const Performance& done, std::size_t s) const {
  const std::string& source = streams_.at(s);
  if (!done.problems[s].empty()) throw InputError(source, 0, done.problems[s]);
  const signal::Series& series = done.series[s];
  const double length = done.end - done.start;
  if (series.samples() == 0) {
    // When the stream last spoke before the performance began (it may have spoken again since).
    const std::optional<double>& last = done.last_before[s];
    throw InputError(
        source, 0,
        fmt::format(
            "no message during '{}' ({:.3f} s): the stream stopped ({})", done.action, length,
            last ? fmt::format("its last message came {:.3f} s before the performance began",
                               done.start - *last)
                 : std::string("nothing has come on it since the node subscribed")));
  }
  if (series.samples() < 2)
    throw InputError(source, 0,
                     fmt::format("one message during '{}' ({:.3f} s), fewer than the 2 a series "
                                 "needs: the stream is slower than the performance",
                                 done.action, length));
  return series;
}

std::vector<signal::Series> PerformanceStreams::take(const std::string& action,
                                                     const std::vector<std::size_t>& streams,
                                                     std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  ended_.wait_for(lock, timeout, [&] { return finished_.has_value(); });
  if (!finished_) {
    const double seconds = std::chrono::duration<double>(timeout).count();
    if (open_ && open_->action == action)
      throw InputError(
          markers_, 0,
          fmt::format("'{}' began but no end marker came within {:g} s", action, seconds));
    throw InputError(markers_, 0,
                     fmt::format("no performance of '{}' ended within {:g} s (the planner marks "
                                 "each sensing action with 'start OBJECT ACTION SESSION' and "
                                 "'end')",
                                 action, seconds));
  }
  const Performance done = std::move(*finished_);
  finished_.reset();
  if (done.action != action)
    throw InputError(
        markers_, 0,
        fmt::format("the performance that ended last was of '{}', not '{}'", done.action, action));
  std::vector<signal::Series> out;
  for (std::size_t s : streams) out.push_back(stream_series(done, s));
  return out;
}

}  // namespace echoplan::robot
