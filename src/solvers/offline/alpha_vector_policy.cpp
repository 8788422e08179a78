#include "solvers/offline/alpha_vector_policy.h"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "solvers/offline/belief_expansion.h"

namespace echoplan::solvers::offline {

AlphaVectorPolicy::AlphaVectorPolicy(std::shared_ptr<const DensePomdp> pomdp,
                                     AlphaVectorSet vectors)
    : pomdp_(std::move(pomdp)), vectors_(std::move(vectors)), belief_(pomdp_->initial_belief) {
  if (vectors_.size() == 0) throw std::invalid_argument("AlphaVectorPolicy needs at least one vector");
  for (const AlphaVector& v : vectors_.vectors()) {
    if (static_cast<int>(v.values.size()) != pomdp_->num_states || v.action < 0 ||
        v.action >= pomdp_->num_actions) {
      throw std::invalid_argument("AlphaVectorPolicy: a vector does not fit the model");
    }
  }
}

void AlphaVectorPolicy::reset(const BeliefVector& belief) {
  if (static_cast<int>(belief.size()) != pomdp_->num_states) {
    throw std::invalid_argument(fmt::format("AlphaVectorPolicy::reset: belief has {} entries for {} states",
                                            belief.size(), pomdp_->num_states));
  }
  belief_ = belief;
}

bool AlphaVectorPolicy::update(int action, int observation) {
  if (action < 0 || action >= pomdp_->num_actions || observation < 0 ||
      observation >= pomdp_->num_observations) {
    throw std::out_of_range(fmt::format("AlphaVectorPolicy::update: action {} or observation {} "
                                        "out of range",
                                        action, observation));
  }
  return bayes_update(*pomdp_, belief_, action, observation);
}

}  // namespace echoplan::solvers::offline
