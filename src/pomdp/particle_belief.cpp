#include "pomdp/particle_belief.h"

#include <stdexcept>

namespace echoplan::pomdp {

ParticleBelief::ParticleBelief(ModelPtr model, int count, Rng& rng) : model_(std::move(model)) {
  if (count <= 0) throw std::invalid_argument("ParticleBelief needs at least one particle");
  particles_.reserve(count);
  for (int i = 0; i < count; ++i) particles_.push_back(model_->sample_initial_state(rng));
}

ParticleBelief::ParticleBelief(ModelPtr model, std::vector<State> particles)
    : model_(std::move(model)), particles_(std::move(particles)) {
  if (particles_.empty()) throw std::invalid_argument("ParticleBelief needs at least one particle");
}

State ParticleBelief::sample(Rng& rng) const {
  const auto n = particles_.size();
  auto i = static_cast<std::size_t>(uniform01(rng) * static_cast<double>(n));
  return particles_[i < n ? i : n - 1];
}

bool ParticleBelief::update(int action, const Observation& observation, Rng& rng) {
  const std::size_t n = particles_.size();
  proposals_.resize(n);
  weights_.resize(n);
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    StepResult r = model_->step(particles_[i], action, rng);
    weights_[i] = r.terminal ? 0.0 : model_->observation_likelihood(r.next, action, observation);
    proposals_[i] = std::move(r.next);
    total += weights_[i];
  }
  bool regular = true;
  if (!(total > 0.0)) {
    regular = false;
    std::vector<State> propagated = proposals_;
    total = reinvigorate(action, observation, rng);
    if (!(total > 0.0)) {
      // Nothing in the model explains the observation: keep the prediction, ignore the observation.
      proposals_ = std::move(propagated);
      weights_.assign(n, 1.0);
      total = static_cast<double>(n);
    }
  }
  resample(total, rng);
  history_.push_back(action);
  return regular;
}

double ParticleBelief::reinvigorate(int action, const Observation& observation, Rng& rng) {
  const std::size_t n = particles_.size();
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    State s = model_->sample_initial_state(rng);
    bool ended = false;
    for (int past : history_) {
      StepResult r = model_->step(s, past, rng);
      ended = r.terminal;
      s = std::move(r.next);
      if (ended) break;
    }
    StepResult r = model_->step(s, action, rng);
    weights_[i] =
        (ended || r.terminal) ? 0.0 : model_->observation_likelihood(r.next, action, observation);
    proposals_[i] = std::move(r.next);
    total += weights_[i];
  }
  return total;
}

void ParticleBelief::resample(double total, Rng& rng) {
  // Systematic resampling: one uniform offset, N evenly spaced pointers into the cumulative
  // weights; lower variance than multinomial draws and O(N).
  const std::size_t n = particles_.size();
  const double step = total / static_cast<double>(n);
  double pointer = uniform01(rng) * step;
  double cumulative = weights_[0];
  std::size_t j = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (pointer >= cumulative && j + 1 < n) cumulative += weights_[++j];
    particles_[i] = proposals_[j];
    pointer += step;
  }
}

std::vector<int> ParticleBelief::particle_counts(int variable) const {
  const auto& values = model_->spec().state.discrete_value_names.at(variable);
  std::vector<int> counts(values.size(), 0);
  for (const State& s : particles_) {
    const int v = s.discrete[variable];
    if (v >= 0 && v < static_cast<int>(counts.size())) ++counts[v];
  }
  return counts;
}

std::vector<double> ParticleBelief::discrete_marginal(int variable) const {
  const std::vector<int> counts = particle_counts(variable);
  int total = 0;
  for (int c : counts) total += c;
  std::vector<double> p(counts.size(), 0.0);
  for (std::size_t i = 0; i < counts.size(); ++i)
    p[i] = total > 0 ? counts[i] / static_cast<double>(total) : 0.0;
  return p;
}

std::unique_ptr<Belief> ParticleBelief::clone() const {
  return std::make_unique<ParticleBelief>(*this);
}

}  // namespace echoplan::pomdp
