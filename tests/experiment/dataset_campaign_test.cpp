// Campaigns in a dataset world, end to end through the library: every (object, session) is a trial
// of every arm, heard only by classifiers that never saw it, and the report counts a trial right
// when it was sorted right.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "../common/source_dir.h"
#include "../perception/synthetic_feature_set.h"
#include "common/error.h"
#include "experiment/campaign.h"
#include "experiment/campaign_certificate.h"
#include "experiment/unheard_choice.h"

namespace echoplan::experiment {
namespace {

namespace fs = std::filesystem;
using perception::test_features::SyntheticSpec;

CampaignConfig dataset_config(const fs::path& data, const std::string& hold_out,
                              const std::string& classifier) {
  const std::string text = "seed: 3\nworld: {type: dataset, data: " + data.string() +
                           ", hold_out: " + hold_out +
                           ", groups: " + (data / "groups.csv").string() +
                           "}\n"
                           "training_set: {classifier: " +
                           classifier +
                           "}\n"
                           "arms:\n"
                           "  - {name: plan, strategy: plan}\n"
                           "  - {name: all_actions, strategy: all_actions}\n"
                           "  - {name: best_single, strategy: best_single}\n"
                           "  - {name: information_gain, strategy: information_gain}\n"
                           "  - {name: random, strategy: random}\n"
                           "planner: {solver: abt, episodes: 300, max_steps: 20}\n";
  return parse_campaign_config(text, (data.parent_path() / "campaign.yaml").string());
}

// Whole objects of `data` held out and sorted by group, with the arms `arms` (YAML list lines).
CampaignConfig novel_object_config(const fs::path& data, const std::string& arms) {
  const std::string text = "seed: 3\nworld: {type: dataset, data: " + data.string() +
                           ", hold_out: object, groups: " + (data / "groups.csv").string() +
                           "}\narms:\n" + arms +
                           "planner: {solver: abt, episodes: 300, max_steps: 20}\n";
  return parse_campaign_config(text, (data.parent_path() / "campaign.yaml").string());
}

// Runs the whole campaign in `dir` on one worker and returns its results.
CampaignResults run(const CampaignConfig& config, const fs::path& dir) {
  fs::remove_all(dir);
  Campaign campaign = open_campaign(config, dir);
  std::atomic<bool> stop{false};
  EXPECT_TRUE(prepare_training(campaign, {}, stop));
  TrialJournal journal(dir / "journal.jsonl");
  CampaignRunOptions options;
  run_campaign_trials(campaign.config, campaign.results.groups, campaign.loops,
                      remaining_jobs(campaign, {}), journal, options);
  rebuild_report(campaign, false);
  CampaignResults results = campaign.results;
  results.entries = read_journal(dir / "journal.jsonl");
  return results;
}

const SummaryRow& all_row(const std::vector<SummaryRow>& rows, const std::string& arm) {
  for (const SummaryRow& row : rows)
    if (row.arm == arm && row.scope == RowScope::all) return row;
  throw std::logic_error("no row for " + arm);
}

// 6 objects in 2 groups of 3, 3 sessions each; "tap" tells objects apart well, "press" barely,
// "shake" in between (separations in noise standard deviations).
fs::path separable_data(const std::string& name) {
  const fs::path data = perception::test_features::fresh_folder(name) / "data";
  const std::vector<std::pair<std::string, double>> actions = {
      {"press", 0.3}, {"shake", 1.0}, {"tap", 4.0}};
  unsigned long long seed = 1;
  for (const auto& [action, separation] : actions) {
    SyntheticSpec spec;
    spec.objects = 6;
    spec.sessions = 3;
    spec.group_size = 3;
    spec.actions = {action};
    spec.modalities = {{"audio", 4, separation}};
    spec.seed = seed++;
    perception::test_features::write_synthetic_feature_set(data, spec);
  }
  return data;
}

TEST(DatasetCampaign, EverySessionIsATrialOfEveryArmPairedAndSortedRightIsCounted) {
  const fs::path data = separable_data("dataset_campaign");
  const CampaignResults results =
      run(dataset_config(data, "session", "lda"), data.parent_path() / "out");
  ASSERT_EQ(results.entries.size(), 5u * 18u);
  // Each arm meets each (object, session) once; the session is in the journal and trials.csv.
  std::map<std::string, std::set<std::pair<std::string, std::string>>> seen;
  for (const JournalEntry& e : results.entries)
    EXPECT_TRUE(seen[e.arm].insert({e.object, e.session}).second) << e.arm << e.object << e.session;
  for (const auto& [arm, trials] : seen) EXPECT_EQ(trials.size(), 18u) << arm;
  std::ifstream csv(data.parent_path() / "out" / "trials.csv");
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_TRUE(header.ends_with(",arm,object,session,seed")) << header;
  // The seed the trial's streams came from: the campaign's, derived for the object's trials.
  const std::string seed = std::to_string(group_seed(results.config.seed, results.groups.at(0)));
  EXPECT_TRUE(first.ends_with(",plan,obj0,s0," + seed)) << first;

  // Sensing actions are 0..2 (press, shake, tap), sorting 3..4.
  for (const JournalEntry& e : results.entries) {
    const std::vector<int>& n = e.result.record.action_counts;
    if (e.arm == "all_actions") {
      EXPECT_EQ((std::vector<int>{n[0], n[1], n[2]}), (std::vector<int>{1, 1, 1}));
    }
    if (e.arm == "best_single") {
      EXPECT_EQ((std::vector<int>{n[0], n[1], n[2]}), (std::vector<int>{0, 0, 1}));
    }
    for (int a = 0; a < 3; ++a) EXPECT_LE(n[a], 1) << e.arm;  // each behaviour recorded once
  }
  // Accuracy is the share sorted right: the trials whose last reward is the task's +10.
  const std::vector<SummaryRow> rows = summary_rows(results);
  for (const CampaignArm& arm : results.config.arms) {
    int right = 0, trials = 0;
    for (const JournalEntry& e : results.entries)
      if (e.arm == arm.name) {
        ++trials;
        right += e.result.steps.back().reward == 10.0;
      }
    EXPECT_DOUBLE_EQ(all_row(rows, arm.name).summary.accuracy, static_cast<double>(right) / trials)
        << arm.name;
  }
  // On data this clear, the planner listens to tap once and sorts right: more reward than
  // performing every behaviour.
  EXPECT_GE(all_row(rows, "plan").summary.accuracy, 0.9);
  EXPECT_LT(all_row(rows, "plan").summary.mean_steps,
            all_row(rows, "all_actions").summary.mean_steps);
  EXPECT_GT(all_row(rows, "plan").summary.mean_discounted_reward,
            all_row(rows, "all_actions").summary.mean_discounted_reward);
}

TEST(DatasetCampaign, ATrialIsHeardByClassifiersThatNeverSawIt) {
  // Pure noise: no behaviour says anything about the object. A nearest-neighbour classifier that
  // had seen the trial's own rows would name them exactly (every trial sorted right); fitted on
  // the other folds only, it is at chance (2 groups: about half).
  const fs::path data = perception::test_features::fresh_folder("dataset_leak") / "data";
  SyntheticSpec spec;
  spec.objects = 8;
  spec.sessions = 3;
  spec.group_size = 4;
  spec.actions = {"press", "tap"};
  spec.modalities = {{"audio", 3, 0.0}};
  perception::test_features::write_synthetic_feature_set(data, spec);
  const CampaignResults results =
      run(dataset_config(data, "session", "nearest-neighbour"), data.parent_path() / "out");
  const double accuracy = all_row(summary_rows(results), "all_actions").summary.accuracy;
  EXPECT_LT(accuracy, 0.85);
  EXPECT_GT(accuracy, 0.15);
}

TEST(DatasetCampaign, HoldingOutObjectsSortsNovelObjectsByGroup) {
  const fs::path data = separable_data("dataset_novel");
  const CampaignResults results =
      run(dataset_config(data, "object", "lda"), data.parent_path() / "out");
  ASSERT_EQ(results.entries.size(), 5u * 18u);
  // The hidden state is the group: 2 classes, and their lookalikes (the planner's default).
  EXPECT_EQ(results.spec.state.discrete_value_names.at(0),
            (std::vector<std::string>{"group0", "group1", "group0~lookalike", "group1~lookalike"}));
  for (const JournalEntry& e : results.entries) {
    const int object = std::stoi(e.object.substr(3));
    EXPECT_EQ(e.result.record.true_state, object / 3) << e.object;
  }
}

// One arm planning with lookalikes: every arm's problem names the copies (so all beliefs name the
// same states), the other arms' copies have no prior and they decide exactly as in a campaign
// without that arm, and each kind of arm has its fold problem.
TEST(DatasetCampaign, AnArmWithLookalikesLeavesTheOtherArmsAsTheyWere) {
  const fs::path data = separable_data("dataset_with_lookalike_arm");
  auto config = [&](bool with_lookalike) {
    std::string arms = "  - {name: plan, strategy: plan, lookalike: false}\n";
    if (with_lookalike) arms += "  - {name: plan_lookalike, strategy: plan, lookalike: true}\n";
    return novel_object_config(data, arms);
  };
  const fs::path with_dir = data.parent_path() / "with";
  const CampaignResults with = run(config(true), with_dir);
  const CampaignResults without = run(config(false), data.parent_path() / "without");
  EXPECT_EQ(with.spec.state.discrete_value_names.at(0),
            (std::vector<std::string>{"group0", "group1", "group0~lookalike", "group1~lookalike"}));
  EXPECT_EQ(without.spec.state.discrete_value_names.at(0).size(), 2u);
  std::map<std::string, TrialResult> plan_without;
  for (const JournalEntry& e : without.entries) plan_without[e.object + "/" + e.session] = e.result;
  int compared = 0;
  for (const JournalEntry& e : with.entries) {
    if (e.arm != "plan") continue;
    const TrialResult& alone = plan_without.at(e.object + "/" + e.session);
    EXPECT_EQ(e.result.record.action_counts, alone.record.action_counts) << e.object << e.session;
    EXPECT_EQ(e.result.record.discounted_reward, alone.record.discounted_reward);
    ++compared;
  }
  EXPECT_EQ(compared, 18);
  EXPECT_TRUE(fs::is_regular_file(with_dir / "folds/1/problem.yaml"));
  EXPECT_TRUE(fs::is_regular_file(with_dir / "folds/1/problem-lookalike.yaml"));
}

// An arm planning with lookalikes: every arm's problem names them after the classes, the arm has
// its own fold problem, and a sort's belief counts a lookalike's chance of being in the bin.
TEST(DatasetCampaign, AnArmWithLookalikesHasItsCopiesAndItsFoldProblem) {
  const fs::path data = separable_data("dataset_lookalike");
  const fs::path dir = data.parent_path() / "out";
  const CampaignResults results =
      run(novel_object_config(data,
                              "  - {name: plan, strategy: plan, lookalike: false}\n"
                              "  - {name: plan_lookalike, strategy: plan, lookalike: true}\n"),
          dir);
  EXPECT_EQ(results.spec.state.discrete_value_names.at(0),
            (std::vector<std::string>{"group0", "group1", "group0~lookalike", "group1~lookalike"}));
  // Two groups: a lookalike of group0 is group1, right only in group1's bin.
  ASSERT_EQ(results.right_share.size(), 4u);
  EXPECT_EQ(results.right_share[2], results.right_share[1]);
  EXPECT_EQ(results.right_share[3], results.right_share[0]);
  EXPECT_TRUE(fs::is_regular_file(dir / "folds/1/problem.yaml"));
  EXPECT_TRUE(fs::is_regular_file(dir / "folds/1/problem-lookalike.yaml"));
  EXPECT_EQ(results.entries.size(), 36u);
}

// Arms that hear some modalities only: each hears with a model fitted on those, so an arm hearing
// a sensor that says nothing (audio here, pure noise) sorts at chance where the arm hearing the
// informative one (haptic) and the arm hearing both sort well; each has its fold problem.
TEST(DatasetCampaign, AnArmHearsOnlyTheModalitiesItNames) {
  const fs::path data = perception::test_features::fresh_folder("dataset_modalities") / "data";
  SyntheticSpec spec;
  spec.objects = 6;
  spec.sessions = 3;
  spec.group_size = 3;
  spec.actions = {"press", "tap"};
  spec.modalities = {{"audio", 3, 0.0}, {"haptic", 3, 5.0}};
  perception::test_features::write_synthetic_feature_set(data, spec);
  const fs::path dir = data.parent_path() / "out";
  const std::string text = "seed: 3\nworld: {type: dataset, data: " + data.string() +
                           ", hold_out: session, groups: " + (data / "groups.csv").string() +
                           "}\ntraining_set: {classifier: lda}\narms:\n"
                           "  - {name: both, strategy: all_actions}\n"
                           "  - {name: audio, strategy: all_actions, modalities: [audio]}\n"
                           "  - {name: haptic, strategy: all_actions, modalities: [haptic]}\n"
                           "planner: {solver: abt, episodes: 300, max_steps: 20}\n";
  const CampaignResults results =
      run(parse_campaign_config(text, (data.parent_path() / "campaign.yaml").string()), dir);
  const auto rows = summary_rows(results);
  EXPECT_GT(all_row(rows, "both").summary.accuracy, 0.9);
  EXPECT_GT(all_row(rows, "haptic").summary.accuracy, 0.9);
  EXPECT_LT(all_row(rows, "audio").summary.accuracy, 0.8);  // two groups: chance is a half
  EXPECT_TRUE(fs::is_regular_file(dir / "folds/1/problem-hears-audio.yaml"));
  EXPECT_TRUE(fs::is_regular_file(dir / "folds/1/problem-hears-haptic.yaml"));
  // A modality the data does not have is refused naming the arm.
  const std::string vision = text.substr(0, text.find("arms:")) +
                             "arms:\n  - {name: both, strategy: all_actions}\n"
                             "  - {name: sight, strategy: all_actions, modalities: [vision]}\n"
                             "planner: {solver: abt, episodes: 300, max_steps: 20}\n";
  try {
    run(parse_campaign_config(vision, (data.parent_path() / "campaign.yaml").string()),
        data.parent_path() / "vision");
    ADD_FAILURE() << "no error for a modality the data lacks";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("arm 'sight': modalities: no action has a modality "
                                         "'vision'"),
              std::string::npos)
        << e.what();
  }
}

// certify --campaign's library half: each fold and arm reported as it is certified, in order and
// counted against all of them; once stopped, the ones finished are returned and no other is begun.
TEST(DatasetCampaign, CertifyingACampaignReportsEachFoldAndArmAndStopsWhenAsked) {
  const fs::path data = separable_data("dataset_certify_progress");
  const fs::path dir = data.parent_path() / "out";
  run(novel_object_config(data,
                          "  - {name: plan, strategy: plan}\n"
                          "  - {name: information_gain, strategy: information_gain}\n"),
      dir);
  CertifyOptions options;
  options.root_expansions = 2000;
  std::vector<std::string> reported;
  std::size_t last_total = 0;
  const auto record = [&](const ArmCertificate& a, std::size_t done, std::size_t total) {
    reported.push_back(a.fold + "/" + a.arm);
    EXPECT_EQ(done, reported.size());
    last_total = total;
  };
  const std::vector<ArmCertificate> all = certify_campaign(dir, options, record);
  std::size_t folds = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(dir / "folds"))
    folds += e.is_directory() ? 1 : 0;
  ASSERT_GE(folds, 2u);
  ASSERT_EQ(all.size(), 2 * folds);  // two arms a fold
  EXPECT_EQ(last_total, all.size());
  ASSERT_EQ(reported.size(), all.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    EXPECT_EQ(reported[i], all[i].fold + "/" + all[i].arm);
  EXPECT_EQ(reported[0], "1/plan");
  EXPECT_EQ(reported[1], "1/information_gain");
  EXPECT_EQ(reported[2], "2/plan");

  // Stopped while the third is certified: it finishes, and no fourth is begun.
  std::atomic<bool> stop{false};
  std::size_t calls = 0;
  const std::vector<ArmCertificate> some = certify_campaign(
      dir, options,
      [&](const ArmCertificate&, std::size_t done, std::size_t) {
        ++calls;
        if (done == 3) stop = true;
      },
      &stop);
  ASSERT_EQ(some.size(), 3u);
  EXPECT_EQ(calls, 3u);
  for (std::size_t i = 0; i < some.size(); ++i) {
    EXPECT_EQ(some[i].fold, all[i].fold);
    EXPECT_EQ(some[i].arm, all[i].arm);
    EXPECT_EQ(some[i].certificate.regret.mean, all[i].certificate.regret.mean);
  }
  // Asked to stop before any: none, and no error (the folder is a campaign's).
  EXPECT_TRUE(certify_campaign(dir, options, {}, &stop).empty());
}

// An arm with unheard: auto plans, trial for trial, as the arm that names the estimate its
// self-play chose (unheard.json), and a stopped self-play prepares nothing. On the shipped example
// (four behaviours, none sorting alone) the two estimates decide differently.
TEST(DatasetCampaign, AnArmWithUnheardAutoPlaysAsTheEstimateItsSelfPlayChose) {
  const fs::path data =
      fs::path(echoplan::testing::source_dir()) / "experiments/data/synthetic_objects";
  const fs::path folder = perception::test_features::fresh_folder("dataset_unheard_auto");
  const std::string text = "seed: 4\nworld: {type: dataset, data: " + data.string() +
                           ", groups: " + (data / "groups.csv").string() +
                           "}\narms:\n  - {name: auto, strategy: plan, unheard: auto}\n"
                           "  - {name: share, strategy: plan, unheard: share}\n"
                           "  - {name: commit, strategy: plan, unheard: commit}\n"
                           "planner: {solver: abt, episodes: 300, max_steps: 20, "
                           "self_play_trials: 24}\n";
  const CampaignConfig config = parse_campaign_config(text, (folder / "campaign.yaml").string());
  const fs::path dir = folder / "out";
  const CampaignResults results = run(config, dir);
  const nlohmann::json chosen = nlohmann::json::parse(std::ifstream(dir / "unheard.json"));
  ASSERT_EQ(chosen["arms"].size(), 1u);
  EXPECT_EQ(chosen["arms"][0]["arm"], "auto");
  EXPECT_EQ(chosen["arms"][0]["self_play_trials"], 24);
  const std::string estimate = chosen["arms"][0]["chosen"];
  ASSERT_TRUE(estimate == "share" || estimate == "commit") << estimate;
  EXPECT_EQ(estimate == "commit", chosen["arms"][0]["commit_minus_share"].get<double>() > 0.0);
  std::map<std::string, TrialResult> named, other;
  for (const JournalEntry& e : results.entries)
    if (e.arm != "auto") (e.arm == estimate ? named : other)[e.object + "/" + e.session] = e.result;
  int compared = 0, unlike_other = 0;
  for (const JournalEntry& e : results.entries) {
    if (e.arm != "auto") continue;
    const TrialResult& same = named.at(e.object + "/" + e.session);
    EXPECT_EQ(e.result.record.action_counts, same.record.action_counts) << e.object << e.session;
    EXPECT_EQ(e.result.record.discounted_reward, same.record.discounted_reward);
    unlike_other +=
        e.result.record.action_counts != other.at(e.object + "/" + e.session).record.action_counts;
    ++compared;
  }
  EXPECT_EQ(compared, 48);
  std::stringstream summary;
  summary << std::ifstream(dir / "summary.txt").rdbuf();
  EXPECT_NE(summary.str().find("  auto                     " + estimate + " (commit minus share"),
            std::string::npos)
      << summary.str();
  const nlohmann::json json = nlohmann::json::parse(std::ifstream(dir / "summary.json"));
  EXPECT_EQ(json["unheard_choices"], chosen["arms"]);
  EXPECT_GT(unlike_other, 0) << "share and commit decided alike: the test cannot tell them apart";

  // Stopped during the self-play: nothing prepared, no choice written.
  Campaign stopped = open_campaign(config, folder / "stopped");
  std::atomic<bool> stop{false};
  int played = 0;
  EXPECT_FALSE(prepare_training(
      stopped,
      [&](const std::string& what, int, int) {
        if (what == "choose unheard" && ++played == 3) stop = true;
      },
      stop));
  EXPECT_GE(played, 3);
  EXPECT_FALSE(fs::exists(folder / "stopped" / "unheard.json"));

  // A leaf commit cannot use is refused before any work.
  std::string rollout = text;
  rollout.replace(rollout.find("unheard: auto}"), 14, "unheard: auto, leaf: rollout}");
  try {
    open_campaign(parse_campaign_config(rollout, (folder / "campaign.yaml").string()),
                  folder / "rollout");
    FAIL() << "no error for unheard: auto with a rollout leaf";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("arm 'auto': unheard: auto may choose commit"), std::string::npos)
        << e.what();
  }

