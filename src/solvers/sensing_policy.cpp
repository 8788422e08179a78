#include "solvers/sensing_policy.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"
#include "solvers/entropy_kernels.h"
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
  for (int a = 0; a < A; ++a) (t.terminal[a] ? terminal_ : sensing_).push_back(a);
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
  for (int l = 0; l < L; ++l)
    for (int a : terminal_) terminal_reward_by_state_.push_back(t.reward[a * L + l]);
  commit_sums_.resize(terminal_.size());
  // Halving steps from half the reward span: committing with a loss of half the span down to about
  // a thousandth of it (on the report's problem, P(wrong group) from 0.5 to 0.0005).
  const double span = std::max(top - bottom, 1e-9);
  thresholds_.push_back(std::numeric_limits<double>::infinity());
  for (int k = 1; k < kThresholds; ++k) thresholds_.push_back(span * std::ldexp(1.0, -k));
  scratch2_.resize(num_states_);
  groups_.resize(A);
  // A choice costs a Bayes update and an entropy per sensing action and outcome; below a few
  // thousand of those, the sums rearranged for speed would cost about as much as they save.
  large_ = static_cast<double>(sensing_.size()) * num_observations_ * L >= kLargeAbove;
  if (large_) {
    // The decision groups: the terminal actions, in action order.
    std::vector<int> group_of_action(A, -1);
    for (int a = 0; a < A; ++a)
      if (t.terminal[a]) group_of_action[a] = num_groups_++;
    for (int l = 0; l < L; ++l)
      group_of_live_.push_back(best_terminal_[l] >= 0 ? group_of_action[best_terminal_[l]] : -1);
    live_belief_.resize(L);
    grouped_.resize(static_cast<std::size_t>(num_observations_) * num_groups_);
    totals_.resize(num_observations_);
    // Each sensing action's emissions by state, then outcome.
    const int O = num_observations_;
    sensing_index_.assign(A, -1);
    for (std::size_t i = 0; i < sensing_.size(); ++i) {
      sensing_index_[sensing_[i]] = static_cast<int>(i);
      for (int l = 0; l < L; ++l)
        for (int o = 0; o < O; ++o) emission_by_state_.push_back(emission(sensing_[i], o)[l]);
    }
    // Rows that are mostly one value take the sparse sum (sparse_grouped_entropy.h); a quarter of
    // the outcomes as exceptions is about where it stops paying.
    if (num_groups_ > 0) {
      sparse_ = std::make_unique<SparseGroupedEntropy>(
          emission_by_state_, static_cast<int>(sensing_.size()), L, O, num_groups_, group_of_live_);
      if (sparse_->mean_exceptions() > 0.25 * O)
        sparse_.reset();
      else
        emission_by_state_ = {}, grouped_ = {}, totals_ = {};
      // The lower bound on the expected entropy holds when P(. | s, a) are distributions: no
      // sensing action ends the episode.
      prune_ = std::all_of(sensing_.begin(), sensing_.end(), [&](int a) {
        return std::all_of(&t.stay[static_cast<std::size_t>(a) * L],
                           &t.stay[static_cast<std::size_t>(a + 1) * L],
                           [](double stay) { return stay == 1.0; });
      });
    }
    memoize_ = !sparse_;
  }
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

template <class ValueAfter>
double SensingPolicy::expect_over_outcomes(const std::vector<double>& belief, int a,
                                           ValueAfter value_after) const {
  double expected = 0.0;
  for (int o = 0; o < num_observations_; ++o) {
    const double p = update(belief, a, o, scratch2_);
    if (p > 0.0) expected += p * value_after(scratch2_);
  }
  return expected;
}

double SensingPolicy::commit_after_sensing(const std::vector<double>& belief, int a) const {
  return expect_over_outcomes(belief, a, [this](const auto& after) { return commit_value(after); });
}

SensingPolicy::OutcomeTerm SensingPolicy::commit_after(const std::vector<double>& belief, int a,
                                                       int o) const {
  const double p = update(belief, a, o, scratch2_);
  return {p, p > 0.0 ? p * commit_value(scratch2_) : 0.0};
}

double SensingPolicy::expected_reward(const std::vector<double>& belief, int a) const {
  const std::vector<int>& states = tables_->model_state;
  const double* reward = &tables_->reward[static_cast<std::size_t>(a) * states.size()];
  double r = 0.0;
  for (std::size_t l = 0; l < states.size(); ++l) r += belief[states[l]] * reward[l];
  return r;
}

double SensingPolicy::commit_value(const std::vector<double>& belief) const {
  // expected_reward() of every terminal action at once, state by state: each sum adds the same
  // terms in the same order (a state the belief leaves out adds an exact 0), so bit for bit.
  const std::vector<int>& states = tables_->model_state;
  const std::size_t T = terminal_.size();
  std::fill(commit_sums_.begin(), commit_sums_.end(), 0.0);
  for (std::size_t l = 0; l < states.size(); ++l)
    if (const double b = belief[states[l]]; b != 0.0)
      add_scaled(commit_sums_.data(), b, &terminal_reward_by_state_[l * T], T);
  double best = -std::numeric_limits<double>::infinity();
  for (double r : commit_sums_) best = std::max(best, r);
  return best;
}

