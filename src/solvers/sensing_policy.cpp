#include "solvers/sensing_policy.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"
#include "solvers/identification_solver.h"

namespace echoplan::solvers {

SensingPolicy::SensingPolicy(const pomdp::TabularModel& model) {
  if (auto why = identification_shape_problem(model))
    throw InputError(
        "the policy leaf value needs an identification problem (the state stays "
        "fixed until an action ends the episode), and this one is not: " +
        *why);
  num_states_ = model.num_states();
  num_actions_ = model.num_actions();
  num_observations_ = model.num_observations();
  discount_ = model.discount();
  const int S = num_states_, A = num_actions_, O = num_observations_;
  absorbing_.resize(S);
  for (int s = 0; s < S; ++s) absorbing_[s] = model.terminal(s);
  reward_.resize(static_cast<std::size_t>(S) * A);
  stay_.resize(static_cast<std::size_t>(A) * S);
  emission_.assign(static_cast<std::size_t>(A) * O * S, 0.0);
  terminal_.assign(A, true);
  for (int a = 0; a < A; ++a)
    for (int s = 0; s < S; ++s) {
      reward_[s * A + a] = model.reward(s, a);
      if (absorbing_[s]) continue;
      const double stay = model.transition(s, a, s);
      stay_[a * S + s] = stay;
      if (stay > 0.0) terminal_[a] = false;
      for (int o = 0; o < O; ++o)
        emission_[(a * O + o) * S + s] = stay * model.observation(a, s, o);
    }
  for (int a = 0; a < A; ++a)
    if (!terminal_[a]) sensing_.push_back(a);
  best_commit_.assign(S, 0.0);
  best_terminal_.assign(S, -1);
  double top = -std::numeric_limits<double>::infinity(), bottom = -top;
  for (int s = 0; s < S; ++s) {
    if (absorbing_[s]) continue;
    for (int a = 0; a < A; ++a) {
      top = std::max(top, reward_[s * A + a]);
      bottom = std::min(bottom, reward_[s * A + a]);
      if (terminal_[a] && (best_terminal_[s] < 0 || reward_[s * A + a] > best_commit_[s]))
        best_commit_[s] = reward_[s * A + a], best_terminal_[s] = a;
    }
  }
  // Halving steps from half the reward span: committing with a loss of half the span down to about
  // a thousandth of it (on the seed's problem, P(wrong group) from 0.5 to 0.0005).
  const double span = std::max(top - bottom, 1e-9);
  thresholds_.push_back(std::numeric_limits<double>::infinity());
  for (int k = 1; k < kThresholds; ++k) thresholds_.push_back(span * std::ldexp(1.0, -k));
  scratch_.resize(S);
  scratch2_.resize(S);
  groups_.resize(A);
}

double SensingPolicy::update(const std::vector<double>& belief, int a, int o,
                             std::vector<double>& out) const {
  const int S = num_states_;
  out.resize(S);
  const double* e = &emission_[static_cast<std::size_t>(a * num_observations_ + o) * S];
  double total = 0.0;
  for (int s = 0; s < S; ++s) total += out[s] = belief[s] * e[s];
  if (total > 0.0)
    for (double& p : out) p /= total;
  return total;
}

double SensingPolicy::observation_probability(const std::vector<double>& belief, int a,
                                              int o) const {
  const int S = num_states_;
  const double* e = &emission_[static_cast<std::size_t>(a * num_observations_ + o) * S];
  double p = 0.0;
  for (int s = 0; s < S; ++s) p += belief[s] * e[s];
  return p;
}

double SensingPolicy::live_probability(const std::vector<double>& belief, int a) const {
  double p = 0.0;
  for (int s = 0; s < num_states_; ++s) p += belief[s] * stay_[a * num_states_ + s];
  return p;
}

double SensingPolicy::expected_reward(const std::vector<double>& belief, int a) const {
  double r = 0.0;
  for (int s = 0; s < num_states_; ++s) r += belief[s] * reward_[s * num_actions_ + a];
  return r;
}

double SensingPolicy::commit_value(const std::vector<double>& belief) const {
  double best = -std::numeric_limits<double>::infinity();
  for (int a = 0; a < num_actions_; ++a)
    if (terminal_[a]) best = std::max(best, expected_reward(belief, a));
  return best;
}

double SensingPolicy::loss(const std::vector<double>& belief) const {
  double known = 0.0;
  for (int s = 0; s < num_states_; ++s) known += belief[s] * best_commit_[s];
  return known - commit_value(belief);
}

double SensingPolicy::decision_entropy(const std::vector<double>& belief) const {
  std::fill(groups_.begin(), groups_.end(), 0.0);
  for (int s = 0; s < num_states_; ++s)
    if (best_terminal_[s] >= 0) groups_[best_terminal_[s]] += belief[s];
  double h = 0.0;
  for (double p : groups_)
    if (p > 0.0) h -= p * std::log(p);
  return h;
}

int SensingPolicy::choose_sensing(const std::vector<double>& belief) const {
  int best = sensing_.front();
  double best_score = std::numeric_limits<double>::infinity();
  for (int a : sensing_) {
    // Expected decision entropy after hearing a's outcome (outcomes that end the episode count 0).
    double expected = 0.0;
    for (int o = 0; o < num_observations_; ++o) {
      const double p = update(belief, a, o, scratch2_);
      if (p > 0.0) expected += p * decision_entropy(scratch2_);
    }
    if (expected < best_score - 1e-12) best = a, best_score = expected;
  }
  return best;
}

void SensingPolicy::rollout(const std::vector<double>& start, int steps, Rng& rng,
                            double* returns) const {
  const int S = num_states_;
  std::vector<double> belief(start), next(S);
  // The true state, drawn from the belief.
  int state = 0;
  {
    double u = uniform01(rng), acc = 0.0;
    state = -1;
    for (int s = 0; s < S; ++s)
      if (belief[s] > 0.0) {
        state = s;
        if ((acc += belief[s]) > u) break;
      }
  }
  double collected = 0.0, weight = 1.0;
  int stopped = 0;  // thresholds_[0..stopped) have committed (they are in decreasing order)
  for (int step = 0;; ++step) {
    const double commit = commit_value(belief);
    const double l = step < steps ? loss(belief) : -std::numeric_limits<double>::infinity();
    while (stopped < kThresholds && l <= thresholds_[stopped])
      returns[stopped++] += collected + weight * commit;
    if (stopped == kThresholds) return;
    const int a = choose_sensing(belief);
    collected += weight * expected_reward(belief, a);
    weight *= discount_;
    if (uniform01(rng) >= stay_[a * S + state]) break;  // the action ended the episode
    // The observation, from the true state's row.
    const double stay = stay_[a * S + state];
    double u = uniform01(rng) * stay, acc = 0.0;
    int heard = num_observations_ - 1;
    for (int o = 0; o < num_observations_; ++o)
      if ((acc += emission_[(a * num_observations_ + o) * S + state]) > u) {
        heard = o;
        break;
      }
    if (update(belief, a, heard, next) <= 0.0) break;
    belief.swap(next);
  }
  // Ended by a collision: nothing more is collected whatever the threshold.
  while (stopped < kThresholds) returns[stopped++] += collected;
}

}  // namespace echoplan::solvers
