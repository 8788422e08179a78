#include "experiment/trial_journal.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "common/error.h"
#include "common/file_io.h"
#include "common/json_fields.h"

namespace echoplan::experiment {

namespace {

namespace fs = std::filesystem;

nlohmann::json observation_json(const pomdp::Observation& o) {
  return {{"index", o.index}, {"values", o.values}};
}

}  // namespace

bool operator==(const JournalEntry& a, const JournalEntry& b) { return to_json(a) == to_json(b); }

nlohmann::json to_json(const JournalEntry& entry) {
  const TrialRecord& r = entry.result.record;
  nlohmann::json steps = nlohmann::json::array();
  for (const StepRecord& s : entry.result.steps) {
    nlohmann::json step = {{"action", s.action},
                           {"observation", observation_json(s.observation)},
                           {"belief", s.belief},
                           {"reward", s.reward},
                           {"episodes", s.episodes}};
    if (s.heard_probability) step["heard_probability"] = *s.heard_probability;
    if (s.heard_ebr_db) step["heard_ebr_db"] = *s.heard_ebr_db;
    steps.push_back(std::move(step));
  }
  nlohmann::json j = {{"id", entry.id},
                      {"arm", entry.arm},
                      {"object", entry.object},
                      {"trial", r.trial},
                      {"true_state", r.true_state},
                      {"believed_state", r.believed_state},
                      {"steps", r.steps},
                      {"action_counts", r.action_counts},
                      {"discounted_reward", r.discounted_reward},
                      {"collision", r.collision},
                      {"capped", r.capped},
                      {"step_log", std::move(steps)}};
  // Only a dataset world's trials have one (journals of other worlds keep their bytes).
  if (!entry.session.empty()) j["session"] = entry.session;
  // Only a world that chose a surface names it (journals of the lab's table keep their bytes).
  if (!r.surface.empty()) j["surface"] = r.surface;
  return j;
}

namespace {

namespace jf = json_fields;

constexpr long long kIntMin = std::numeric_limits<int>::min();
constexpr long long kIntMax = std::numeric_limits<int>::max();

int int_member(const nlohmann::json& j, const std::string& key, const std::string& path,
               const jf::JsonSource& source) {
  return jf::integer(jf::member(j, key, path, source), kIntMin, kIntMax, jf::child(path, key),
                     source);
}

// One step of an entry's step_log, at `path` ("step_log[2]").
StepRecord step_from_json(const nlohmann::json& js, const std::string& path,
                          const jf::JsonSource& source) {
  StepRecord s;
  s.action = int_member(js, "action", path, source);
  const std::string observation = jf::child(path, "observation");
  const nlohmann::json& o = jf::member(js, "observation", path, source);
  s.observation.index = int_member(o, "index", observation, source);
  s.observation.values = jf::numbers(jf::member(o, "values", observation, source), -1,
                                     jf::child(observation, "values"), source);
  s.belief =
      jf::numbers(jf::member(js, "belief", path, source), -1, jf::child(path, "belief"), source);
  s.reward = jf::number(jf::member(js, "reward", path, source), jf::child(path, "reward"), source);
  s.episodes =
      jf::integer64(jf::member(js, "episodes", path, source), jf::child(path, "episodes"), source);
  if (const nlohmann::json* p = jf::optional_member(js, "heard_probability", path, source))
    s.heard_probability = jf::number(*p, jf::child(path, "heard_probability"), source);
  if (const nlohmann::json* p = jf::optional_member(js, "heard_ebr_db", path, source))
    s.heard_ebr_db = jf::number(*p, jf::child(path, "heard_ebr_db"), source);
  return s;
}

}  // namespace

JournalEntry journal_entry_from_json(const nlohmann::json& j, const std::string& file, int line) {
  const jf::JsonSource source{file, line};
  JournalEntry e;
  e.id = int_member(j, "id", "", source);
  e.arm = jf::string(jf::member(j, "arm", "", source), "arm", source);
  e.object = jf::string(jf::member(j, "object", "", source), "object", source);
  if (const auto* session = jf::optional_member(j, "session", "", source))
    e.session = jf::string(*session, "session", source);
  TrialRecord& r = e.result.record;
  r.trial = int_member(j, "trial", "", source);
  r.true_state = int_member(j, "true_state", "", source);
  r.believed_state = int_member(j, "believed_state", "", source);
  r.steps = int_member(j, "steps", "", source);
  r.action_counts =
      jf::integers(jf::member(j, "action_counts", "", source), -1, "action_counts", source);
  r.discounted_reward =
      jf::number(jf::member(j, "discounted_reward", "", source), "discounted_reward", source);
  r.collision = jf::boolean(jf::member(j, "collision", "", source), "collision", source);
  r.capped = jf::boolean(jf::member(j, "capped", "", source), "capped", source);
  if (const auto* surface = jf::optional_member(j, "surface", "", source))
    r.surface = jf::string(*surface, "surface", source);
  const nlohmann::json& log = jf::array(jf::member(j, "step_log", "", source), "step_log", source);
  for (std::size_t i = 0; i < log.size(); ++i) {
    StepRecord s = step_from_json(log[i], jf::element("step_log", i), source);
    s.trial = r.trial;
    s.step = static_cast<int>(i);
    e.result.steps.push_back(std::move(s));
  }
  if (static_cast<int>(e.result.steps.size()) != r.steps)
    throw InputError(file, line, "a journal entry's step count does not match its step log");
  return e;
}

std::vector<JournalEntry> read_journal(const fs::path& path) {
  std::vector<JournalEntry> entries;
  std::error_code error;
  if (!fs::exists(path, error)) return entries;
  const std::string text = read_text_file(path.string(), "trial journal");
  std::size_t start = 0;
  int line = 0;
  while (true) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) break;  // a torn last line, or the end
    ++line;
    const std::string_view row(text.data() + start, end - start);
    start = end + 1;
    if (row.empty()) continue;
    nlohmann::json j = nlohmann::json::parse(row, nullptr, false);
    if (j.is_discarded())
      throw InputError(path.string(), line, "malformed journal line (not JSON)");
    entries.push_back(journal_entry_from_json(j, path.string(), line));
  }
  return entries;
}

