// The campaign's journal: one JSON line per finished trial, appended and fsync'd as each trial
// ends, so Ctrl-C, kill -9 or a power cut keeps every finished trial, and the next run skips them.
//
// The journal is the campaign's only record of results; every table, figure and page in the output
// folder is rebuilt from it. Lines are written whole with one write(2) and synced; a line cut short
// by a crash is dropped (and cut off the file) when the journal is opened again. Numbers are
// written so they read back bit for bit.
#pragma once

#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiment/trial_records.h"

namespace echoplan::experiment {

// One finished trial of a campaign. `id` numbers the campaign's trials 0..N-1 (campaign_runner.h).
struct JournalEntry {
  int id = 0;
  std::string arm;
  std::string object;   // what the world held
  std::string session;  // a dataset world's session of `object` the trial replayed; else empty
  TrialResult result;

  friend bool operator==(const JournalEntry&, const JournalEntry&);
};

nlohmann::json to_json(const JournalEntry& entry);
// Throws InputError(source, line, ...) for a malformed entry.
JournalEntry journal_entry_from_json(const nlohmann::json& j, const std::string& source, int line);

// Reads every whole line of a journal file (missing file: none). A last line without its newline is
// a trial cut short and is ignored; a malformed whole line throws InputError naming file and line.
std::vector<JournalEntry> read_journal(const std::filesystem::path& path);

// Writes `entries` as a journal, replacing `path` atomically (temporary file, fsync, rename).
void write_journal(const std::filesystem::path& path, const std::vector<JournalEntry>& entries);

class TrialJournal {
 public:
  // Opens (creating) `path` for appending, after cutting off a torn last line. Throws InputError
  // when the file cannot be written.
  explicit TrialJournal(std::filesystem::path path);
  ~TrialJournal();
  TrialJournal(const TrialJournal&) = delete;
  TrialJournal& operator=(const TrialJournal&) = delete;

  // Appends one line and fsyncs it; safe to call from several threads.
  void append(const JournalEntry& entry);

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::mutex mutex_;
};

}  // namespace echoplan::experiment
