// A small finished campaign, written out by hand, for the report layer's tests (campaign_report,
// campaign_figures, html_report): two arms, two groups (object "a"; "b_heavy", a variant playing
// "b"), six trials:
//
//   id arm  group    truth believed steps reward  listen heard (per step; "none" after picks)
//   0  one  a        a     a        2     8       heard_a
//   1  one  a        a     b        2     -2      heard_b
//   2  one  b_heavy  b     b        1     10      (picks at once)
//   3  two  a        a     a        3     6       heard_a, heard_a
//   4  two  a        a     a        2     4       heard_b
//   5  two  b_heavy  b     a        2     -100    heard_b
//
// Actions: listen (0), pick_a (1), pick_b (2); observations heard_a, heard_b, none.
#pragma once

#include "../common/source_dir.h"
#include "experiment/campaign_report.h"

namespace echoplan::experiment::testing {

inline JournalEntry trial_entry(int id, const std::string& arm, const std::string& object,
                                int truth, int believed, double reward,
                                const std::vector<int>& heard) {
  JournalEntry e;
  e.id = id;
  e.arm = arm;
  e.object = object;
  TrialRecord& r = e.result.record;
  r.trial = id;
  r.true_state = truth;
  r.believed_state = believed;
  r.discounted_reward = reward;
  r.action_counts = {static_cast<int>(heard.size()), believed == 0 ? 1 : 0, believed == 1 ? 1 : 0};
  r.steps = static_cast<int>(heard.size()) + 1;
  double p_a = 0.5;
  int step = 0;
  for (int h : heard) {  // each listen moves 0.25 of belief toward what was heard
    StepRecord s;
    s.trial = id;
    s.step = step++;
    s.action = 0;
    s.observation.index = h;
    s.belief = {p_a, 1.0 - p_a};
    s.heard_probability = 0.75;
    e.result.steps.push_back(s);
    p_a += h == 0 ? 0.25 : -0.25;
  }
  StepRecord pick;
  pick.trial = id;
  pick.step = step;
  pick.action = believed == 0 ? 1 : 2;
  pick.observation.index = 2;
  pick.belief = {p_a, 1.0 - p_a};
  e.result.steps.push_back(pick);
  return e;
}

inline CampaignResults small_campaign() {
  CampaignResults results;
  CampaignConfig& c = results.config;
  c.source = "small.yaml";
  // summary.json's campaign identity hashes the problem file: a real one.
  const std::string problem = echoplan::testing::source_dir() + "/problems/audio_objects.yaml";
  c.arms = {{"one", problem, false}, {"two", problem, true}};
  c.world.type = WorldType::model;
  c.world.problem = problem;
  c.groups = {{"a", "a", 2}, {"b_heavy", "b", 1}};
  c.planner.episodes = 100;
  results.arms = resolve_arms(c);
  results.groups = c.groups;  // a model world's are the file's
  pomdp::ModelSpec& spec = results.spec;
  spec.action_names = {"listen", "pick_a", "pick_b"};
  spec.state.discrete_names = {"object"};
  spec.state.discrete_value_names = {{"a", "b"}};
  spec.observation.names = {"heard_a", "heard_b", "none"};
  results.entries = {trial_entry(0, "one", "a", 0, 0, 8.0, {0}),
                     trial_entry(1, "one", "a", 0, 1, -2.0, {1}),
                     trial_entry(2, "one", "b_heavy", 1, 1, 10.0, {}),
                     trial_entry(3, "two", "a", 0, 0, 6.0, {0, 0}),
                     trial_entry(4, "two", "a", 0, 0, 4.0, {1}),
                     trial_entry(5, "two", "b_heavy", 1, 0, -100.0, {1})};
  results.planned_trials = 6;
  return results;
}

// A reference with a result for "a" only, an original-objects total covering exactly "a", a
// variants total covering more than the campaign's variants, and an "all" total in another order.
inline ReferenceResults small_reference(const std::string& label = "lab") {
  ReferenceResults r;
  r.source = "ref.yaml";
  r.label = label;
  r.note = "Numbers from the lab's notebook <p. 3> & friends.";
  r.objects["a"] = {10, 9, 7.5, 2.5};
  r.original_objects = ReferenceTotal{{"a"}, {10, 9, 7.5, 2.5}};
  r.variants = ReferenceTotal{{"b_heavy", "c_heavy"}, {20, 10, -1.0, 3.0}};
  r.all = ReferenceTotal{{"b_heavy", "a"}, {30, 25, 4.25, 2.75}};
  return r;
}

}  // namespace echoplan::experiment::testing