double SensingPolicy::loss(const std::vector<double>& belief, double commit) const {
  const std::vector<int>& states = tables_->model_state;
  double known = 0.0;
  for (std::size_t l = 0; l < states.size(); ++l) known += belief[states[l]] * best_commit_[l];
  return known - commit;
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
  if (!memoize_) return choose_sensing_now(belief, uses);
  // The key is the belief's and the uses' exact bits: a hit is the very same question.
  choice_key_.assign(reinterpret_cast<const char*>(belief.data()), belief.size() * sizeof(double));
  choice_key_.append(reinterpret_cast<const char*>(uses.data()), uses.size() * sizeof(uses[0]));
  if (auto it = choices_.find(choice_key_); it != choices_.end()) return it->second;
  if (choices_.size() >= kMaxMemoizedChoices) choices_.clear();
  const int chosen = choose_sensing_now(belief, uses);
  choices_.emplace(choice_key_, chosen);
  return chosen;
}

int SensingPolicy::choose_sensing_now(const std::vector<double>& belief,
                                      const UseCounts& uses) const {
  const std::size_t S = sensing_.size();
  expected_.assign(S, std::numeric_limits<double>::infinity());
  if (large_) {
    const std::vector<int>& states = tables_->model_state;
    for (std::size_t l = 0; l < states.size(); ++l) live_belief_[l] = belief[states[l]];
  }
  if (sparse_) {
    expect_sparse(belief, uses);
  } else {
    for (std::size_t i = 0; i < S; ++i)
      if (const int a = sensing_[i]; tables_->limits.allows(uses, a))
        expected_[i] =
            large_ ? expected_entropy_grouped(a) : expected_entropy_by_outcome(belief, a);
  }
  // The first action, in the problem's order, within the margin of the lowest.
  const double lowest = *std::min_element(expected_.begin(), expected_.end());
  if (lowest == std::numeric_limits<double>::infinity()) return -1;  // none allowed
  for (std::size_t i = 0;; ++i)
    if (expected_[i] <= lowest + kChoiceMargin) return sensing_[i];
}

void SensingPolicy::expect_sparse(const std::vector<double>& belief, const UseCounts& uses) const {
  // The bound: Σ_o P(o) H(decision | o) = H(decision) − I(decision; o) ≥ H(decision) −
  // I(state; o) (the decision is a function of the state), and I(state; o) needs the outcome
  // term the expected entropy needs anyway; what the bound saves is the groups' logs. All three
  // terms scale with the belief's sum, so H(decision) is −Σ_k m_k log m_k on the groups' masses.
  const double decision = decision_entropy(belief);
  sparse_->set_belief(live_belief_.data());
  order_.clear();
  for (std::size_t i = 0; i < sensing_.size(); ++i)
    if (tables_->limits.allows(uses, sensing_[i])) {
      const int index = static_cast<int>(i);
      const double outcome = sparse_->outcome_term(index);
      expected_[i] = outcome;  // the group term is subtracted below, where it is needed
      order_.push_back({prune_ ? decision + outcome - sparse_->state_term(index)
                               : -std::numeric_limits<double>::infinity(),
                        i});
    }
  // In the order of the bounds: once a bound is above the lowest entropy found (by more than the
  // rounding in either), that action cannot be chosen: it counts as not allowed. Before the whole
  // group term, the bound is raised by its slack on the group with the most mass (one group's
  // logs), which settles most of those the bound alone does not.
  std::sort(order_.begin(), order_.end());
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& [bound, i] : order_) {
    if (bound > lowest + kPruneMargin ||
        (prune_ && lowest < std::numeric_limits<double>::infinity() &&
         bound + sparse_->top_group_slack(static_cast<int>(i)) > lowest + kPruneMargin)) {
      expected_[i] = std::numeric_limits<double>::infinity();
      continue;
    }
    expected_[i] -= sparse_->group_term(static_cast<int>(i));
    lowest = std::min(lowest, expected_[i]);
  }
}

double SensingPolicy::expected_entropy_by_outcome(const std::vector<double>& belief, int a) const {
  // Outcomes that end the episode count 0.
  return expect_over_outcomes(belief, a,
                              [this](const auto& after) { return decision_entropy(after); });
}

double SensingPolicy::expected_entropy_grouped(int a) const {
  // With g[k][o] = Σ_{l sorted by k} b(l) e(a, o, l) and T[o] = Σ_k g[k][o] = P(o) (every live
  // state is sorted by some terminal action, when there is one), the entropy after o weighted by
  // P(o) is T[o] H(g[.][o] / T[o]) = T[o] log T[o] − Σ_k g[k][o] log g[k][o]: no normalised
  // belief, every log in a vectorised pass, and the sums run over the outcomes contiguously
  // (emission_by_state_), each state's into its group's row alone.
  const int L = tables_->live_states, O = num_observations_, K = num_groups_;
  std::fill(grouped_.begin(), grouped_.end(), 0.0);
  const auto group = [&](int k) { return &grouped_[static_cast<std::size_t>(k) * O]; };
  const double* e = &emission_by_state_[static_cast<std::size_t>(sensing_index_[a]) * L * O];
  for (int l = 0; l < L; ++l, e += O) {
    const double b = live_belief_[l];
    if (b != 0.0 && group_of_live_[l] >= 0) add_scaled(group(group_of_live_[l]), b, e, O);
  }
  std::fill(totals_.begin(), totals_.end(), 0.0);
  for (int k = 0; k < K; ++k) add_scaled(totals_.data(), 1.0, group(k), O);
  return sum_x_log_x(totals_.data(), O) -
         sum_x_log_x(grouped_.data(), static_cast<std::size_t>(K) * O);
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
    const double l = go_on ? loss(belief, commit) : -std::numeric_limits<double>::infinity();
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
