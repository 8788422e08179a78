// The exact belief filter against Bayes' rule worked by hand, on Tiger and the report's problem.
#include "pomdp/exact_belief.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pomdp/problem.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;

constexpr int kSlide = 0, kStrike = 1;

// Bayes' rule for the report's problem written out: uniform prior times the table entries,
// normalised.
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

TEST(ExactBelief, ReportProblemMatchesBayesAndTracksTheOffset) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  const auto& d = (*p.model->object_identification()).data();
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
  const auto& m = (*p.model->object_identification());
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

}  // namespace
}  // namespace echoplan::pomdp
