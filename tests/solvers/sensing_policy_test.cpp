// The sense-until-confident default policy on the report's shipped problem: Bayes' rule, the commit
// value, the choice of sensing action, and what its rollouts return in cases known by hand.
#include "solvers/sensing_policy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "../common/source_dir.h"
#include "common/error.h"
#include "pomdp/problem.h"
#include "pomdp/random_problem.h"

namespace echoplan::solvers {
namespace {

std::string repo_file(const std::string& relative) {
  return echoplan::testing::source_dir() + "/" + relative;
}

// The report's problem's indices: objects pringles_can 0, coffee_mug 1, plastic_cup 2, paper_base 3
// (state 4 is 'done'); actions slide 0, strike 1, move_to_A 2, move_to_B 3; observations follow the
// objects, then "none".
constexpr int kSlide = 0, kStrike = 1, kMoveToA = 2;
constexpr int kPaperBase = 3;

struct ReportPolicy : ::testing::Test {
  pomdp::Problem problem = pomdp::load_problem(repo_file("problems/audio_objects.yaml"));
  SensingPolicy policy{*problem.model->tabular()};
  std::vector<double> uniform{0.25, 0.25, 0.25, 0.25, 0.0};
};

TEST_F(ReportPolicy, BayesRuleUsesTheObservationTable) {
  std::vector<double> after;
  // Strike heard paper_base: the strike rows' paper_base column is 0.05, 0.05, 0.11, 0.67.
  const double p = policy.update(uniform, kStrike, kPaperBase, after);
  EXPECT_NEAR(p, (0.05 + 0.05 + 0.11 + 0.67) / 4, 1e-12);
  EXPECT_NEAR(after[0], 0.05 / 0.88, 1e-12);
  EXPECT_NEAR(after[2], 0.11 / 0.88, 1e-12);
  EXPECT_NEAR(after[3], 0.67 / 0.88, 1e-12);
  EXPECT_EQ(after[4], 0.0);
}

TEST_F(ReportPolicy, CommitValueIsTheBestSortingActionsExpectedReward) {
  EXPECT_DOUBLE_EQ(policy.commit_value(uniform), 0.5 * 10 + 0.5 * -100);
  EXPECT_DOUBLE_EQ(policy.commit_value({0.9, 0.0, 0.1, 0.0, 0.0}), 10.0);
  EXPECT_DOUBLE_EQ(policy.commit_value({0.8, 0.2, 0.0, 0.0, 0.0}), 0.8 * 10 + 0.2 * -100);
  EXPECT_TRUE(policy.is_terminal(kMoveToA));
  EXPECT_FALSE(policy.is_terminal(kSlide));
}

TEST_F(ReportPolicy, SensingThenCommittingWeighsEachOutcomesBestSort) {
  // Strike at the uniform prior, outcome by outcome (the table's columns, A = pringles can and
  // plastic cup against B = coffee mug and paper base): pringles_can 0.71 A / 0.16 B, coffee_mug
  // 0.16 / 0.71, plastic_cup 0.97 / 0.41, paper_base 0.16 / 0.72, each a quarter of the mass; the
  // best sort after each earns 10 per unit of the bin's mass and -100 per unit of the other's.
  const double by_hand = 0.25 * ((7.1 - 16) + (7.1 - 16) + (9.7 - 41) + (7.2 - 16));
  EXPECT_NEAR(policy.commit_after_sensing(uniform, kStrike), by_hand, 1e-12);
  // A known object: sensing changes nothing, committing after it earns what committing now does.
  EXPECT_NEAR(policy.commit_after_sensing({0, 0, 1, 0, 0}, kSlide), 10.0, 1e-12);
}

TEST_F(ReportPolicy, SensesWithTheActionThatSeparatesTheGroups) {
  // Pringles can (A) against coffee mug (B): the expected entropy of the group after one outcome is
  // 0.419 nats for strike and 0.582 for slide (computed from the table rows by hand).
  EXPECT_EQ(policy.choose_sensing({0.5, 0.5, 0.0, 0.0, 0.0}), kStrike);
}

TEST_F(ReportPolicy, RolloutsFromAKnownGroupCommitAtOnce) {
  Rng rng(1);
  std::vector<double> returns(SensingPolicy::kThresholds, 0.0);
  for (int i = 0; i < 10; ++i) policy.rollout({0.5, 0.0, 0.5, 0.0, 0.0}, 50, rng, returns.data());
  for (double r : returns) EXPECT_DOUBLE_EQ(r, 10 * 10.0);
}

TEST_F(ReportPolicy, RolloutsFromUniformImproveOnCommittingNow) {
  Rng rng(2);
  const int n = 2000;
  std::vector<double> returns(SensingPolicy::kThresholds, 0.0);
  for (int i = 0; i < n; ++i) policy.rollout(uniform, 100, rng, returns.data());
  // The first threshold commits at once: exactly the commit value every time.
  EXPECT_DOUBLE_EQ(returns[0] / n, -45.0);
  // A confident threshold is a real policy: its value is a lower bound on V*(b0) in [2.952, 2.955]
  // (echoplan solve --method exact), and sensing until confident is far better than guessing.
  double best = -1e9;
  for (double r : returns) best = std::max(best, r / n);
  EXPECT_GT(best, 0.0);
  EXPECT_LT(best, 2.955 + 0.3);  // a few standard errors (returns' sd is about 3.5) above V*
}

TEST(SensingPolicy, RefusesProblemsThatAreNotIdentification) {
  const pomdp::Problem tiger = pomdp::load_problem(repo_file("problems/tiger.pomdp"));
  EXPECT_THROW(SensingPolicy{*tiger.model->tabular()}, InputError);
}

// At 64 objects, 9 sensing actions and 64 outcomes the policy takes its large-problem path (the
// expected entropy summed without normalised posteriors: dense with a memo of choices, or sparse
// on rows that are mostly one value, with actions pruned by lower bounds). Its choices must be
// those of the definition, computed here outcome by outcome from Bayes' rule: argmin over the
// available sensing actions of sum_o P(o | b, a) H(right sorting action | b, a, o), first in
// action order on ties. Half the beliefs are spread, half mostly on one object (as a rollout's
// become, where the bounds prune most).
pomdp::ObjectProblemData large_problem(Rng& rng) {
  pomdp::RandomProblemSettings settings;
  settings.objects = 64;
  settings.sensing_actions = 9;
  settings.bins = 8;
  return pomdp::make_random_object_problem(settings, rng);
}

void expect_choices_of_the_definition(const pomdp::ObjectProblemData& data, Rng& rng) {
  auto model = std::make_shared<const pomdp::ObjectIdentificationModel>(data);
  const int objects = static_cast<int>(data.objects.size());
  const SensingPolicy policy(*model->tabular());
  const int states = policy.num_states(), actions = model->num_actions();
  const int outcomes = static_cast<int>(model->spec().observation.names.size());
  // Each live state's right sorting action, from point beliefs.
  std::vector<int> right(states, -1);
  for (int s = 0; s < objects; ++s) {
    std::vector<double> point(states, 0.0);
    point[s] = 1.0;
    double best = -std::numeric_limits<double>::infinity();
    for (int a = 0; a < actions; ++a)
      if (policy.is_terminal(a) && policy.expected_reward(point, a) > best)
        best = policy.expected_reward(point, a), right[s] = a;
  }
  const auto reference = [&](const std::vector<double>& b, const UseCounts& used) {
    int chosen = -1;
    double chosen_score = 0.0;
    for (int a = 0; a < actions; ++a) {
      if (policy.is_terminal(a) || (!used.empty() && used[a] > 0)) continue;
      double expected = 0.0;
      for (int o = 0; o < outcomes; ++o) {
        std::vector<double> after;
        const double p = policy.update(b, a, o, after);
        if (p <= 0.0) continue;
        std::vector<double> mass(actions, 0.0);
        for (int s = 0; s < objects; ++s) mass[right[s]] += after[s];
        double h = 0.0;
        for (double m : mass)
          if (m > 0.0) h -= m * std::log(m);
        expected += p * h;
      }
      if (chosen < 0 || expected < chosen_score - 1e-9) chosen = a, chosen_score = expected;
    }
    return chosen;
  };
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<double> b(states, 0.0);
    double total = 0.0;
    for (int s = 0; s < objects; ++s) total += b[s] = std::pow(uniform01(rng), 4);
    if (trial % 2 == 1) {
      const double extra = 4.0 * total;
      b[static_cast<int>(uniform01(rng) * objects)] += extra;
      total += extra;
    }
    for (double& p : b) p /= total;
    const int expected = reference(b, {});
    EXPECT_EQ(policy.choose_sensing(b), expected) << "belief " << trial;
    EXPECT_EQ(policy.choose_sensing(b), expected) << "belief " << trial << ", remembered";
  }
}

TEST(SensingPolicyLarge, ChoosesWhatTheDefinitionChoosesAndRemembersIt) {
  Rng rng(7);
  expect_choices_of_the_definition(large_problem(rng), rng);
}

// Rows as a feature set's shrunk table has them (a flat value, the true class and three others
// above it): the sparse sum.
TEST(SensingPolicyLarge, ChoosesWhatTheDefinitionChoosesOnRowsOfOneValue) {
  Rng rng(11);
  pomdp::ObjectProblemData data = large_problem(rng);
  for (auto& action : data.observation_table)
    for (std::size_t k = 0; k < action.size(); ++k) {
      std::vector<double>& row = action[k];
      std::fill(row.begin(), row.end(), 1.0);
      row[k] = 30.0;
      for (int x = 0; x < 3; ++x) row[static_cast<std::size_t>(uniform01(rng) * 64)] += 5.0;
      double total = 0.0;
      for (double p : row) total += p;
      for (double& p : row) p /= total;
    }
  expect_choices_of_the_definition(data, rng);
}

// The same rows graded (docs/perception.md, "Graded observations"): each class heard at one of
// three grades, P(h@g | k) = P(h | k) P(g | right) when h = k, P(h | k) P(g | wrong) otherwise, so
// each grade has a flat value of its own: the sparse sum with a base value per grade.
TEST(SensingPolicyLarge, ChoosesWhatTheDefinitionChoosesOnGradedRows) {
  Rng rng(13);
  pomdp::ObjectProblemData data = large_problem(rng);
  const std::vector<std::string> labels = data.observation_symbols;
  const char* grades[] = {"low", "mid", "high"};
  const double right[] = {0.1, 0.3, 0.6}, wrong[] = {0.6, 0.3, 0.1};
  data.observation_symbols.clear();
  for (int g = 0; g < 3; ++g)
    for (const std::string& label : labels)
      data.observation_symbols.push_back(label + "@" + grades[g]);
  for (auto& action : data.observation_table)
    for (std::size_t k = 0; k < action.size(); ++k) {
      std::vector<double> row(labels.size(), 1.0);
      row[k] = 30.0;
      for (int x = 0; x < 3; ++x) row[static_cast<std::size_t>(uniform01(rng) * 64)] += 5.0;
      double total = 0.0;
      for (double p : row) total += p;
      action[k].clear();
      for (int g = 0; g < 3; ++g)
        for (std::size_t h = 0; h < row.size(); ++h)
          action[k].push_back(row[h] / total * (h == k ? right[g] : wrong[g]));
    }
  expect_choices_of_the_definition(data, rng);
}

}  // namespace
}  // namespace echoplan::solvers
