#include "experiment/trial_journal.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/error.h"
#include "common/file_io.h"

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
    steps.push_back(std::move(step));
  }
  return {{"id", entry.id},
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
}

JournalEntry journal_entry_from_json(const nlohmann::json& j, const std::string& source, int line) {
  try {
    JournalEntry e;
    e.id = j.at("id").get<int>();
    e.arm = j.at("arm").get<std::string>();
    e.object = j.at("object").get<std::string>();
    TrialRecord& r = e.result.record;
    r.trial = j.at("trial").get<int>();
    r.true_state = j.at("true_state").get<int>();
    r.believed_state = j.at("believed_state").get<int>();
    r.steps = j.at("steps").get<int>();
    r.action_counts = j.at("action_counts").get<std::vector<int>>();
    r.discounted_reward = j.at("discounted_reward").get<double>();
    r.collision = j.at("collision").get<bool>();
    r.capped = j.at("capped").get<bool>();
    int step_index = 0;
    for (const nlohmann::json& js : j.at("step_log")) {
      StepRecord s;
      s.trial = r.trial;
      s.step = step_index++;
      s.action = js.at("action").get<int>();
      s.observation.index = js.at("observation").at("index").get<int>();
      s.observation.values = js.at("observation").at("values").get<std::vector<double>>();
      s.belief = js.at("belief").get<std::vector<double>>();
      s.reward = js.at("reward").get<double>();
      s.episodes = js.at("episodes").get<std::int64_t>();
      if (js.contains("heard_probability"))
        s.heard_probability = js.at("heard_probability").get<double>();
      e.result.steps.push_back(std::move(s));
    }
    if (static_cast<int>(e.result.steps.size()) != r.steps)
      throw InputError(source, line, "a journal entry's step count does not match its step log");
    return e;
  } catch (const nlohmann::json::exception& error) {
    throw InputError(source, line, std::string("malformed journal entry: ") + error.what());
  }
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
  write_all(fd_, line, path_);
  if (::fsync(fd_) != 0)
    throw InputError(path_.string(), 0, std::string("fsync failed: ") + std::strerror(errno));
}

}  // namespace echoplan::experiment
