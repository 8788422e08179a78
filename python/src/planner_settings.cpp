#include "planner_settings.h"

#include <functional>
#include <map>
#include <string>

namespace echoplan::python {

namespace py = pybind11;

solvers::PlannerOverrides planner_overrides(const py::kwargs& settings) {
  solvers::PlannerOverrides o;
  using Setter = std::function<void(py::handle)>;
  const std::map<std::string, Setter> setters{
      {"solver", [&](py::handle v) { o.solver = v.cast<std::string>(); }},
      {"policy", [&](py::handle v) { o.policy = v.cast<std::string>(); }},
      {"episodes", [&](py::handle v) { o.episodes = v.cast<std::int64_t>(); }},
      {"step_ms", [&](py::handle v) { o.step_ms = v.cast<std::int64_t>(); }},
      {"exploration", [&](py::handle v) { o.exploration = v.cast<double>(); }},
      {"depth", [&](py::handle v) { o.depth = v.cast<int>(); }},
      {"leaf", [&](py::handle v) { o.leaf = v.cast<std::string>(); }},
      {"unheard", [&](py::handle v) { o.unheard = v.cast<std::string>(); }},
      {"expand_after", [&](py::handle v) { o.expand_after = v.cast<int>(); }},
      {"exact_share", [&](py::handle v) { o.exact_share = v.cast<double>(); }},
      {"offline_expansions", [&](py::handle v) { o.offline_expansions = v.cast<long>(); }},
      {"root_particles", [&](py::handle v) { o.root_particles = v.cast<int>(); }},
      {"branch_threshold", [&](py::handle v) { o.branch_threshold = v.cast<double>(); }},
  };
  for (const auto& [key, value] : settings) {
    const std::string name = key.cast<std::string>();
    const auto it = setters.find(name);
    if (it == setters.end()) {
      std::string known;
      for (const auto& [k, unused] : setters) known += (known.empty() ? "" : ", ") + k;
      throw py::type_error("unexpected keyword argument '" + name +
                           "' (planner settings: " + known + ")");
    }
    if (!value.is_none()) it->second(value);  // None: keep the problem file's
  }
  return o;
}

const char* planner_settings_doc() {
  return "Planner settings (keywords; left out or None: the problem file's, as the flags of "
         "`echoplan trials`): solver ('abt', 'pomcp', 'offline' or a strategy: all_actions, "
         "best_single, decision_region, information_gain, random), policy (offline: "
         "policy.json), episodes or step_ms (search per step), exploration, depth, leaf ('policy', "
         "'exact', 'exact-offline', 'lookahead', 'heuristic', 'rollout'), unheard ('share' or "
         "'commit'), expand_after, exact_share, offline_expansions, root_particles, "
         "branch_threshold.";
}

}  // namespace echoplan::python
