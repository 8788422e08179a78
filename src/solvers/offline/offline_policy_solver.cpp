#include "solvers/offline/offline_policy_solver.h"

#include <limits>

namespace echoplan::solvers::offline {

std::vector<double> OfflinePolicySolver::root_action_values() const {
  std::vector<double> values(num_actions_, std::numeric_limits<double>::quiet_NaN());
  values[policy_.best_action()] = policy_.value();
  return values;
}

}  // namespace echoplan::solvers::offline
