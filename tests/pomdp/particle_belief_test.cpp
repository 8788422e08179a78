// The particle filter against the exact filter, its reproducibility and every recovery path.
#include "pomdp/particle_belief.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pomdp/exact_belief.h"
#include "pomdp/problem.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;
using testing::repo_text;

constexpr int kSlide = 0, kStrike = 1;

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
  std::string text = repo_text("problems/audio_objects.yaml");
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

// The exact posterior marginal over the objects after `steps` (action, observation index).
std::vector<double> exact_marginal(const Problem& p,
                                   const std::vector<std::pair<int, int>>& steps) {
  ExactBelief exact(p.model);
  Rng unused(0);
  for (auto [a, o] : steps) exact.update(a, Observation{o, {}}, unused);
  return exact.discrete_marginal(0);
}

TEST(ParticleBelief, AnObjectResampledAwayComesBackWhenTheEvidenceCallsForIt) {
  // Six strikes that sound like the pringles can (O0: 0.6 for it, 0.05 for the mug) leave the
  // mug with posterior ~1e-7: 200 particles hold none of it. Nine strikes that sound like the mug
  // (O1) then make it the exact posterior's favourite (~0.999). Plain SIR (fresh share 0) never
  // gets it back; the filter with fresh particles weighted by the whole history must follow the
  // exact belief.
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  std::vector<std::pair<int, int>> steps(6, {kStrike, 0});
  steps.insert(steps.end(), 9, {kStrike, 1});
  const std::vector<double> exact = exact_marginal(p, steps);
  ASSERT_GT(exact[1], 0.99);
  for (std::uint64_t seed : {21u, 22u, 23u}) {
    Rng rng(seed);
    ParticleBelief plain(p.model, 200, rng, 0.0);
    ParticleBelief filter(p.model, 200, rng);
    for (std::size_t t = 0; t < steps.size(); ++t) {
      const auto [a, o] = steps[t];
      plain.update(a, Observation{o, {}}, rng);
      EXPECT_TRUE(filter.update(a, Observation{o, {}}, rng));
      if (t == 5) {
        EXPECT_EQ(plain.particle_counts(0)[1], 0) << "seed " << seed << ": the mug was not lost";
        EXPECT_LE(filter.particle_counts(0)[1], 1) << "seed " << seed;
      }
    }
    EXPECT_EQ(plain.particle_counts(0)[1], 0) << "seed " << seed;
    EXPECT_NEAR(filter.discrete_marginal(0)[1], exact[1], 0.05) << "seed " << seed;
  }
}

TEST(ParticleBelief, ReinvigoratedParticlesAreWeightedByTheWholeHistory) {
  // In the sharp problem the slide never sounds O2 for the pringles can. Eight strikes heard as O0
  // leave only pringles cans in the set; a slide heard as O2 then explains none of them, and the
  // set is rebuilt from fresh particles. Weighted by the whole history, the mug is nearly ruled
  // out by the strikes (exact posterior ~2e-4); weighted by the last observation only, it would
  // get about 0.09 (0.11 / (0.11 + 0.67 + 0.48)).
  const Problem p = sharp_problem();
  std::vector<std::pair<int, int>> steps(8, {kStrike, 0});
  steps.push_back({kSlide, 2});
  const std::vector<double> exact = exact_marginal(p, steps);
  ASSERT_LT(exact[1], 0.01);
  for (std::uint64_t seed : {31u, 32u}) {
    Rng rng(seed);
    ParticleBelief b(p.model, 2000, rng);
    for (std::size_t t = 0; t + 1 < steps.size(); ++t)
      b.update(steps[t].first, Observation{steps[t].second, {}}, rng);
    ASSERT_EQ(b.particle_counts(0)[0], 2000) << "seed " << seed;
    EXPECT_FALSE(b.update(kSlide, Observation{2, {}}, rng)) << "seed " << seed;
    const std::vector<double> m = b.discrete_marginal(0);
    EXPECT_EQ(m[0], 0.0);
    EXPECT_LT(m[1], 0.02) << "seed " << seed;
    // Cup and base: binomial sd of a share ~0.5 among ~1000 effective draws is ~0.016.
    for (int k = 2; k < 4; ++k) EXPECT_NEAR(m[k], exact[k], 0.06) << "seed " << seed;
  }
}

TEST(ParticleBelief, ImpossibleObservationKeepsTheParticles) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  const auto& m = (*p.model->object_identification());
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

}  // namespace
}  // namespace echoplan::pomdp
