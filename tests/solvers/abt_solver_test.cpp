// ABT on the report's shipped problem: as published, stored episodes revised on a model change (the
// observation table recalibrated) against a tree built afresh with the new model; and the policy
// leaf value, which decides from the tree's exact belief (POMCP refuses it: it stays textbook).
#include "solvers/abt_solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "../common/source_dir.h"
#include "common/error.h"
#include "pomdp/exact_belief.h"
#include "pomdp/particle_belief.h"
#include "pomdp/problem.h"
#include "solvers/identification_solver.h"
#include "solvers/model_change.h"
#include "solvers/planner_overrides.h"
#include "solvers/pomcp_solver.h"

namespace echoplan::solvers {
namespace {

using pomdp::ObjectIdentificationModel;
using pomdp::ObjectProblemData;

constexpr int kSlide = 0, kStrike = 1;

pomdp::Problem report_problem() {
  return pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
}

std::shared_ptr<const ObjectIdentificationModel> report_model() {
  const pomdp::ModelPtr model = report_problem().model;
  // The same model, shared with the problem's pointer (aliasing constructor).
  return std::shared_ptr<const ObjectIdentificationModel>(model, model->object_identification());
}

// The report's model with a recalibrated strike: the pringles can and the mug now sound the same
// when struck (their rows were 0.6 on their own symbols and 0.05 on each other's). The strike loses
// much of its value.
std::shared_ptr<const ObjectIdentificationModel> recalibrated(const ObjectIdentificationModel& m) {
  ObjectProblemData data = m.data();
  data.observation_table[kStrike][0] = {0.3, 0.3, 0.35, 0.05};
  data.observation_table[kStrike][1] = {0.3, 0.3, 0.35, 0.05};
  return std::make_shared<const ObjectIdentificationModel>(std::move(data));
}

// The shipped model behind a counter of simulator calls (the cost measure: wall time is for
// benchmarks).
class CountingModel final : public pomdp::Model {
 public:
  explicit CountingModel(pomdp::ModelPtr inner) : inner_(std::move(inner)) {}
  const pomdp::ModelSpec& spec() const override { return inner_->spec(); }
  pomdp::State sample_initial_state(Rng& rng) const override {
    return inner_->sample_initial_state(rng);
  }
  pomdp::StepResult step(const pomdp::State& s, int a, Rng& rng) const override {
    ++steps;
    return inner_->step(s, a, rng);
  }
  double observation_likelihood(const pomdp::State& s, int a,
                                const pomdp::Observation& o) const override {
    ++likelihoods;
    return inner_->observation_likelihood(s, a, o);
  }
  double heuristic_value(const pomdp::State& s) const override {
    return inner_->heuristic_value(s);
  }
  const pomdp::TabularModel* tabular() const override { return inner_->tabular(); }
  pomdp::State tabular_state(int s) const override { return inner_->tabular_state(s); }

  mutable std::int64_t steps = 0, likelihoods = 0;

