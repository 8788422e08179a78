#include "loop/calibrated_problem.h"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

#include "common/error.h"
#include "common/file_io.h"
#include "loop/object_problem.h"

namespace echoplan::loop {

pomdp::ObjectProblemData calibrated_problem(const pomdp::ObjectProblemData& base,
                                            const perception::ObservationModel& model,
                                            perception::ObservationKind kind) {
  const std::vector<std::string>& classes = model.classes();
  const std::vector<std::string>& actions = model.actions();
  pomdp::ObjectProblemData out = base;
  out.observation_symbols = model.observation_symbols(kind);
  out.observation_table.clear();
  for (const pomdp::SensingAction& act : base.sensing) {
    if (std::find(actions.begin(), actions.end(), act.name) == actions.end())
      throw InputError(
          fmt::format("problem '{}' has sensing action '{}', but the observation model was "
                      "trained for {} only",
                      base.name, act.name, fmt::join(actions, ", ")));
    const auto& table = model.observation_table(act.name, kind);
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

std::shared_ptr<const pomdp::Problem> calibrate_problem(const pomdp::Problem& base,
                                                        const perception::ObservationModel& model,
                                                        const std::string& source_path,
                                                        perception::ObservationKind kind) {
  auto calibrated = std::make_shared<pomdp::Problem>(base);
  try {
    calibrated->model = std::make_shared<pomdp::ObjectIdentificationModel>(
        calibrated_problem(object_problem(*base.model).data(), model, kind));
  } catch (const InputError& e) {
    throw InputError(base.source_path, 0, e.problem());
  }
  calibrated->source_path = source_path;
  return calibrated;
}

void save_problem(const pomdp::Problem& problem, const std::string& path,
                  const std::string& header) {
  std::ostringstream text;
  text << header;
  pomdp::write_problem_yaml(text, object_problem(*problem.model).data(), problem.belief,
                            problem.planner);
  write_file_atomically(path, text.str());
}

}  // namespace echoplan::loop