  // The choice does not depend on the workers: every trial's streams come from (seed, trial).
  UnheardSelfPlay play;
  play.problems = {std::make_shared<const pomdp::Problem>(
                       pomdp::load_problem((dir / "folds/1/problem.yaml").string())),
                   std::make_shared<const pomdp::Problem>(
                       pomdp::load_problem((dir / "folds/2/problem.yaml").string()))};
  play.planner.episodes = 300;
  play.trials = 10;
  const std::atomic<bool> never{false};
  const std::optional<UnheardChoice> one = choose_unheard(play, {}, never);
  play.workers = 2;
  const std::optional<UnheardChoice> two = choose_unheard(play, {}, never);
  ASSERT_TRUE(one && two);
  EXPECT_EQ(one->difference, two->difference);
  EXPECT_EQ(one->ci95, two->ci95);
  EXPECT_EQ(one->chosen, two->chosen);
}

TEST(DatasetCampaign, UnheardChoicesThatAreNotACampaignsAreRefusedNamingTheFile) {
  const fs::path file = perception::test_features::fresh_folder("unheard_file") / "unheard.json";
  write_unheard_choices(file, {{"plan", {solvers::UnheardOutcomes::commit, 1.5, 0.5, 40}}});
  const nlohmann::json arms = read_unheard_choices(file);
  ASSERT_EQ(arms.size(), 1u);
  EXPECT_EQ(arms[0]["chosen"], "commit");
  EXPECT_EQ(arms[0]["self_play_trials"], 40);
  for (const std::string text : {"{", "{\"arms\": [{\"arm\": \"plan\"}]}", "[]"}) {
    std::ofstream(file) << text;
    try {
      read_unheard_choices(file);
      FAIL() << "no error for " << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), file.string());
      EXPECT_NE(e.problem().find("unheard choices"), std::string::npos) << e.what();
    }
  }
}

TEST(DatasetCampaign, TooFewSessionsOrObjectsToCalibrateOnAreRefusedBeforeAnyWork) {
  const fs::path data = perception::test_features::fresh_folder("dataset_few") / "data";
  SyntheticSpec spec;
  spec.objects = 4;
  spec.sessions = 2;
  spec.group_size = 2;
  perception::test_features::write_synthetic_feature_set(data, spec);
  for (const std::string hold_out : {"session", "object"}) {
    try {
      open_campaign(dataset_config(data, hold_out, "lda"), data.parent_path() / "out");
      FAIL() << "no error for hold_out " << hold_out;
    } catch (const InputError& e) {
      EXPECT_NE(e.problem().find("needs at least 3"), std::string::npos) << e.what();
      EXPECT_EQ(e.file(), data.string());
    }
  }
}

}  // namespace
}  // namespace echoplan::experiment
