#include "solvers/observation_branch.h"

#include <cmath>
#include <cstddef>

namespace echoplan::solvers {

bool ObservationBranching::same_branch(const pomdp::Observation& representative,
                                       const pomdp::Observation& observation) const {
  // Discrete symbols: identity. A model emits either kind, never both, so the index decides.
  if (representative.index >= 0 || observation.index >= 0)
    return representative.index == observation.index;
  if (representative.values.size() != observation.values.size()) return false;
  double squared = 0.0;
  for (std::size_t i = 0; i < observation.values.size(); ++i) {
    const double d = representative.values[i] - observation.values[i];
    squared += d * d;
  }
  return std::sqrt(squared) <= continuous_threshold;
}

}  // namespace echoplan::solvers
