#include "experiment/expected_reward.h"

#include <cstddef>

namespace echoplan::experiment {

std::optional<double> expected_discounted_reward(const std::vector<StepRecord>& steps,
                                                 const pomdp::TabularModel& model) {
  const double gamma = model.discount();
  double total = 0.0, weight = 1.0;
  for (const StepRecord& step : steps) {
    const std::vector<double>& belief = step.belief;
    if (belief.empty() || belief.size() > static_cast<std::size_t>(model.num_states()))
      return std::nullopt;
    double expected = 0.0;
    for (std::size_t s = 0; s < belief.size(); ++s)
      expected += belief[s] * model.reward(static_cast<int>(s), step.action);
    total += weight * expected;
    weight *= gamma;
  }
  return total;
}

}  // namespace echoplan::experiment
