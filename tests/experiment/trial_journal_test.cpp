// The journal keeps finished trials through crashes: entries read back bit for bit, a torn last
// line is dropped and cut off before appending, a malformed line is an InputError with its line.
#include "experiment/trial_journal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "common/error.h"

namespace echoplan::experiment {
namespace {

namespace fs = std::filesystem;

fs::path fresh_file(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "echoplan_journal_test";
  fs::create_directories(dir);
  fs::remove(dir / name);
  return dir / name;
}

JournalEntry entry(int id) {
  JournalEntry e;
  e.id = id;
  e.arm = "hand_tuned";
  e.object = "coffee_mug_weighted";
  e.result.record.trial = id;
  e.result.record.true_state = 1;
  e.result.record.believed_state = 2;
  e.result.record.steps = 2;
  e.result.record.action_counts = {1, 0, 0, 1};
  // Values with no short decimal form must come back exactly.
  e.result.record.discounted_reward = 0.1 + 0.2 + id * std::acos(-1.0);
  e.result.record.capped = true;
  StepRecord s;
  s.trial = id;
  s.action = 0;
  s.observation.index = 3;
  s.belief = {1.0 / 3.0, 2.0 / 3.0, 0.0, 0.0};
  s.reward = -1;
  s.episodes = 1234567890123;
  s.heard_probability = 0.7 / 3.0;
  e.result.steps.push_back(s);
  s.step = 1;
  s.action = 3;
  s.observation.index = -1;
  s.observation.values = {std::exp(1.0), -1e-300};
  s.heard_probability.reset();
  e.result.steps.push_back(s);
  return e;
}

TEST(TrialJournal, EntriesReadBackExactly) {
  const fs::path path = fresh_file("exact.jsonl");
  {
    TrialJournal journal(path);
    journal.append(entry(3));
    journal.append(entry(1));
  }
  const std::vector<JournalEntry> back = read_journal(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0], entry(3));
  EXPECT_EQ(back[1], entry(1));
  EXPECT_EQ(back[0].result.record.discounted_reward, entry(3).result.record.discounted_reward);
  EXPECT_EQ(back[0].result.steps[0].belief[0], 1.0 / 3.0);
  EXPECT_EQ(*back[0].result.steps[0].heard_probability, 0.7 / 3.0);
  EXPECT_FALSE(back[0].result.steps[1].heard_probability.has_value());
  EXPECT_EQ(back[0].result.steps[1].observation.values[1], -1e-300);
}

TEST(TrialJournal, TornLastLineIsDroppedAndCutBeforeAppending) {
  const fs::path path = fresh_file("torn.jsonl");
  {
    TrialJournal journal(path);
    journal.append(entry(0));
  }
  // A crash in the middle of writing the next line.
  const std::string whole = to_json(entry(1)).dump() + "\n";
  {
    std::ofstream out(path, std::ios::app);
    out << whole.substr(0, whole.size() / 2);
  }
  ASSERT_EQ(read_journal(path).size(), 1u);
  {
    TrialJournal journal(path);
    journal.append(entry(2));
  }
  const std::vector<JournalEntry> back = read_journal(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].id, 0);
  EXPECT_EQ(back[1].id, 2);
}

TEST(TrialJournal, MalformedLineNamesFileAndLine) {
  const fs::path path = fresh_file("bad.jsonl");
  {
    std::ofstream out(path);
    out << to_json(entry(0)).dump() << "\n{\"id\": 1}\n";
  }
  try {
    read_journal(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_EQ(e.line(), 2);
  }
}

TEST(TrialJournal, WriteJournalReplacesTheFile) {
  const fs::path path = fresh_file("sorted.jsonl");
  {
    TrialJournal journal(path);
    journal.append(entry(5));
  }
  write_journal(path, {entry(1), entry(2)});
  const std::vector<JournalEntry> back = read_journal(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].id, 1);
  EXPECT_EQ(back[1].id, 2);
  EXPECT_FALSE(fs::exists(path.string() + ".part"));
}

}  // namespace
}  // namespace echoplan::experiment