 private:
  pomdp::ModelPtr inner_;
};

// The shipped problem's planner section (exploration 110, depth 100) with the lookahead leaf (the
// policy leaf cannot be revised: revise() refuses it), keeping the episodes.
SearchOptions seed_options() {
  PlannerOverrides lookahead;
  lookahead.leaf = "lookahead";
  SearchOptions options = search_options(lookahead, report_problem());
  options.keep_episodes = true;
  return options;
}

struct Tree {
  std::vector<double> q;  // root Q-values
  std::int64_t steps = 0, likelihoods = 0;
  RevisionStats revision;
};

// A tree of `episodes` episodes from a 1000-particle belief drawn with `seed`: built with `build`,
// and then revised to `revise_to` when given.
Tree grow(pomdp::ModelPtr build, pomdp::ModelPtr revise_to, std::uint64_t seed, int episodes,
          std::vector<double>* before_revision = nullptr) {
  auto counted = std::make_shared<CountingModel>(build);
  AbtSolver solver(counted, seed_options());
  Rng rng(seed);
  pomdp::ParticleBelief belief(build, 1000, rng);
  solver.reset(belief, rng);
  solver.improve(Budget::episodes(episodes), rng);
  Tree tree;
  if (before_revision) *before_revision = solver.root_action_values();
  tree.steps = counted->steps;
  if (revise_to) {
    auto counted_after = std::make_shared<CountingModel>(revise_to);
    ModelChange change;
    change.model = counted_after;
    change.rows = {{kStrike, 0}, {kStrike, 1}};
    const std::int64_t likelihoods_before = counted->likelihoods;
    tree.revision = solver.revise(change, rng);
    EXPECT_EQ(solver.stored_episodes(), episodes);
    EXPECT_EQ(solver.stats().episodes_total, episodes);
    tree.steps = counted_after->steps;
    tree.likelihoods = counted_after->likelihoods + counted->likelihoods - likelihoods_before;
  }
  tree.q = solver.root_action_values();
  return tree;
}

struct MeanSd {
  double mean = 0, sd = 0;
};
MeanSd mean_sd(const std::vector<double>& x) {
  MeanSd r;
  for (double v : x) r.mean += v;
  r.mean /= x.size();
  for (double v : x) r.sd += (v - r.mean) * (v - r.mean);
  r.sd = std::sqrt(r.sd / (x.size() - 1));
  return r;
}

TEST(AbtRevision, RevisedTreeMatchesAFreshTreeAtAFractionOfTheCost) {
  // K independent seeds; per seed, the same root particles (same seed) for three trees of N
  // episodes: built with the old table and revised, built afresh with the new table, and the old
  // tree left stale. For each root action, the mean Q of the revised trees must lie within 4
  // standard errors of the difference of the means (computed from the K-seed spreads) of the
  // fresh trees' mean: with K = 10 that is a t-statistic of 4 on ~18 degrees of freedom, a false
  // alarm below 0.2% per action for a revision that is exact in distribution. The stale trees
  // must fail the same check for the strike (the change is large enough for the check to see), and
  // the revision must cost less than a third of the fresh build in model steps.
  const auto old_model = report_model();
  const auto new_model = recalibrated(*old_model);
  const int K = 10, N = 3000;
  const int actions = old_model->num_actions();
  std::vector<std::vector<double>> revised(actions), fresh(actions), stale(actions);
  std::int64_t revise_steps = 0, revise_likelihoods = 0, fresh_steps = 0, resimulated = 0,
               affected = 0;
  for (int k = 0; k < K; ++k) {
    std::vector<double> before;
    const Tree r = grow(old_model, new_model, 100 + k, N, &before);
    const Tree f = grow(new_model, nullptr, 100 + k, N);
    revise_steps += r.steps;
    revise_likelihoods += r.likelihoods;
    fresh_steps += f.steps;
    resimulated += r.revision.resimulated_episodes;
    affected += r.revision.affected_steps;
    for (int a = 0; a < actions; ++a) {
      revised[a].push_back(r.q[a]);
      fresh[a].push_back(f.q[a]);
      stale[a].push_back(before[a]);
    }
  }
  std::printf(
      "revision: %lld model steps + %lld likelihoods for %lld affected steps, %lld "
      "episodes re-simulated (of %d); fresh build: %lld model steps (ratio %.3f)\n",
      static_cast<long long>(revise_steps), static_cast<long long>(revise_likelihoods),
      static_cast<long long>(affected), static_cast<long long>(resimulated), K * N,
      static_cast<long long>(fresh_steps),
      static_cast<double>(revise_steps) / static_cast<double>(fresh_steps));
  for (int a = 0; a < actions; ++a) {
    const MeanSd r = mean_sd(revised[a]), f = mean_sd(fresh[a]), s = mean_sd(stale[a]);
    const double se_rf = std::sqrt((r.sd * r.sd + f.sd * f.sd) / K);
    const double se_sf = std::sqrt((s.sd * s.sd + f.sd * f.sd) / K);
    std::printf(
        "%-10s revised %.3f +- %.3f  fresh %.3f +- %.3f  stale %.3f +- %.3f  "
        "(revised - fresh) / se = %.2f, (stale - fresh) / se = %.2f\n",
        old_model->spec().action_names[a].c_str(), r.mean, r.sd, f.mean, f.sd, s.mean, s.sd,
        (r.mean - f.mean) / se_rf, (s.mean - f.mean) / se_sf);
    EXPECT_LE(std::abs(r.mean - f.mean), 4 * se_rf) << old_model->spec().action_names[a];
    if (a == kStrike) {
      EXPECT_GT(std::abs(s.mean - f.mean), 4 * se_sf) << "the check has no power";
    }
  }
  EXPECT_GT(resimulated, 0);
  EXPECT_LT(3 * revise_steps, fresh_steps);
}

TEST(AbtRevision, AChangeOfNoRowsLeavesTheTreeAsItWas) {
  const auto model = report_model();
  std::vector<double> before;
  AbtSolver solver(model, seed_options());
  Rng rng(5);
  pomdp::ParticleBelief belief(model, 300, rng);
  solver.reset(belief, rng);
  solver.improve(Budget::episodes(500), rng);
  before = solver.root_action_values();
  ModelChange change;
  change.model = recalibrated(*model);  // a new table, but announced as no changed row
  const RevisionStats stats = solver.revise(change, rng);
  EXPECT_EQ(stats.affected_steps, 0);
  EXPECT_EQ(stats.episodes, 500);
  EXPECT_EQ(solver.root_action_values(), before);
}

TEST(AbtRevision, ChangedRowsAreFoundAndOtherChangesRefused) {
  const auto model = report_model();
  const ModelChange change = observation_table_change(*model, recalibrated(*model));
  EXPECT_EQ(change.rows, (std::vector<ObservationRow>{{kStrike, 0}, {kStrike, 1}}));
  ObjectProblemData data = model->data();
  data.sorting_reward[0][0] = 5;
  EXPECT_THROW(observation_table_change(
                   *model, std::make_shared<const ObjectIdentificationModel>(std::move(data))),
               InputError);
  // A model with other actions cannot replace the planning model.
  data = model->data();
  data.sensing[kSlide].name = "push";
  AbtSolver solver(model, seed_options());
  Rng rng(1);
  pomdp::ParticleBelief belief(model, 50, rng);
  solver.reset(belief, rng);
  solver.improve(Budget::episodes(10), rng);
  ModelChange other;
  other.model = std::make_shared<const ObjectIdentificationModel>(std::move(data));
  EXPECT_THROW(solver.revise(other, rng), InputError);
  // Without kept episodes there is nothing to revise.
  SearchOptions plain = seed_options();
  plain.keep_episodes = false;
  AbtSolver forgetful(model, plain);
  forgetful.reset(belief, rng);
  forgetful.improve(Budget::episodes(10), rng);
  EXPECT_EQ(forgetful.stored_episodes(), 0);
  EXPECT_THROW(forgetful.revise(observation_table_change(*model, recalibrated(*model)), rng),
               std::logic_error);
}

// The sequence docs/planning.md gives users ("How to use it when the observation table is
// recalibrated"): lookahead leaf and kept episodes from the problem's planner section, a real step,
// the strike's table recalibrated mid-trial, revise(), the belief moved to the new model, planning
// on.
TEST(AbtRevision, DocumentedUsageRevisesAMidTrialTable) {
  const pomdp::Problem problem = report_problem();
  const auto old_model = report_model();
  const auto new_model = recalibrated(*old_model);
  PlannerOverrides overrides;
  overrides.leaf = "lookahead";
  SearchOptions options = search_options(overrides, problem);
  options.keep_episodes = true;
  AbtSolver solver(old_model, options);
  Rng rng(11);
  pomdp::ParticleBelief belief(old_model, 1000, rng);
  solver.reset(belief, rng);
  solver.improve(Budget::episodes(1000), rng);
  pomdp::Observation heard;
  heard.index = 0;  // the strike sounded like the pringles can
  belief.update(kStrike, heard, rng);
  solver.update(kStrike, heard, belief, rng);
  const std::int64_t kept = solver.stored_episodes();
  ASSERT_GT(kept, 0);

  const RevisionStats stats = solver.revise(observation_table_change(*old_model, new_model), rng);
  EXPECT_EQ(stats.episodes, kept);
  // Below the root the strike is tried again, and its changed rows (pringles can, mug) are used.
  EXPECT_GT(stats.affected_steps, 0);
  EXPECT_LE(stats.kept_observations, stats.affected_steps);
  EXPECT_GT(stats.resimulated_episodes, 0);

  pomdp::ParticleBelief new_belief(new_model, 1000, rng);
  const std::int64_t before = solver.stats().episodes_total;
  solver.improve(Budget::episodes(500), rng);
  EXPECT_EQ(solver.stats().episodes_total, before + 500);
  const int action = solver.best_action();
  EXPECT_TRUE(action >= 0 && action < new_model->num_actions());
  // The next real step updates both with the new model's belief.
  new_belief.update(kStrike, heard, rng);
  solver.update(kStrike, heard, new_belief, rng);
  EXPECT_GT(solver.stored_episodes(), 0);
}

TEST(AbtRevision, UpdateKeepsTheEpisodesThroughTheNewRoot) {
  const auto model = report_model();
  AbtSolver solver(model, seed_options());
  Rng rng(3);
  pomdp::ParticleBelief belief(model, 500, rng);
  solver.reset(belief, rng);
  solver.improve(Budget::episodes(2000), rng);
  ASSERT_EQ(solver.stored_episodes(), 2000);
  const pomdp::Observation heard{1, {}};
  belief.update(kStrike, heard, rng);
  solver.update(kStrike, heard, belief, rng);
  const std::int64_t kept = solver.stored_episodes();
  EXPECT_GT(kept, 0);
  EXPECT_LT(kept, 2000);
  // The kept episodes can be revised and the search goes on from them.
  const RevisionStats stats =
      solver.revise(observation_table_change(*model, recalibrated(*model)), rng);
  EXPECT_EQ(stats.episodes, kept);
  EXPECT_GT(stats.affected_steps, 0);
  solver.improve(Budget::episodes(100), rng);
  EXPECT_EQ(solver.stored_episodes(), kept + 100);
  solver.reset(belief, rng);
  EXPECT_EQ(solver.stored_episodes(), 0);
}

std::string repo_file(const std::string& relative) {
  return echoplan::testing::source_dir() + "/" + relative;
}

constexpr int kMoveToA = 2;

// ABT's options with one of the leaves that need a tabular identification problem.
SearchOptions tabular_leaf(LeafMode mode) {
  SearchOptions options;
  options.leaf.mode = mode;
  options.root_particles = 200;
  return options;
}

SearchOptions policy_leaf() { return tabular_leaf(LeafMode::policy); }

TEST(AbtPolicyLeaf, SensesFirstAndSortsOnceTheEvidenceIsStrong) {
  const pomdp::Problem p = pomdp::load_problem(repo_file("problems/audio_objects.yaml"));
  AbtSolver solver(p.model, policy_leaf());
  pomdp::ExactBelief belief(p.model);
  Rng rng(5);
  solver.reset(belief, rng);
  solver.improve(Budget::episodes(3000), rng);
  // At the uniform prior sorting loses 45 on average; V*(b0) is about 2.95.
  EXPECT_FALSE(solver.best_action() >= kMoveToA);
  // Five strikes that all sound like the pringles can (A): P(B) = 8e-6, so sorting to A is best by
  // far (sensing once more costs at least 1 and can gain at most 110 * 8e-6).
  pomdp::Observation pringles;
  pringles.index = 0;
  for (int i = 0; i < 5; ++i) {
    belief.update(kStrike, pringles, rng);
    solver.update(kStrike, pringles, belief, rng);
  }
  solver.improve(Budget::episodes(2000), rng);
  EXPECT_EQ(solver.best_action(), kMoveToA);
}

TEST(AbtPolicyLeaf, RevisionIsRefusedBecauseEveryNodesValueDependsOnTheTable) {
  const auto model = report_model();
  SearchOptions options = policy_leaf();
  options.keep_episodes = true;
  AbtSolver solver(model, options);
  Rng rng(5);
  pomdp::ParticleBelief belief(model, 200, rng);
  solver.reset(belief, rng);
  solver.improve(Budget::episodes(50), rng);
  EXPECT_THROW(solver.revise(observation_table_change(*model, recalibrated(*model)), rng),
               std::logic_error);
}

TEST(AbtPolicyLeaf, NeedsAnIdentificationProblem) {
  const pomdp::Problem tiger = pomdp::load_problem(repo_file("problems/tiger.pomdp"));
  EXPECT_THROW(AbtSolver(tiger.model, policy_leaf()), InputError);
  EXPECT_EQ(default_leaf_mode("abt", *tiger.model), LeafMode::lookahead);
  const pomdp::Problem report = pomdp::load_problem(repo_file("problems/audio_objects.yaml"));
  EXPECT_EQ(default_leaf_mode("abt", *report.model), LeafMode::policy);
  EXPECT_EQ(default_leaf_mode("pomcp", *report.model), LeafMode::lookahead);
  EXPECT_THROW(PomcpSolver(report.model, policy_leaf()), InputError);
}

SearchOptions exact_leaf() { return tabular_leaf(LeafMode::exact); }

TEST(AbtExactLeaf, TakesTheActionTheExactBoundsProveOptimal) {
  // At beliefs from one observation to nearly certain, a separate exact solver refined there
  // (10,000 expansions) proves one action optimal (its lower bound on Q* at least every other
  // action's upper bound); ABT with the exact leaf and 2,000 episodes' worth of budget per step
  // must take it.
  const pomdp::Problem p = pomdp::load_problem(repo_file("problems/audio_objects.yaml"));
  const pomdp::TabularModel& m = *p.model->tabular();
  // Heard: slide "pringles_can"; strike "pringles_can" twice; three times; strike "coffee_mug"
  // three times.
  const std::vector<std::vector<std::pair<int, int>>> histories = {
      {{kSlide, 0}},
      {{kStrike, 0}, {kStrike, 0}},
      {{kStrike, 0}, {kStrike, 0}, {kStrike, 0}},
      {{kStrike, 1}, {kStrike, 1}, {kStrike, 1}},
  };
  std::vector<int> optimal;
  for (const auto& history : histories) {
    IdentificationSolver reference(m);
    IdentificationSolver::NodeId node = reference.root();
    for (const auto& [a, o] : history) node = reference.child(node, a, o);
    reference.refine(node, RefineLimits{1e-4, 0.0, 10000});

    int best = 0;
    for (int a = 1; a < m.num_actions(); ++a)
      if (reference.action_value(node, a).lower > reference.action_value(node, best).lower)
        best = a;
    for (int a = 0; a < m.num_actions(); ++a) {
      if (a == best) continue;
      ASSERT_LE(reference.action_value(node, a).upper, reference.action_value(node, best).lower)
          << "the reference bounds do not separate action " << a << " after " << history.size()
          << " observations";
    }
    optimal.push_back(best);

    AbtSolver solver(p.model, exact_leaf());
    pomdp::ExactBelief belief(p.model);
    Rng rng(7);
    solver.reset(belief, rng);
    for (const auto& [a, o] : history) {
      pomdp::Observation heard;
      heard.index = o;
      belief.update(a, heard, rng);
      solver.update(a, heard, belief, rng);
    }
    solver.improve(Budget::episodes(2000), rng);
    EXPECT_EQ(solver.best_action(), best) << "after " << history.size() << " observations";
  }
  // The beliefs cover both sensing actions and both sorting actions.
  EXPECT_EQ(optimal, (std::vector<int>{kStrike, kSlide, kMoveToA, kMoveToA + 1}));
}

TEST(AbtExactLeaf, FallsBackToThePolicyLeafAtABeliefTheExactSolverDoesNotHold) {
  // Reset at "surely the mug" (not the problem's start belief): no count vector holds it, so the
  // guide is off and ABT plans with the policy leaf from the tree's own exact beliefs.
  const auto model = report_model();
  AbtSolver solver(model, exact_leaf());
  Rng rng(3);
  pomdp::ParticleBelief belief(model, 200, rng);
  for (int i = 0; i < 8; ++i) {
    pomdp::Observation mug;
    mug.index = 1;
    belief.update(kStrike, mug, rng);
  }
  solver.reset(belief, rng);
  solver.improve(Budget::episodes(500), rng);
  EXPECT_EQ(solver.best_action(), kMoveToA + 1);  // the mug goes to B
  EXPECT_EQ(solver.stats().episodes_last, 500);
}

TEST(AbtExactLeaf, NeedsAnIdentificationProblemAndIsAbtsOnly) {
  const pomdp::Problem tiger = pomdp::load_problem(repo_file("problems/tiger.pomdp"));
  EXPECT_THROW(AbtSolver(tiger.model, exact_leaf()), InputError);
  const pomdp::Problem report = pomdp::load_problem(repo_file("problems/audio_objects.yaml"));
  EXPECT_THROW(PomcpSolver(report.model, exact_leaf()), InputError);
  SearchOptions offline = exact_leaf();
  offline.leaf.mode = LeafMode::exact_offline;
  EXPECT_THROW(PomcpSolver(report.model, offline), InputError);
  offline.leaf.exact_share = 1.5;
  EXPECT_THROW(AbtSolver(report.model, offline), InputError);
}

SearchOptions unheard_at(UnheardOutcomes unheard) {
  SearchOptions options = policy_leaf();
  options.unheard = unheard;
  return options;
}

// Sensing once from the report's uniform prior, by hand from the table's columns (a quarter of the
// mass per object; A = pringles can and plastic cup, B = coffee mug and paper base): P(o) and
// P(o) times the best sort's value after o, 10 per unit of the bin's mass and -100 per unit of the
// other's, for the outcomes heard as pringles can, coffee mug, plastic cup and paper base. Slide's
// outcomes put 0.61 / 0.12 (A / B), 0.41 / 0.68, 0.82 / 0.59 and 0.16 / 0.61 there; strike's
// 0.71 / 0.16, 0.16 / 0.71, 0.97 / 0.41 and 0.16 / 0.72.
struct OneSensing {
  double probability[4];
  double commit[4];  // P(o) commit_value(b after o)
  double commit_after() const { return commit[0] + commit[1] + commit[2] + commit[3]; }
};
constexpr OneSensing kSlideOnce{
    {0.1825, 0.2725, 0.3525, 0.1925},
    {0.25 * (6.1 - 12), 0.25 * (6.8 - 41), 0.25 * (8.2 - 59), 0.25 * (6.1 - 16)}};
constexpr OneSensing kStrikeOnce{
    {0.2175, 0.2175, 0.345, 0.22},
    {0.25 * (7.1 - 16), 0.25 * (7.1 - 16), 0.25 * (9.7 - 41), 0.25 * (7.2 - 16)}};
constexpr double kSense = -1, kGamma = 0.99;

std::vector<double> root_values(UnheardOutcomes unheard, int seed, int episodes) {
  const pomdp::Problem p = pomdp::load_problem(repo_file("problems/audio_objects.yaml"));
  AbtSolver solver(p.model, unheard_at(unheard));
  pomdp::ExactBelief belief(p.model);
  Rng rng(static_cast<std::uint64_t>(seed));
  solver.reset(belief, rng);
  solver.improve(Budget::episodes(episodes), rng);
  return solver.root_action_values();
}

TEST(AbtUnheardOutcomes, AtCommitSensingIsWorthAtLeastSensingOnceThenSorting) {
  // Unheard outcomes at their commit value and heard ones at least at theirs: the one-step plan
  // is a floor however few episodes there were. (An action no episode tried is NaN.)
  for (int seed = 1; seed <= 10; ++seed)
    for (int episodes : {8, 16, 32, 64}) {
      const std::vector<double> q = root_values(UnheardOutcomes::commit, seed, episodes);
      EXPECT_FALSE(q[kSlide] < kSense + kGamma * kSlideOnce.commit_after() - 1e-9) << seed;
      EXPECT_FALSE(q[kStrike] < kSense + kGamma * kStrikeOnce.commit_after() - 1e-9) << seed;
    }
}

// Q of a sensing action from the report's uniform prior when only outcome o was heard and its
// child is worth v, as `unheard` counts the other outcomes (search_tree.h, UnheardOutcomes).
double one_heard_outcome(UnheardOutcomes unheard, const OneSensing& once, int o, double v) {
  if (unheard == UnheardOutcomes::share) return kSense + kGamma * v;  // v stands for all
  const double p = once.probability[o], c = once.commit[o];
  return kSense + kGamma * (once.commit_after() + std::max(p * v, c) - c);
}

TEST(AbtUnheardOutcomes, OneHeardOutcomeStandsForAllOrOnlyForItself) {
  // The root branches from the first episode, and an untried action goes first: the first four
  // episodes try slide, strike, A and B in turn, so after 4 each sensing action has one heard
  // outcome o, whose child holds one leaf value v, the same under both estimates (same seed, same
  // rollouts). Shared, v stands for every outcome, so Q = -1 + 0.99 v gives v; from it, Q at
  // commit for the one o that was heard.
  for (int seed = 1; seed <= 10; ++seed) {
    const std::vector<double> shared = root_values(UnheardOutcomes::share, seed, 4);
    const std::vector<double> q = root_values(UnheardOutcomes::commit, seed, 4);
    for (auto [action, once] : {std::pair{kSlide, kSlideOnce}, std::pair{kStrike, kStrikeOnce}}) {
      const double v = (shared[action] - kSense) / kGamma;
      double nearest = std::numeric_limits<double>::infinity();
      for (int o = 0; o < 4; ++o)
        nearest = std::min(
            nearest, std::abs(q[action] - one_heard_outcome(UnheardOutcomes::commit, once, o, v)));
      EXPECT_LT(nearest, 1e-9) << "seed " << seed << ", action " << action;
    }
  }
}

TEST(AbtUnheardOutcomes, CommitNeedsALeafThatFollowsTheExactBelief) {
  const pomdp::Problem report = pomdp::load_problem(repo_file("problems/audio_objects.yaml"));
  SearchOptions lookahead = unheard_at(UnheardOutcomes::commit);
  lookahead.leaf.mode = LeafMode::lookahead;
  EXPECT_THROW(AbtSolver(report.model, lookahead), InputError);
  EXPECT_EQ(parse_unheard_outcomes("commit"), UnheardOutcomes::commit);
  EXPECT_THROW(parse_unheard_outcomes("Commit"), InputError);
}

}  // namespace
}  // namespace echoplan::solvers
