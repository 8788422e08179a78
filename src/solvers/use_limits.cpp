#include "solvers/use_limits.h"

#include <algorithm>
#include <stdexcept>

namespace echoplan::solvers {

UseLimits::UseLimits(std::vector<int> max_uses) {
  for (int m : max_uses)
    if (m < 0) throw std::invalid_argument("a use limit must be >= 0 (0: no limit)");
  if (std::any_of(max_uses.begin(), max_uses.end(), [](int m) { return m > 0; }))
    max_uses_ = std::move(max_uses);
}

namespace {
std::vector<int> limits_of(const pomdp::Model& model) {
  std::vector<int> limits(model.num_actions(), 0);
  for (int a = 0; a < model.num_actions(); ++a) limits[a] = model.max_uses(a);
  return limits;
}
}  // namespace

UseLimits::UseLimits(const pomdp::Model& model) : UseLimits(limits_of(model)) {}

}  // namespace echoplan::solvers
