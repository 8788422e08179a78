// Campaigns end to end through the library: any split of the work (threads, stops and resumes,
// shards) writes the same files as one uninterrupted one-core run; both arms see the same trials;
// every bad input is refused before any work.
#include "experiment/campaign.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <sstream>

#include "../common/source_dir.h"
#include "../perception/trained_model.h"
#include "common/error.h"
#include "common/file_io.h"
#include "perception/recording_set.h"

namespace echoplan::experiment {
namespace {

namespace fs = std::filesystem;

const std::string kProblem = echoplan::testing::source_dir() + "/problems/audio_objects.yaml";

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "echoplan_campaign_test" / name;
  fs::remove_all(dir);
  return dir;
}

// A small campaign: 3 groups x 3 trials per arm, small budgets.
CampaignConfig tiny_config(int arms = 1, const std::string& second_problem = kProblem) {
  std::string text = "seed: 11\narms:\n  - {name: hand_tuned, problem: " + kProblem + "}\n";
  if (arms > 1) text += "  - {name: second, problem: " + second_problem + "}\n";
  text += "world: {type: model, problem: " + kProblem +
          "}\n"
          "training_set: {recordings_per_pair: 0, catalogue: " +
          echoplan::testing::source_dir() +
          "/objects/catalogue.yaml}\n"
          "trials:\n"
          "  - {object: pringles_can, trials: 3}\n"
          "  - {object: paper_base, trials: 3}\n"
          "  - {object: coffee_mug_weighted, plays: coffee_mug, trials: 3}\n"
          "planner: {solver: abt, episodes: 200, max_steps: 25}\n";
  return parse_campaign_config(text, "tiny.yaml");
}

// Runs `shard` of the campaign in `dir` with `workers` threads (the preparation too), stopping
// after `stop_after` trials (< 0: never), then rebuilds the report (no figures: gnuplot is tested
// by the CLI tests).
int run(const CampaignConfig& config, const fs::path& dir, int workers, Shard shard = {},
        int stop_after = -1) {
  Campaign campaign = open_campaign(config, dir);
  std::atomic<bool> stop{false};
  EXPECT_TRUE(prepare_training(campaign, {}, stop, workers));
  int finished = 0;
  TrialJournal journal(dir / "journal.jsonl");
  CampaignRunOptions options;
  options.workers = workers;
  options.stop = &stop;
  options.on_trial = [&](const JournalEntry&) {
    if (++finished == stop_after) stop = true;
  };
  const int n = run_campaign_trials(campaign.config, campaign.results.groups, campaign.loops,
                                    remaining_jobs(campaign, shard), journal, options);
  rebuild_report(campaign, false);
  return n;
}

// Every regular file under `dir`, by relative path, with its bytes.
std::map<std::string, std::string> files_of(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    files[fs::relative(entry.path(), dir).string()] = bytes.str();
  }
  return files;
}

// The same file names with the same bytes.
void expect_same(const std::map<std::string, std::string>& fa,
                 const std::map<std::string, std::string>& fb) {
  std::vector<std::string> names_a, names_b;
  for (const auto& [name, bytes] : fa) names_a.push_back(name);
  for (const auto& [name, bytes] : fb) names_b.push_back(name);
  ASSERT_EQ(names_a, names_b);
  for (const auto& [name, bytes] : fa) EXPECT_TRUE(bytes == fb.at(name)) << name << " differs";
}

void expect_same_files(const fs::path& a, const fs::path& b) {
  expect_same(files_of(a), files_of(b));
}

int lines_of(const fs::path& file) {
  std::ifstream in(file);
  int n = 0;
  std::string line;
  while (std::getline(in, line)) ++n;
  return n;
}

TEST(Campaign, ParallelRunWritesTheFilesOfAOneCoreRun) {
  const CampaignConfig config = tiny_config();
  const fs::path one = fresh_dir("one_core"), many = fresh_dir("three_workers");
  EXPECT_EQ(run(config, one, 1), 9);
  EXPECT_EQ(run(config, many, 3), 9);
  expect_same_files(one, many);
  EXPECT_EQ(lines_of(one / "trials.csv"), 10);
  // Table 5.2's columns stay where `echoplan trials` writes them; arm, object and session (empty
  // outside a dataset world) come last.
  std::ifstream steps(one / "steps.csv");
  std::string header;
  std::getline(steps, header);
  EXPECT_EQ(
      header,
      "trial,step,action,observation,particles_pringles_can,particles_coffee_mug,particles_"
      "plastic_cup,"
      "particles_paper_base,reward,episodes,heard_probability,heard_ebr_db,arm,object,session");
}

