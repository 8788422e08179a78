// Running a campaign's trials: numbering them, sharing them out (threads on this machine, shards
// across machines), and journalling each as it finishes.
//
// Trial `id` numbers the campaign's trials arm by arm, then group by group (the world's order),
// then 0..trials-1 within the group. A trial's random streams depend only on the campaign seed, its
// group's object and its index in the group, not on the arm, the worker, the shard or what ran
// before: both arms see the same true objects and the same world noise (a paired comparison), and
// any split of the work gives the same results.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "experiment/campaign_config.h"
#include "experiment/trial_journal.h"
#include "loop/loop.h"
#include "pomdp/problem.h"

namespace echoplan::experiment {

struct TrialJob {
  int id = 0;
  int arm = 0;    // index into CampaignConfig::arms
  int group = 0;  // index into the world's trial groups (CampaignResults::groups)
  int index = 0;  // 0-based within the group
};

// Every trial of `arms` arms over the world's trial `groups`, in id order.
std::vector<TrialJob> campaign_jobs(int arms, const std::vector<ObjectGroup>& groups);

// The seed of the trial streams of `group` in a campaign of seed `seed` (trial_runner.h derives
// each trial's streams from it).
std::uint64_t group_seed(std::uint64_t seed, const ObjectGroup& group);

// One share of the trials: `--shard I/N` takes ids with id % N == I - 1 (I in 1..N), so shards are
// balanced across arms and objects.
struct Shard {
  int index = 1;
  int count = 1;
  bool contains(int id) const { return id % count == index - 1; }
};

// Parses "I/N"; throws InputError for anything else or I outside 1..N.
Shard parse_shard(const std::string& text);

// What a trial runs: the checked loop, the true state it fixes and, in a dataset world, the
// session it replays.
struct TrialLoop {
  std::shared_ptr<const loop::LoopSpec> spec;
  int true_state = -1;  // index into the problem's objects
  std::string session;  // the data's session name; empty outside a dataset world
};

// The loops of each arm and group: loops[arm][group] holds one TrialLoop that all the group's
// trials share (a model or simulated world), or one per trial (a dataset world: each session has
// its fold's classifiers and its own use limits). campaign.h builds them.
using ArmLoops = std::vector<std::vector<std::vector<TrialLoop>>>;

// The TrialLoop of `job`.
const TrialLoop& trial_loop(const ArmLoops& loops, const TrialJob& job);

struct CampaignRunOptions {
  int workers = 1;                          // threads, >= 1; results do not depend on it
  const std::atomic<bool>* stop = nullptr;  // optional: no new steps once set
  // Called after each trial is journalled, from one thread at a time.
  std::function<void(const JournalEntry&)> on_trial;
};

// Runs `jobs` (normally those of this shard the journal does not hold yet), appending each finished
// trial to `journal`. Each worker builds a loop (a world and a planner) of its own per arm and
// group it meets; the specs and what they hold are shared read-only. Returns the number of trials
// finished; fewer than asked when stopped. Rethrows the first error of any worker after the others
// have finished their trial in progress. `groups`: the world's trial groups.
int run_campaign_trials(const CampaignConfig& config, const std::vector<ObjectGroup>& groups,
                        const ArmLoops& loops, const std::vector<TrialJob>& jobs,
                        TrialJournal& journal, const CampaignRunOptions& options);

}  // namespace echoplan::experiment
