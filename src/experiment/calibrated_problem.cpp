#include "experiment/calibrated_problem.h"

#include <fmt/format.h>

#include <algorithm>

#include "common/error.h"

namespace echoplan::experiment {

pomdp::ObjectProblemData calibrated_problem(const pomdp::ObjectProblemData& base,
                                            const perception::ObservationModel& model) {
  const std::vector<std::string>& classes = model.classes();
  const std::vector<std::string>& actions = model.actions();
  pomdp::ObjectProblemData out = base;
  out.observation_symbols = model.observation_symbols();
  out.observation_table.clear();
  for (const pomdp::SensingAction& act : base.sensing) {
    if (std::find(actions.begin(), actions.end(), act.name) == actions.end())
      throw InputError(
          fmt::format("problem '{}' has sensing action '{}', but the observation model was "
                      "trained for {} only",
                      base.name, act.name, fmt::join(actions, ", ")));
    const auto& table = model.observation_table(act.name);
    auto& block = out.observation_table.emplace_back();
    for (const std::string& object : base.objects) {
      const auto k = std::find(classes.begin(), classes.end(), object) - classes.begin();
      if (k == static_cast<long>(classes.size()))
        throw InputError(
            fmt::format("problem '{}' has object '{}', but the observation model was trained "
                        "for {} only",
                        base.name, object, fmt::join(classes, ", ")));
      block.push_back(table[k]);
    }
  }
  pomdp::validate_object_problem(out);
  return out;
}

}  // namespace echoplan::experiment
