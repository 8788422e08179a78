// Beliefs: the exact filter against Bayes' rule worked by hand, the particle filter against the
// exact filter, and every recovery path.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "pomdp/cassandra_reader.h"
#include "pomdp/exact_belief.h"
#include "pomdp/make_belief.h"
#include "pomdp/model_environment.h"
#include "pomdp/particle_belief.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;

constexpr int kSlide = 0, kStrike = 1;

std::string seed_text() {
  std::ifstream in(repo_file("problems/audio_objects.yaml"));
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Bayes' rule for the seed problem written out: uniform prior times the table entries, normalised.
std::vector<double> hand_posterior(const ObjectProblemData& d,
                                   const std::vector<std::pair<int, int>>& steps) {
  std::vector<double> p(4, 0.25);
  for (auto [a, o] : steps) {
    for (int k = 0; k < 4; ++k) p[k] *= d.observation_table[a][k][o];
  }
  double z = p[0] + p[1] + p[2] + p[3];
  for (double& x : p) x /= z;
  return p;
}

TEST(ExactBelief, TigerListeningMatchesBayes) {
  const Problem p = load_problem(repo_file("problems/tiger.pomdp"));
  ExactBelief b(p.model);
  Rng rng(1);
  EXPECT_TRUE(b.update(0, Observation{0, {}}, rng));
  EXPECT_NEAR(b.probabilities()[0], 0.85, 1e-15);
  EXPECT_TRUE(b.update(0, Observation{0, {}}, rng));
  EXPECT_NEAR(b.probabilities()[0], 0.85 * 0.85 / (0.85 * 0.85 + 0.15 * 0.15), 1e-15);
  // Opening a door resets the tiger: back to uniform whatever is heard.
  EXPECT_TRUE(b.update(1, Observation{1, {}}, rng));
  EXPECT_NEAR(b.probabilities()[0], 0.5, 1e-15);
}

TEST(ExactBelief, SeedProblemMatchesBayesAndTracksTheOffset) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  const auto& d = dynamic_cast<const ObjectIdentificationModel&>(*p.model).data();
  ExactBelief b(p.model);
  Rng rng(2);
  const std::vector<std::pair<int, int>> steps = {
      {kStrike, 0}, {kSlide, 1}, {kStrike, 0}, {kSlide, 2}};
  for (auto [a, o] : steps) EXPECT_TRUE(b.update(a, Observation{o, {}}, rng));
  const std::vector<double> expected = hand_posterior(d, steps);
  const std::vector<double> marginal = b.discrete_marginal(0);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(b.probabilities()[k], expected[k], 1e-12);
    EXPECT_NEAR(marginal[k], expected[k], 1e-12);
  }
  EXPECT_EQ(b.probabilities()[4], 0.0);
  // Two slides: the object is 0.1 + 2 * 0.05 m from the end effector in every sampled state.
  const State s = b.sample(rng);
  EXPECT_NEAR(s.continuous[7], 0.2, 1e-12);
}

TEST(ExactBelief, ImpossibleObservationKeepsThePrediction) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  const auto& m = dynamic_cast<const ObjectIdentificationModel&>(*p.model);
  ExactBelief b(p.model);
  Rng rng(3);
  EXPECT_TRUE(b.update(kStrike, Observation{1, {}}, rng));
  const std::vector<double> before = b.probabilities();
  // 'none' cannot follow a sensing action without a collision, and 42 is no symbol at all.
  EXPECT_FALSE(b.update(kStrike, Observation{m.none_symbol(), {}}, rng));
  EXPECT_EQ(b.probabilities(), before);
  EXPECT_FALSE(b.update(kStrike, Observation{42, {}}, rng));
  EXPECT_EQ(b.probabilities(), before);
}

// The particle filter's marginal matches the exact posterior within sampling error. With N
// particles one resampling has standard deviation sqrt(p(1-p)/N) <= 0.5/sqrt(N); over T updates
// the errors add at most T such terms in variance, so with N = 20000 and T = 4 the standard
// deviation is at most 0.5 * sqrt(4 / 20000) = 0.0071; we allow 4 of them (0.028).
TEST(ParticleBelief, MatchesTheExactPosteriorWithinSamplingError) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  const int n = 20000;
  const std::vector<std::pair<int, int>> steps = {
      {kStrike, 0}, {kStrike, 1}, {kSlide, 1}, {kStrike, 1}};
  for (std::uint64_t seed : {11u, 12u, 13u}) {
    Rng rng(seed);
    ParticleBelief particles(p.model, n, rng);
    ExactBelief exact(p.model);
    for (auto [a, o] : steps) {
      EXPECT_TRUE(particles.update(a, Observation{o, {}}, rng));
      exact.update(a, Observation{o, {}}, rng);
    }
    const std::vector<double> pm = particles.discrete_marginal(0);
    const std::vector<double> em = exact.discrete_marginal(0);
    const double bound = 4 * 0.5 * std::sqrt(static_cast<double>(steps.size()) / n);
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(pm[k], em[k], bound) << "seed " << seed << " object " << k;
    const std::vector<int> counts = particles.particle_counts(0);
    EXPECT_EQ(counts[0] + counts[1] + counts[2] + counts[3], n);
  }
}