TEST(Campaign, StoppedAndResumedRunWritesTheFilesOfOneRun) {
  const CampaignConfig config = tiny_config();
  const fs::path whole = fresh_dir("whole"), resumed = fresh_dir("resumed");
  run(config, whole, 1);
  // Stopped after the 4th trial: the other worker may still finish the trial it is in.
  const int first = run(config, resumed, 2, {}, 4);
  EXPECT_GE(first, 4);
  EXPECT_LT(first, 9);
  EXPECT_EQ(lines_of(resumed / "journal.jsonl"), first);
  EXPECT_EQ(run(config, resumed, 2), 9 - first);  // only the rest
  expect_same_files(whole, resumed);
}

TEST(Campaign, MergedShardsEqualTheUnshardedRun) {
  const CampaignConfig config = tiny_config(2);
  const fs::path whole = fresh_dir("unsharded");
  run(config, whole, 2);
  std::vector<fs::path> shards;
  for (int i = 1; i <= 3; ++i) {
    shards.push_back(fresh_dir("shard" + std::to_string(i)));
    EXPECT_EQ(run(config, shards.back(), 1, {i, 3}), 6);
  }
  const fs::path merged = fresh_dir("merged");
  // The merged report draws figures; so does the reference, rebuilt with them.
  merge_campaigns(merged, shards);
  rebuild_report(open_campaign(config, whole), true);
  expect_same_files(whole, merged);
}

