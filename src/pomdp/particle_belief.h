// A belief as a set of equally weighted state samples, updated by sequential importance
// resampling (SIR), as the report's OPPT setup did with 1000 particles.
//
// update(a, o): every particle is propagated with the model's step for `a`, weighted by
// P(o | s', a), and the set is resampled back to its size with systematic resampling. Particles
// whose step ended the episode (a collision) get weight 0: the real episode went on.
// When no particle explains the observation (total weight 0), the belief is reinvigorated: fresh
// states are drawn from the initial belief, replayed through every action taken so far (so
// deterministic effects such as slides are applied), stepped with `a` and weighted by the
// observation; the set is resampled from those. If even that finds nothing (the observation is
// impossible under the model), the propagated particles are kept unweighted, i.e. the
// observation is ignored. Either recovery makes update() return false. The belief never empties.
#pragma once

#include <vector>

#include "pomdp/belief.h"

namespace echoplan::pomdp {

class ParticleBelief final : public Belief {
 public:
  // `count` (> 0) particles drawn from the model's initial belief.
  ParticleBelief(ModelPtr model, int count, Rng& rng);
  // The given particles (non-empty), e.g. a solver's belief node. The action history starts empty,
  // so reinvigoration replays nothing.
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
  // Reinvigoration: fresh draws replayed through history_ then `action`, weighted by `observation`.
  // Fills proposals_/weights_; returns the total weight.
  double reinvigorate(int action, const Observation& observation, Rng& rng);
  // Systematic resampling of proposals_ by weights_ (total > 0) into particles_.
  void resample(double total, Rng& rng);

  ModelPtr model_;
  std::vector<State> particles_;
  std::vector<int> history_;  // actions taken since the initial belief
  // Scratch space reused by every update so the steady state does not reallocate.
  std::vector<State> proposals_;
  std::vector<double> weights_;
};

}  // namespace echoplan::pomdp
