#include "solvers/use_limits.h"

#include <algorithm>
#include <stdexcept>

namespace echoplan::solvers {

UseLimits::UseLimits(std::vector<int> max_uses, std::vector<std::vector<int>> prerequisites) {
  for (int m : max_uses)
    if (m < 0) throw std::invalid_argument("a use limit must be >= 0 (0: no limit)");
  const int actions = static_cast<int>(max_uses.size());
  if (!prerequisites.empty() && static_cast<int>(prerequisites.size()) != actions)
    throw std::invalid_argument("prerequisites need one list per action");
  bool gated = false;
  for (const auto& list : prerequisites) {
    for (int r : list)
      if (r < 0 || r >= actions) throw std::invalid_argument("a prerequisite must be an action");
    gated = gated || !list.empty();
  }
  const bool limited = std::any_of(max_uses.begin(), max_uses.end(), [](int m) { return m > 0; });
  if (!limited && !gated) return;
  max_uses_ = std::move(max_uses);
  if (gated) prerequisites_ = std::move(prerequisites);
}

namespace {
std::vector<int> limits_of(const pomdp::Model& model) {
  std::vector<int> limits(model.num_actions(), 0);
  for (int a = 0; a < model.num_actions(); ++a) limits[a] = model.max_uses(a);
  return limits;
}

std::vector<std::vector<int>> prerequisites_of(const pomdp::Model& model) {
  std::vector<std::vector<int>> lists(model.num_actions());
  for (int a = 0; a < model.num_actions(); ++a) lists[a] = model.prerequisites(a);
  return lists;
}
}  // namespace

UseLimits::UseLimits(const pomdp::Model& model)
    : UseLimits(limits_of(model), prerequisites_of(model)) {}

}  // namespace echoplan::solvers