void write_journal(const fs::path& path, const std::vector<JournalEntry>& entries) {
  std::string text;
  for (const JournalEntry& e : entries) text += to_json(e).dump() + '\n';
  write_file_atomically(path, text);
}

TrialJournal::TrialJournal(fs::path path) : path_(std::move(path)) {
  // Cut a torn last line off, so appended lines start on a line of their own.
  std::error_code error;
  if (fs::exists(path_, error)) {
    const std::string text = read_text_file(path_.string(), "trial journal");
    const std::size_t keep = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
    if (keep != text.size()) fs::resize_file(path_, keep, error);
    if (error) throw InputError(path_.string(), 0, "cannot repair the journal: " + error.message());
  }
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw InputError(path_.string(), 0, std::string("cannot write: ") + std::strerror(errno));
}

TrialJournal::~TrialJournal() {
  if (fd_ >= 0) ::close(fd_);
}

void TrialJournal::append(const JournalEntry& entry) {
  const std::string line = to_json(entry).dump() + '\n';
  std::lock_guard<std::mutex> lock(mutex_);
  // A full disk (or a file-size limit) lets a write stop partway: cut the part back off, so the
  // journal holds whole lines only, for this run's other workers and for the next run.
  const off_t whole = ::lseek(fd_, 0, SEEK_END);
  try {
    write_all(fd_, line, path_);
    if (::fsync(fd_) != 0)
      throw InputError(path_.string(), 0, std::string("fsync failed: ") + std::strerror(errno));
  } catch (const InputError& e) {
    const bool cut = whole >= 0 && ::ftruncate(fd_, whole) == 0;
    throw InputError(path_.string(), 0,
                     fmt::format("trial {} ({}, {}) could not be journalled: {}; {}; free space "
                                 "and run the same command again to finish the campaign",
                                 entry.id, entry.arm, entry.object, e.problem(),
                                 cut ? "the trials journalled before it are kept whole"
                                     : "its torn line is cut off when the journal is next opened"));
  }
}

}  // namespace echoplan::experiment
