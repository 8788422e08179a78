#include "robot/performance_rows.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/error.h"

namespace echoplan::robot {

namespace {

std::string pair_name(const std::string& behaviour, const std::string& modality) {
  return behaviour + "/" + modality;
}

}  // namespace

PerformanceRows::PerformanceRows(std::map<std::string, std::vector<std::string>> sensors,
                                 std::string source)
    : sensors_(std::move(sensors)), source_(std::move(source)) {}

std::string PerformanceRows::add(PerformanceRow row) {
  std::string why;
  const auto it = sensors_.find(row.behaviour);
  if (it == sensors_.end()) {
    std::vector<std::string> read;
    for (const auto& [action, modalities] : sensors_)
      for (const std::string& m : modalities) read.push_back(pair_name(action, m));
    why =
        fmt::format("a '{}' row of '{}': the model reads no sensor rows of '{}' (it reads: {})",
                    row.modality, row.behaviour, row.behaviour,
                    read.empty() ? std::string("none") : fmt::format("{}", fmt::join(read, ", ")));
  } else if (std::find(it->second.begin(), it->second.end(), row.modality) == it->second.end()) {
    why = fmt::format("a '{}' row of '{}': the model's sensors for '{}' are: {}", row.modality,
                      row.behaviour, row.behaviour, fmt::join(it->second, ", "));
  } else if (row.values.empty()) {
    why = fmt::format("a '{}' row of '{}' with no values", row.modality, row.behaviour);
  } else {
    for (std::size_t i = 0; i < row.values.size() && why.empty(); ++i)
      if (!std::isfinite(row.values[i]))
        why = fmt::format("a '{}' row of '{}' whose value {} is {}", row.modality, row.behaviour,
                          i + 1, row.values[i]);
  }
  std::lock_guard lock(mutex_);
  if (!why.empty()) {
    ignored_.push_back(why);
    return why;
  }
  window_.push_back(std::move(row));
  arrived_.notify_all();
  return {};
}

bool PerformanceRows::complete(const std::string& action) const {
  for (const std::string& m : sensors_.at(action))
    if (std::none_of(window_.begin(), window_.end(), [&](const PerformanceRow& r) {
          return r.behaviour == action && r.modality == m;
        }))
      return false;
  return true;
}

std::string PerformanceRows::missing_text(const std::string& action,
                                          std::chrono::milliseconds timeout) const {
  std::vector<std::string> missing, arrived;
  for (const std::string& m : sensors_.at(action))
    if (std::none_of(window_.begin(), window_.end(), [&](const PerformanceRow& r) {
          return r.behaviour == action && r.modality == m;
        }))
      missing.push_back(m);
  for (const PerformanceRow& r : window_) arrived.push_back(pair_name(r.behaviour, r.modality));
  std::string text = fmt::format(
      "no '{}' row of '{}' arrived within {:g} s of the request (the robot publishes one per "
      "sensor of each performance, named as the model names them: {})",
      fmt::join(missing, "' or '"), action, std::chrono::duration<double>(timeout).count(),
      fmt::join(sensors_.at(action), ", "));
  text += arrived.empty()
              ? std::string("; no row arrived since the previous observation")
              : fmt::format("; rows since the previous observation: {}", fmt::join(arrived, ", "));
  if (!ignored_.empty()) text += fmt::format("; ignored: {}", fmt::join(ignored_, "; "));
  return text;
}

PerformanceRows::Taken PerformanceRows::take(const std::string& action,
                                             std::chrono::milliseconds timeout) {
  if (sensors_.count(action) == 0)
    throw InputError(source_, 0, fmt::format("'{}' has no sensor rows in the model", action));
  std::unique_lock lock(mutex_);
  const bool got = arrived_.wait_for(lock, timeout, [&] { return complete(action); });
  const std::string why = got ? std::string() : missing_text(action, timeout);
  // Whatever happens next, the next request is for a later performance.
  const std::vector<PerformanceRow> window = std::exchange(window_, {});
  ignored_.clear();
  lock.unlock();
  if (!got) throw InputError(source_, 0, why);
  Taken taken;
  for (const std::string& m : sensors_.at(action)) {
    const PerformanceRow* found = nullptr;
    for (const PerformanceRow& r : window) {
      if (r.behaviour != action || r.modality != m) continue;
      if (found)
        throw InputError(
            source_, 0,
            fmt::format("two '{}' rows of '{}' arrived since the previous observation; a "
                        "performance gives one row per sensor (does the robot publish twice, or "
                        "for an action that failed?)",
                        m, action));
      found = &r;
    }
    taken.rows.push_back(found->values);
  }
  for (const PerformanceRow& r : window)
    if (r.behaviour != action) taken.unused.push_back(pair_name(r.behaviour, r.modality));
  return taken;
}

}  // namespace echoplan::robot
