#include "pomdp/particle_belief.h"

#include <cmath>
#include <stdexcept>

namespace echoplan::pomdp {

ParticleBelief::ParticleBelief(ModelPtr model, int count, Rng& rng, double fresh_share)
    : model_(std::move(model)), fresh_share_(fresh_share) {
  if (count <= 0) throw std::invalid_argument("ParticleBelief needs at least one particle");
  if (!(fresh_share >= 0.0 && fresh_share <= 1.0))
    throw std::invalid_argument("ParticleBelief: fresh share must be in [0, 1]");
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
  history_.push_back({action, observation});
  bool regular = true;
  if (total > 0.0) {
    const auto fresh = static_cast<std::size_t>(std::ceil(fresh_share_ * static_cast<double>(n)));
    const double fresh_total = fresh > 0 ? draw_fresh(fresh, rng) : 0.0;
    if (fresh_total > 0.0) {
      // Mix the two self-normalised samples of b_t in proportion to their sizes.
      const double main_scale = static_cast<double>(n) / static_cast<double>(n + fresh) / total;
      const double fresh_scale =
          static_cast<double>(fresh) / static_cast<double>(n + fresh) / fresh_total;
      for (std::size_t i = 0; i < n; ++i) weights_[i] *= main_scale;
      for (std::size_t i = n; i < n + fresh; ++i) weights_[i] *= fresh_scale;
      total = 1.0;
    }
  } else {
    regular = false;
    std::vector<State> propagated = proposals_;
    proposals_.clear();
    weights_.clear();
    total = draw_fresh(n, rng);
    if (!(total > 0.0)) {
      // Nothing in the model explains the observation: keep the prediction, ignore the observation.
      proposals_ = std::move(propagated);
      weights_.assign(n, 1.0);
      total = static_cast<double>(n);
    }
  }
  resample(total, rng);
  return regular;
}

double ParticleBelief::draw_fresh(std::size_t count, Rng& rng) {
  double total = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    State s = model_->sample_initial_state(rng);
    double weight = 1.0;
    for (const Step& past : history_) {
      StepResult r = model_->step(s, past.action, rng);
      weight = r.terminal
                   ? 0.0
                   : weight * model_->observation_likelihood(r.next, past.action, past.observation);
      s = std::move(r.next);
      if (!(weight > 0.0)) break;  // cannot come back; the state is never resampled
    }
    proposals_.push_back(std::move(s));
    weights_.push_back(weight > 0.0 ? weight : 0.0);
    total += weights_.back();
  }
  return total;
}

void ParticleBelief::resample(double total, Rng& rng) {
  // Systematic resampling: one uniform offset, n evenly spaced pointers into the cumulative
  // weights of all proposals; lower variance than multinomial draws and O(n + proposals).
  const std::size_t n = particles_.size();
  const std::size_t m = proposals_.size();
  const double step = total / static_cast<double>(n);
  double pointer = uniform01(rng) * step;
  double cumulative = weights_[0];
  std::size_t j = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (pointer >= cumulative && j + 1 < m) cumulative += weights_[++j];
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
