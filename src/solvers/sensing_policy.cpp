#include "solvers/sensing_policy.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"
#include "solvers/identification_solver.h"

namespace echoplan::solvers {

namespace {
// `model`'s identification tables, once identification_shape_problem() has found nothing wrong.
std::shared_ptr<const IdentificationTables> policy_tables(const pomdp::TabularModel& model,
                                                          const UseLimits& limits) {
  if (auto why = identification_shape_problem(model))
    throw InputError(
        "the policy leaf value needs an identification problem (the state stays "
        "fixed until an action ends the episode), and this one is not: " +
        *why);
  return read_identification_tables(model, limits);
}
}  // namespace

SensingPolicy::SensingPolicy(const pomdp::TabularModel& model, const UseLimits& limits)
    : SensingPolicy(policy_tables(model, limits)) {}

SensingPolicy::SensingPolicy(std::shared_ptr<const IdentificationTables> tables)
    : tables_(std::move(tables)) {
  const IdentificationTables& t = *tables_;
  num_states_ = t.states;
  num_actions_ = t.actions;
  num_observations_ = t.observations;
  discount_ = t.discount;
  const int L = t.live_states, A = num_actions_;
  for (int a = 0; a < A; ++a)
    if (!t.terminal[a]) sensing_.push_back(a);
  best_commit_.assign(L, 0.0);
  best_terminal_.assign(L, -1);
  double top = -std::numeric_limits<double>::infinity(), bottom = -top;
  for (int l = 0; l < L; ++l) {
    for (int a = 0; a < A; ++a) {
      const double r = t.reward[a * L + l];
      top = std::max(top, r);
      bottom = std::min(bottom, r);
      if (t.terminal[a] && (best_terminal_[l] < 0 || r > best_commit_[l]))
        best_commit_[l] = r, best_terminal_[l] = a;
    }
  }
  // Halving steps from half the reward span: committing with a loss of half the span down to about
  // a thousandth of it (on the report's problem, P(wrong group) from 0.5 to 0.0005).
  const double span = std::max(top - bottom, 1e-9);
  thresholds_.push_back(std::numeric_limits<double>::infinity());
  for (int k = 1; k < kThresholds; ++k) thresholds_.push_back(span * std::ldexp(1.0, -k));
  scratch_.resize(num_states_);
  scratch2_.resize(num_states_);
  groups_.resize(A);
}

const double* SensingPolicy::emission(int action, int observation) const {
  const int L = tables_->live_states;
  return &tables_->emission[static_cast<std::size_t>(action * num_observations_ + observation) * L];
}

double SensingPolicy::update(const std::vector<double>& belief, int a, int o,
                             std::vector<double>& out) const {
  const std::vector<int>& states = tables_->model_state;
  out.assign(num_states_, 0.0);  // absorbing states keep none
  const double* e = emission(a, o);
  double total = 0.0;
  for (std::size_t l = 0; l < states.size(); ++l)
    total += out[states[l]] = belief[states[l]] * e[l];
  if (total > 0.0)
    for (double& p : out) p /= total;
  return total;
}

double SensingPolicy::observation_probability(const std::vector<double>& belief, int a,
                                              int o) const {
  const std::vector<int>& states = tables_->model_state;
  const double* e = emission(a, o);
  double p = 0.0;
  for (std::size_t l = 0; l < states.size(); ++l) p += belief[states[l]] * e[l];
  return p;
}

double SensingPolicy::live_probability(const std::vector<double>& belief, int a) const {
  const std::vector<int>& states = tables_->model_state;
  const double* stay = &tables_->stay[static_cast<std::size_t>(a) * states.size()];
  double p = 0.0;
  for (std::size_t l = 0; l < states.size(); ++l) p += belief[states[l]] * stay[l];
  return p;
}

double SensingPolicy::expected_reward(const std::vector<double>& belief, int a) const {
  const std::vector<int>& states = tables_->model_state;
  const double* reward = &tables_->reward[static_cast<std::size_t>(a) * states.size()];
  double r = 0.0;
  for (std::size_t l = 0; l < states.size(); ++l) r += belief[states[l]] * reward[l];
  return r;
}

double SensingPolicy::commit_value(const std::vector<double>& belief) const {
  double best = -std::numeric_limits<double>::infinity();
  for (int a = 0; a < num_actions_; ++a)
    if (tables_->terminal[a]) best = std::max(best, expected_reward(belief, a));
  return best;
}

double SensingPolicy::loss(const std::vector<double>& belief) const {
  const std::vector<int>& states = tables_->model_state;
  double known = 0.0;
  for (std::size_t l = 0; l < states.size(); ++l) known += belief[states[l]] * best_commit_[l];
  return known - commit_value(belief);
}

double SensingPolicy::decision_entropy(const std::vector<double>& belief) const {
  const std::vector<int>& states = tables_->model_state;
  std::fill(groups_.begin(), groups_.end(), 0.0);
  for (std::size_t l = 0; l < states.size(); ++l)
    if (best_terminal_[l] >= 0) groups_[best_terminal_[l]] += belief[states[l]];
  double h = 0.0;
  for (double p : groups_)
    if (p > 0.0) h -= p * std::log(p);
  return h;
}

bool SensingPolicy::can_sense(const UseCounts& uses) const {
  for (int a : sensing_)
    if (tables_->limits.allows(uses, a)) return true;
  return false;
}

int SensingPolicy::choose_sensing(const std::vector<double>& belief, const UseCounts& uses) const {
  int best = -1;
  double best_score = std::numeric_limits<double>::infinity();
  for (int a : sensing_) {
    if (!tables_->limits.allows(uses, a)) continue;
    // Expected decision entropy after hearing a's outcome (outcomes that end the episode count 0).
    double expected = 0.0;
    for (int o = 0; o < num_observations_; ++o) {
      const double p = update(belief, a, o, scratch2_);
      if (p > 0.0) expected += p * decision_entropy(scratch2_);
    }
    if (best < 0 || expected < best_score - 1e-12) best = a, best_score = expected;
  }
  return best;
}

void SensingPolicy::rollout(const std::vector<double>& start, const UseCounts& start_uses,
                            int steps, Rng& rng, double* returns) const {
  const std::vector<int>& states = tables_->model_state;
  const int L = tables_->live_states;
  const UseLimits& limits = tables_->limits;
  UseCounts uses = limits.any() ? start_uses : UseCounts{};
  std::vector<double> belief(start), next(num_states_);
  // The true state (its live index), drawn from the belief.
  int state = -1;
  {
    double u = uniform01(rng), acc = 0.0;
    for (int l = 0; l < L; ++l)
      if (belief[states[l]] > 0.0) {
        state = l;
        if ((acc += belief[states[l]]) > u) break;
      }
  }
  double collected = 0.0, weight = 1.0;
  int stopped = 0;  // thresholds_[0..stopped) have committed (they are in decreasing order)
  for (int step = 0;; ++step) {
    const double commit = commit_value(belief);
    // Past the step cap, or with every sensing action used up, every threshold commits now.
    const bool go_on = step < steps && (!limits.any() || can_sense(uses));
    const double l = go_on ? loss(belief) : -std::numeric_limits<double>::infinity();
    while (stopped < kThresholds && l <= thresholds_[stopped])
      returns[stopped++] += collected + weight * commit;
    if (stopped == kThresholds) return;
    const int a = choose_sensing(belief, uses);
    limits.count(uses, a);
    collected += weight * expected_reward(belief, a);
    weight *= discount_;
    const double stay = tables_->stay[a * L + state];
    if (uniform01(rng) >= stay) break;  // the action ended the episode
    // The observation, from the true state's row.
    double u = uniform01(rng) * stay, acc = 0.0;
    int heard = num_observations_ - 1;
    for (int o = 0; o < num_observations_; ++o)
      if ((acc += emission(a, o)[state]) > u) {
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