TEST(Campaign, ArmsWithTheSameProblemPlayTheSameTrials) {
  const CampaignConfig config = tiny_config(2);
  const fs::path dir = fresh_dir("paired");
  run(config, dir, 2);
  const std::vector<JournalEntry> entries = read_journal(dir / "journal.jsonl");
  ASSERT_EQ(entries.size(), 18u);
  for (std::size_t k = 0; k < 9; ++k) {
    JournalEntry second = entries[k + 9];
    EXPECT_EQ(second.arm, "second");
    second.id = entries[k].id;
    second.arm = entries[k].arm;
    second.result.record.trial = entries[k].result.record.trial;
    for (std::size_t s = 0; s < second.result.steps.size(); ++s)
      second.result.steps[s].trial = entries[k].id;
    EXPECT_EQ(second, entries[k]) << "trial " << k;
  }
  std::ifstream summary(dir / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(summary);
  EXPECT_EQ(j["paired_differences"][0]["pairs"], 9);
  EXPECT_EQ(j["paired_differences"][0]["mean_discounted_reward_difference"], 0.0);
}

// A problem file's arm with unheard: auto plans, trial for trial, as the arm that names the
// estimate its self-play chose (on the problem with an exact belief), and shards merge with the
// choice.
TEST(Campaign, AnArmWithUnheardAutoPlaysAsTheEstimateItChoseAndShardsMergeWithIt) {
  std::string text = "seed: 11\narms:\n";
  for (const std::string unheard : {"auto", "share", "commit"})
    text += "  - {name: " + unheard + ", problem: " + kProblem + ", unheard: " + unheard + "}\n";
  text +=
      "world: {type: model, problem: " + kProblem +
      "}\ntraining_set: {recordings_per_pair: 0, catalogue: " + echoplan::testing::source_dir() +
      "/objects/catalogue.yaml}\ntrials:\n  - {object: pringles_can, trials: 4}\n"
      "  - {object: paper_base, trials: 4}\n"
      "planner: {solver: abt, episodes: 200, max_steps: 25, self_play_trials: 30}\n";
  const CampaignConfig config = parse_campaign_config(text, "auto.yaml");
  const fs::path whole = fresh_dir("auto");
  run(config, whole, 2);
  const nlohmann::json chosen = nlohmann::json::parse(std::ifstream(whole / "unheard.json"));
  ASSERT_EQ(chosen["arms"].size(), 1u);
  const std::string estimate = chosen["arms"][0]["chosen"];
  std::map<std::string, std::vector<JournalEntry>> by_arm;
  for (const JournalEntry& e : read_journal(whole / "journal.jsonl")) by_arm[e.arm].push_back(e);
  ASSERT_EQ(by_arm["auto"].size(), 8u);
  const std::string other = estimate == "share" ? "commit" : "share";
  int unlike_other = 0;
  for (std::size_t k = 0; k < 8; ++k) {
    const TrialRecord& mine = by_arm["auto"][k].result.record;
    const TrialRecord& named = by_arm[estimate][k].result.record;
    EXPECT_EQ(mine.action_counts, named.action_counts) << "trial " << k;
    EXPECT_EQ(mine.discounted_reward, named.discounted_reward) << "trial " << k;
    unlike_other += mine.action_counts != by_arm[other][k].result.record.action_counts;
  }
  EXPECT_GT(unlike_other, 0) << "share and commit decided alike: the test cannot tell them apart";

  std::vector<fs::path> shards;
  for (int i = 1; i <= 2; ++i) {
    shards.push_back(fresh_dir("auto_shard" + std::to_string(i)));
    run(config, shards.back(), 1, {i, 2});
  }
  const fs::path merged = fresh_dir("auto_merged");
  merge_campaigns(merged, shards);
  rebuild_report(open_campaign(config, whole), true);
  expect_same_files(whole, merged);
}

TEST(Campaign, TrialsOfAGroupHaveItsObjectAsTruth) {
  const CampaignConfig config = tiny_config();
  const fs::path dir = fresh_dir("truth");
  run(config, dir, 2);
  for (const JournalEntry& e : read_journal(dir / "journal.jsonl")) {
    const int expected = e.object == "pringles_can" ? 0 : e.object == "paper_base" ? 3 : 1;
    EXPECT_EQ(e.result.record.true_state, expected) << e.object;
    EXPECT_EQ(e.result.steps.size(), static_cast<std::size_t>(e.result.record.steps));
  }
}

// The simulated world with a calibrated arm beside the hand-tuned one, heard against the report's
// reference: a training set of 2 recordings per pair, one trial of an object and of a variant.
CampaignConfig closed_loop_config() {
  const std::string text =
      "seed: 5\narms:\n  - {name: calibrated, problem: " + kProblem +
      ", calibrate: true}\n  - {name: hand_tuned, problem: " + kProblem +
      "}\nworld: {type: simulated, problem: " + kProblem +
      "}\ntraining_set: {recordings_per_pair: 2, catalogue: " + echoplan::testing::source_dir() +
      "/objects/catalogue.yaml}\n"
      "trials:\n  - {object: paper_base, trials: 1}\n"
      "  - {object: coffee_mug_weighted, plays: coffee_mug, trials: 1}\n"
      "planner: {solver: abt, episodes: 200, max_steps: 12}\nreference: " +
      echoplan::testing::source_dir() + "/experiments/chapter5_reference.yaml\n";
  return parse_campaign_config(text, "closed_loop.yaml");
}

TEST(Campaign, ClosedLoopRunsWithACalibratedArmAndGivesTheSameFilesOnAnyNumberOfWorkers) {
  const CampaignConfig config = closed_loop_config();
  const fs::path one = fresh_dir("loop_one"), two = fresh_dir("loop_two");
  EXPECT_EQ(run(config, one, 1), 4);
  EXPECT_EQ(run(config, two, 2), 4);
  expect_same_files(one, two);
  // The calibrated arm plans with the trained classifier's table, written next to the model.
  EXPECT_TRUE(fs::exists(one / "training" / "model.json"));
  EXPECT_TRUE(fs::exists(one / "training" / "calibrated.problem.yaml"));
  // Every sensing step was classified: its heard probability is logged.
  for (const JournalEntry& e : read_journal(one / "journal.jsonl"))
    for (const StepRecord& s : e.result.steps)
      if (s.observation.index < 4) {
        EXPECT_TRUE(s.heard_probability.has_value()) << "trial " << e.id;
      }
  // The training set heard by the reference's classifier, leave-one-out: every recording (the
  // problem's 4 objects x 2 per action) counted once; then the trials' variant, the weighted mug,
  // synthesised 2 per action and heard by the classifier fitted on the whole training set; beside
  // the lab's counts.
  const nlohmann::json summary =
      nlohmann::json::parse(read_text_file((one / "summary.json").string(), "summary"));
  EXPECT_EQ(summary["heard"]["classifier"], "report-template");
  ASSERT_EQ(summary["heard"]["simulated"].size(), 2u);
  for (const nlohmann::json& action : summary["heard"]["simulated"]) {
    ASSERT_EQ(action["objects"].size(), 5u);
    EXPECT_EQ(action["objects"][4], "coffee_mug_weighted");
    EXPECT_EQ(action["heard"].size(), 4u) << action.dump();
    std::vector<int> per_row;
    for (const auto& row : action["counts"]) {
      int total = 0;
      for (const auto& c : row) total += c.get<int>();
      per_row.push_back(total);
    }
    EXPECT_EQ(per_row, (std::vector<int>{2, 2, 2, 2, 2})) << action["action"];
  }
  EXPECT_EQ(summary["heard"]["lab"].size(), 2u);
  EXPECT_EQ(perception::load_recording_set((one / "training" / "variants").string()).objects,
            (std::vector<std::string>{"coffee_mug_weighted"}));
}

// Rebuilding a finished campaign's report (as `echoplan merge` or a rerun does) reads the journal
// and what the preparation wrote: with the training recordings, the variants' recordings and the
// trained model moved out of the folder, the report's files come out byte for byte the same, the
// heard counts and the templates figure included, and nothing is synthesised again.
TEST(Campaign, RebuildingTheReportOpensNoRecordingAndFitsNoModel) {
  const CampaignConfig config = closed_loop_config();
  const fs::path dir = fresh_dir("rebuild_reads_files"), away = fresh_dir("rebuild_moved_away");
  run(config, dir, 1);
  rebuild_report(open_campaign(config, dir), true);
  ASSERT_TRUE(fs::exists(dir / "figures" / "templates.svg"));
  fs::create_directories(away);
  for (const char* moved : {"recordings", "variants", "model.json"})
    fs::rename(dir / "training" / moved, away / moved);
  const auto before = files_of(dir);
  rebuild_report(open_campaign(config, dir), true);
  expect_same(before, files_of(dir));
  const nlohmann::json summary =
      nlohmann::json::parse(read_text_file((dir / "summary.json").string(), "summary"));
  EXPECT_EQ(summary["heard"]["simulated"].size(), 2u);
}

// A recordings tree replayed as a dataset world: its three objects struck and tapped in three
// sessions each (manifest.csv names the sessions).
fs::path recorded_sessions(const std::string& name) {
  const fs::path dir = fresh_dir(name) / "data";
  fs::create_directories(dir);
  std::ofstream manifest(dir / "manifest.csv");
  manifest << "file,object,action,session\n";
  for (std::size_t k = 0; k < perception::test_model::kObjects.size(); ++k)
    for (const std::string action : {"strike", "tap"})
      for (unsigned session = 1; session <= 3; ++session) {
        const std::string object = perception::test_model::kObjects[k];
        const fs::path file = fs::path(object) / action / (std::to_string(session) + ".wav");
        fs::create_directories(dir / file.parent_path());
        audio::write_audio(
            (dir / file).string(),
            perception::test_model::recording(
                k, 7 * session + static_cast<unsigned>(k) * 100 + (action == "tap" ? 1000 : 0)));
        manifest << file.generic_string() << ',' << object << ',' << action << ',' << session
                 << '\n';
      }
  return dir;
}

// Every recording overwritten with bytes that are no audio, its size and time kept: opening one
// would fail.
void garble_recordings(const fs::path& dir) {
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".wav") continue;
    const auto size = fs::file_size(entry.path());
    const auto written = fs::last_write_time(entry.path());
    std::ofstream(entry.path(), std::ios::binary) << std::string(size, 'x');
    fs::last_write_time(entry.path(), written);
  }
}

