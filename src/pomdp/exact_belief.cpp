#include "pomdp/exact_belief.h"

#include <stdexcept>

#include "pomdp/distribution.h"

namespace echoplan::pomdp {

ExactBelief::ExactBelief(ModelPtr model) : model_(std::move(model)), tabular_(model_->tabular()) {
  if (tabular_ == nullptr)
    throw std::invalid_argument("ExactBelief needs a model with tables (tabular())");
  probabilities_ = tabular_->initial_belief();
  for (int s = 0; s < tabular_->num_states(); ++s)
    representatives_.push_back(model_->tabular_state(s));
}

State ExactBelief::sample(Rng& rng) const {
  const int n = static_cast<int>(probabilities_.size());
  return representatives_[sample_index(probabilities_.data(), n, uniform01(rng))];
}

bool ExactBelief::update(int action, const Observation& observation, Rng& rng) {
  const int n = tabular_->num_states();
  predicted_.assign(n, 0.0);
  for (int s = 0; s < n; ++s) {
    if (probabilities_[s] == 0.0) continue;
    for (int s_next = 0; s_next < n; ++s_next) {
      predicted_[s_next] += probabilities_[s] * tabular_->transition(s, action, s_next);
    }
  }
  const int o = observation.index;
  double total = 0.0;
  if (o >= 0 && o < tabular_->num_observations()) {
    for (int s = 0; s < n; ++s) {
      probabilities_[s] = predicted_[s] * tabular_->observation(action, s, o);
      total += probabilities_[s];
    }
  }
  const bool regular = total > 0.0;
  if (regular) {
    for (double& p : probabilities_) p /= total;
  } else {
    probabilities_ = predicted_;
  }
  // Advance the continuous part of each representative; its tabular identity stays.
  for (int s = 0; s < n; ++s) {
    State& rep = representatives_[s];
    if (rep.continuous.empty() || tabular_->terminal(s)) continue;
    StepResult r = model_->step(rep, action, rng);
    if (!r.terminal) rep.continuous = std::move(r.next.continuous);
  }
  return regular;
}

std::vector<double> ExactBelief::discrete_marginal(int variable) const {
  const auto& values = model_->spec().state.discrete_value_names.at(variable);
  std::vector<double> marginal(values.size(), 0.0);
  double total = 0.0;
  for (std::size_t s = 0; s < probabilities_.size(); ++s) {
    const int v = representatives_[s].discrete.at(variable);
    if (v < 0 || v >= static_cast<int>(values.size())) continue;
    marginal[v] += probabilities_[s];
    total += probabilities_[s];
  }
  if (total > 0.0) {
    for (double& p : marginal) p /= total;
  }
  return marginal;
}

std::unique_ptr<Belief> ExactBelief::clone() const { return std::make_unique<ExactBelief>(*this); }

}  // namespace echoplan::pomdp
