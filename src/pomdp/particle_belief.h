// A belief as a set of equally weighted state samples, updated by sequential importance
// resampling (SIR), as the report's OPPT setup did with 1000 particles.
//
// update(a, o): every particle is propagated with the model's step for `a`, weighted by
// P(o | s', a), and the set is resampled back to its size with systematic resampling. Particles
// whose step ended the episode (a collision) get weight 0: the real episode went on.
//
// Depletion. SIR with N particles loses a state for good once resampling drops its last copy
// (after a run of observations that speak against it), however strongly later evidence favours
// it. So every update also draws `fresh` particles from the initial belief, replays them through
// every (action, observation) since then (deterministic effects such as slides are applied) and
// weights each by the likelihood of the *whole* observation history, P(o_1..o_t | s). Those are
// an importance sample of the same posterior b_t as the propagated set, independent of what the
// set has lost; the two self-normalised samples are mixed in proportion to their sizes
// (n : fresh) and resampled back to n. A state dropped from the set therefore returns with about
// fresh/(n+fresh) of its exact posterior probability at every step, and grows from there as the
// evidence keeps favouring it. fresh = ceil(fresh_share * n); share 0 turns this off.
//
// When no propagated particle explains the observation (total weight 0), the set is rebuilt from
// n fresh particles weighted the same way (reinvigoration). If even that finds nothing (the
// observation is impossible under the model), the propagated particles are kept unweighted, i.e.
// the observation is ignored. Either recovery makes update() return false. The belief never
// empties.
#pragma once

#include <vector>

#include "pomdp/belief.h"

namespace echoplan::pomdp {

class ParticleBelief final : public Belief {
 public:
  // Share of fresh particles drawn at every update (see above): 5% costs 0.05 * n * t model steps
  // at step t and brings a lost state back within a few informative observations.
  static constexpr double kDefaultFreshShare = 0.05;

  // `count` (> 0) particles drawn from the model's initial belief; `fresh_share` in [0, 1].
  ParticleBelief(ModelPtr model, int count, Rng& rng, double fresh_share = kDefaultFreshShare);
  // The given particles (non-empty), e.g. a solver's belief node. Their history is unknown, so no
  // fresh particles are mixed in at regular updates (the initial belief is not this belief's
  // origin); when nothing explains an observation, reinvigoration replays only the updates made
  // since construction.
  ParticleBelief(ModelPtr model, std::vector<State> particles);

  State sample(Rng& rng) const override;
  bool update(int action, const Observation& observation, Rng& rng) override;
  std::vector<double> discrete_marginal(int variable) const override;
  std::unique_ptr<Belief> clone() const override;

  // How many particles hold each value of discrete variable `variable` (e.g. per object: the
  // columns of the report's Table 5.2). Length = number of values the model names; sums to size().
  std::vector<int> particle_counts(int variable) const;
  const std::vector<State>& particles() const { return particles_; }
  int size() const { return static_cast<int>(particles_.size()); }

 private:
  struct Step {
    int action;
    Observation observation;
  };
  // Appends `count` fresh draws from the initial belief, replayed through history_ and weighted by
  // the likelihood of all of its observations, to proposals_/weights_; returns their total weight.
  double draw_fresh(std::size_t count, Rng& rng);
  // Systematic resampling of proposals_ by weights_ (total > 0) into particles_ (size unchanged).
  void resample(double total, Rng& rng);

  ModelPtr model_;
  std::vector<State> particles_;
  std::vector<Step> history_;  // every update since the initial belief (or since construction)
  double fresh_share_ = 0.0;
  // Scratch space reused by every update so the steady state does not reallocate.
  std::vector<State> proposals_;
  std::vector<double> weights_;
};

}  // namespace echoplan::pomdp