// A dataset campaign over recordings analyses them once: reopening it to rebuild its report, or to
// merge it as a shard, reads the kept analysis (analysed_recordings.json) and opens no recording;
// a recording changed since makes the tree analysed again (here, all garbage: the first is named).
TEST(Campaign, ADatasetCampaignOverRecordingsAnalysesThemOnce) {
  const fs::path data = recorded_sessions("analysed_once");
  const fs::path dir = data.parent_path() / "campaign", merged = data.parent_path() / "merged";
  const CampaignConfig config =
      parse_campaign_config("seed: 2\nworld: {type: dataset, data: " + data.string() +
                                ", hold_out: session}\narms:\n  - {name: plan, strategy: plan}\n"
                                "  - {name: all_actions, strategy: all_actions}\n"
                                "planner: {solver: abt, episodes: 200, max_steps: 20}\n",
                            (data.parent_path() / "campaign.yaml").string());
  run(config, dir, 1);
  ASSERT_TRUE(fs::exists(dir / "analysed_recordings.json"));
  const auto before = files_of(dir);
  garble_recordings(data);
  rebuild_report(open_campaign(config, dir), false);
  expect_same(before, files_of(dir));
  merge_campaigns(merged, {dir});
  EXPECT_EQ(read_text_file((merged / "trials.csv").string(), "trials"),
            read_text_file((dir / "trials.csv").string(), "trials"));
  // Touched: the listing no longer matches, so the tree is analysed again.
  const fs::path touched = data / "ring" / "tap" / "2.wav";
  fs::last_write_time(touched, fs::last_write_time(touched) + std::chrono::seconds(5));
  try {
    open_campaign(config, dir);
    ADD_FAILURE() << "a changed recording was not analysed again";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(".wav: cannot decode as audio"), std::string::npos)
        << e.what();
  }
}

