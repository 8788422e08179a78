#include "pomdp/make_belief.h"

#include "common/error.h"
#include "pomdp/exact_belief.h"
#include "pomdp/particle_belief.h"

namespace echoplan::pomdp {

BeliefPtr make_belief(const Problem& problem, Rng& rng) {
  if (problem.belief.type == BeliefSettings::Type::exact) {
    if (problem.model->tabular() == nullptr) {
      throw InputError(problem.source_path, 0,
                       "belief type 'exact' needs a problem with tables; use 'particle'");
    }
    return std::make_unique<ExactBelief>(problem.model);
  }
  return std::make_unique<ParticleBelief>(problem.model, problem.belief.particles, rng);
}

}  // namespace echoplan::pomdp