TEST(ParticleBelief, SameSeedSameParticles) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  auto run = [&] {
    Rng rng(7);
    ParticleBelief b(p.model, 1000, rng);
    b.update(kSlide, Observation{2, {}}, rng);
    b.update(kStrike, Observation{3, {}}, rng);
    return b.particles();
  };
  EXPECT_EQ(run(), run());
}

// A problem where the slide tells pringles_can apart perfectly, to make particles disagree with
// an observation.
Problem sharp_problem() {
  std::string text = seed_text();
  const std::string row = "pringles_can: [0.5, 0.3, 0.15, 0.05]";
  text.replace(text.find(row), row.size(), "pringles_can: [1, 0, 0, 0]");
  return parse_problem_yaml(text, "sharp.yaml");
}

TEST(ParticleBelief, ReinvigoratesFromTheInitialBeliefReplayingHistory) {
  const Problem p = sharp_problem();
  Rng rng(8);
  ParticleBelief b(p.model, 500, rng);
  // Slide, hear pringles_can: only pringles_can (1.0) and the others (0.11, 0.11, 0.01) explain it.
  EXPECT_TRUE(b.update(kSlide, Observation{0, {}}, rng));
  // Force a belief that is all pringles_can, then hear coffee_mug after a slide: impossible for it.
  std::vector<State> all_pringles(500, b.particles()[0]);
  for (auto& s : all_pringles) s.discrete[0] = 0;
  ParticleBelief forced(p.model, all_pringles);
  EXPECT_FALSE(forced.update(kSlide, Observation{1, {}}, rng));
  const std::vector<int> counts = forced.particle_counts(0);
  EXPECT_EQ(counts[0], 0);
  EXPECT_EQ(counts[0] + counts[1] + counts[2] + counts[3], 500);
  // No history in `forced`: replay covers only this slide, so offsets are 0.1 + 0.05.
  for (const State& s : forced.particles()) EXPECT_NEAR(s.continuous[7], 0.15, 1e-12);

  // With history: b has slid once already; reinvigoration must replay that slide as well.
  for (int i = 0; i < 20 && b.particle_counts(0)[0] < 500; ++i)
    b.update(kSlide, Observation{0, {}}, rng);
  ASSERT_EQ(b.particle_counts(0)[0], 500);
  const double offset_before = b.particles()[0].continuous[7];
  EXPECT_FALSE(b.update(kSlide, Observation{1, {}}, rng));
  EXPECT_EQ(b.particle_counts(0)[0], 0);
  for (const State& s : b.particles()) EXPECT_NEAR(s.continuous[7], offset_before + 0.05, 1e-9);
}

TEST(ParticleBelief, ImpossibleObservationKeepsTheParticles) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  const auto& m = dynamic_cast<const ObjectIdentificationModel&>(*p.model);
  Rng rng(9);
  ParticleBelief b(p.model, 300, rng);
  const std::vector<int> before = b.particle_counts(0);
  EXPECT_FALSE(b.update(kStrike, Observation{m.none_symbol(), {}}, rng));
  EXPECT_EQ(b.size(), 300);
  // Ignoring the observation resamples the (unchanged) objects uniformly: counts stay close.
  const std::vector<int> after = b.particle_counts(0);
  int total = 0;
  for (int c : after) total += c;
  EXPECT_EQ(total, 300);
  // Systematic resampling of equal weights reproduces the set exactly.
  EXPECT_EQ(after, before);
}

TEST(MakeBelief, FollowsTheProblemSettings) {
  Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  Rng rng(10);
  BeliefPtr particles = make_belief(p, rng);
  ASSERT_NE(dynamic_cast<ParticleBelief*>(particles.get()), nullptr);
  EXPECT_EQ(dynamic_cast<ParticleBelief&>(*particles).size(), 1000);
  p.belief.type = BeliefSettings::Type::exact;
  BeliefPtr exact = make_belief(p, rng);
  EXPECT_NE(dynamic_cast<ExactBelief*>(exact.get()), nullptr);
  // A clone is independent of its original.
  BeliefPtr copy = exact->clone();
  exact->update(kStrike, Observation{0, {}}, rng);
  EXPECT_EQ(copy->discrete_marginal(0), (std::vector<double>{0.25, 0.25, 0.25, 0.25}));
}

TEST(ModelEnvironment, StepsTheTrueStateUntilTheEpisodeEnds) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  const auto& m = dynamic_cast<const ObjectIdentificationModel&>(*p.model);
  ModelEnvironment env(p.model);
  Rng rng(11);
  env.reset(m.tabular_state(2), rng);
  Outcome slide = env.execute(kSlide, rng);
  EXPECT_EQ(slide.reward, -1.0);
  EXPECT_FALSE(slide.terminal);
  EXPECT_NEAR(env.true_state().continuous[7], 0.15, 1e-12);
  Outcome sort = env.execute(2, rng);  // move_to_A: plastic_cup belongs at A
  EXPECT_EQ(sort.reward, 10.0);
  EXPECT_TRUE(sort.terminal);
  EXPECT_THROW(env.execute(kSlide, rng), std::logic_error);
}

}  // namespace
}  // namespace echoplan::pomdp