// The InputError message of opening `config` in `dir`.
std::string open_error(const CampaignConfig& config, const fs::path& dir) {
  try {
    open_campaign(config, dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// The rows of a manifest.csv after its header.
std::vector<std::string> manifest_rows(const fs::path& file) {
  std::istringstream text(read_text_file(file.string(), "manifest"));
  std::vector<std::string> rows;
  for (std::string line; std::getline(text, line);) rows.push_back(line);
  rows.erase(rows.begin());
  return rows;
}

// A dataset world over recordings heard through noise: every arm's trials hear one noisy copy of
// the tree (each recording at the world's ratio), the arm trained in noise fits each fold on the
// recordings and their noisy twins, each twin in its quiet recording's session, and plans with a
// table of its own.
TEST(Campaign, ADatasetWorldOverRecordingsIsHeardThroughItsNoise) {
  const fs::path data = recorded_sessions("dataset_noise");
  const fs::path dir = data.parent_path() / "campaign";
  const CampaignConfig config =
      parse_campaign_config("seed: 2\nworld: {type: dataset, data: " + data.string() +
                                ", hold_out: session, noise: {sources: [white], ebr_db: \"0\"}}\n"
                                "training_set: {noise: {sources: [room], ebr_db: \"-6:6\"}}\n"
                                "arms:\n  - {name: quiet, strategy: plan}\n"
                                "  - {name: in_noise, strategy: plan, trained_in_noise: true}\n"
                                "  - {name: levels, strategy: plan, trained_in_noise: true, "
                                "observations: levels}\n"
                                "planner: {solver: abt, episodes: 200, max_steps: 20}\n",
                            (data.parent_path() / "campaign.yaml").string());
  run(config, dir, 1);
  std::vector<std::string> quiet = manifest_rows(data / "manifest.csv");
  std::sort(quiet.begin(), quiet.end());
  std::vector<std::string> heard = manifest_rows(dir / "heard_recordings" / "manifest.csv");
  std::sort(heard.begin(), heard.end());
  ASSERT_EQ(heard.size(), quiet.size());
  for (std::size_t r = 0; r < quiet.size(); ++r) EXPECT_EQ(heard[r], quiet[r] + ",0,white");
  const std::vector<std::string> twins =
      manifest_rows(dir / "training" / "recordings_in_noise" / "manifest.csv");
  ASSERT_EQ(twins.size(), 2 * quiet.size());
  EXPECT_NE(std::find(quiet.begin(), quiet.end(), twins[0].substr(0, twins[0].rfind(",,none"))),
            quiet.end());
  EXPECT_TRUE(twins[0].ends_with(",,none")) << twins[0];
  std::string twin = twins[0].substr(0, twins[0].size() - std::string(",,none").size());
  twin.replace(twin.find(".wav"), 4, ".noisy.wav");
  EXPECT_EQ(twins[1].substr(0, twin.size() + 1), twin + ",");  // the same object, action, session
  EXPECT_TRUE(twins[1].ends_with(",room")) << twins[1];
  for (int fold = 1; fold <= 3; ++fold) {
    const fs::path folder = dir / "folds" / std::to_string(fold);
    ASSERT_TRUE(fs::exists(folder / "problem-in-noise.yaml"));
    EXPECT_NE(read_text_file((folder / "problem.yaml").string(), "problem"),
              read_text_file((folder / "problem-in-noise.yaml").string(), "problem"));
  }
  EXPECT_EQ(lines_of(dir / "trials.csv"), 1 + 3 * 9);
  // The arm hearing levels plans with the noise-trained classifier's level table, and every step
  // that heard a performance logs the level measured from its noisy recording.
  const std::string levels =
      read_text_file((dir / "folds" / "1" / "problem-levels-in-noise.yaml").string(), "problem");
  EXPECT_NE(levels.find("ring@noisy"), std::string::npos);
  std::istringstream steps(read_text_file((dir / "steps.csv").string(), "steps"));
  std::string header, line;
  std::getline(steps, header);
  const auto column = std::count(header.begin(), header.begin() + header.find("heard_ebr_db"), ',');
  int sensed = 0;
  while (std::getline(steps, line)) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    if (cells.at(2) != "strike" && cells.at(2) != "tap") continue;
    ++sensed;
    // White noise mixed at 0 dB measures within a few dB of it.
    EXPECT_NEAR(std::stod(cells.at(static_cast<std::size_t>(column))), 0.0, 6.0) << line;
  }
  EXPECT_GT(sensed, 0);

  // A feature set's features are computed already: no noise can be mixed into them.
  const std::string features =
      echoplan::testing::source_dir() + "/experiments/data/synthetic_objects";
  const CampaignConfig on_features = parse_campaign_config(
      "world: {type: dataset, data: " + features +
          ", noise: {sources: [white], ebr_db: \"0\"}}\narms:\n  - {name: plan, strategy: plan}\n"
          "planner: {episodes: 100}\n",
      (data.parent_path() / "features.yaml").string());
  EXPECT_NE(open_error(on_features, data.parent_path() / "on_features")
                .find("background noise is mixed into recordings, and world.data (" + features +
                      ") is a feature set"),
            std::string::npos)
      << open_error(on_features, data.parent_path() / "on_features");
}

TEST(Campaign, RefusesBadInputBeforeAnyWork) {
  const fs::path dir = fresh_dir("errors");
  CampaignConfig config = tiny_config();
  config.groups[2].object = "teapot";
  EXPECT_NE(open_error(config, dir).find("object 'teapot' has no entry in the catalogue"),
            std::string::npos)
      << open_error(config, dir);

  config = tiny_config();
  config.groups[2].plays = "teapot";
  EXPECT_NE(open_error(config, dir).find("plays 'teapot', which is not an object of"),
            std::string::npos);

  config = tiny_config();
  config.training.recordings = (dir / "no_such_recordings").string();
  EXPECT_NE(
      open_error(config, dir).find("no_such_recordings: the recordings folder does not exist"),
      std::string::npos);

  config = tiny_config(2, echoplan::testing::source_dir() + "/problems/tiger.pomdp");
  EXPECT_NE(open_error(config, dir).find("must share objects, actions and observations"),
            std::string::npos)
      << open_error(config, dir);

  // A file where the folder should be: nothing can be created under it (even as root).
  fs::create_directories(dir);
  std::ofstream(dir / "a_file") << "x";
  EXPECT_NE(
      open_error(tiny_config(), dir / "a_file" / "out").find("cannot create the output folder"),
      std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "hand_tuned"));  // nothing was written for the refused campaigns

  // A folder holding another campaign.
  const fs::path used = fresh_dir("used");
  open_campaign(tiny_config(), used);
  config = tiny_config();
  config.seed = 12;
  EXPECT_NE(open_error(config, used).find("holds a different campaign"), std::string::npos);
}

TEST(Campaign, ShardsParseAndPartitionTheTrials) {
  EXPECT_EQ(parse_shard("2/5").index, 2);
  EXPECT_EQ(parse_shard("2/5").count, 5);
  for (const char* bad : {"0/3", "4/3", "1", "a/b", "1/0", "1/3x", "-1/3"})
    EXPECT_THROW(parse_shard(bad), InputError) << bad;
  const CampaignConfig config = tiny_config(2);
  const std::vector<TrialJob> jobs =
      campaign_jobs(static_cast<int>(config.arms.size()), config.groups);
  std::vector<int> owners(jobs.size(), 0);
  for (int i = 1; i <= 4; ++i)
    for (const TrialJob& job : jobs) owners[job.id] += Shard{i, 4}.contains(job.id);
  for (int n : owners) EXPECT_EQ(n, 1);
}

}  // namespace
}  // namespace echoplan::experiment
