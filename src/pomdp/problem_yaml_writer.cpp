// Writing object-identification problems as YAML that parse_problem_yaml() reads back exactly.
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "pomdp/problem.h"

namespace echoplan::pomdp {

namespace {

// Shortest text that reads back to the same double.
std::string exact(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  double back = 0.0;
  for (int digits = 1; digits <= 17; ++digits) {
    std::ostringstream t;
    t << std::setprecision(digits) << v;
    std::istringstream(t.str()) >> back;
    if (back == v) return t.str();
  }
  return s.str();
}

template <class Range>
std::string flow_list(const Range& values) {
  std::string out = "[";
  for (const auto& v : values) out += (out.size() > 1 ? ", " : "") + exact(v);
  return out + "]";
}

}  // namespace

void write_problem_yaml(std::ostream& out, const ObjectProblemData& d, const BeliefSettings& belief,
                        const PlannerDefaults& planner) {
  std::vector<std::string> sensing_names;
  for (const auto& a : d.sensing) sensing_names.push_back(a.name);
  auto names = [](const std::vector<std::string>& v) {
    std::string s = "[";
    for (const auto& n : v) s += (s.size() > 1 ? ", " : "") + n;
    return s + "]";
  };
  out << "name: " << d.name << "\n"
      << "discount: " << exact(d.discount) << "\n"
      << "objects: " << names(d.objects) << "\n"
      << "actions:\n  sensing: " << names(sensing_names) << "\n  sorting: " << names(d.sorting)
      << "\n";
  // Written only when some action has a limit, so problems without limits read as before.
  bool limited = false;
  for (const auto& a : d.sensing) limited = limited || a.uses > 0;
  if (limited) {
    out << "  uses:\n";
    for (const auto& a : d.sensing)
      if (a.uses > 0) out << "    " << a.name << ": " << a.uses << "\n";
  }
  bool gated = false;
  for (const auto& a : d.sensing) gated = gated || !a.prerequisites.empty();
  if (gated) {
    out << "  requires:\n";
    for (const auto& a : d.sensing) {
      if (a.prerequisites.empty()) continue;
      std::vector<std::string> required;
      for (int r : a.prerequisites) required.push_back(d.sensing[r].name);
      out << "    " << a.name << ": " << names(required) << "\n";
    }
  }
  out << "initial_belief:\n  type: fixed_configuration\n"
      << "  joints: " << flow_list(d.initial_joints) << "\n"
      << "  offset: " << flow_list(d.initial_offset) << "\n"
      << "  objects:\n";
  for (std::size_t k = 0; k < d.objects.size(); ++k)
    out << "    " << d.objects[k] << ": " << exact(d.prior[k]) << "\n";
  out << "transition:\n  type: kinematic\n  offset_change:\n";
  for (const auto& a : d.sensing)
    out << "    " << a.name << ": " << flow_list(a.offset_change) << "\n";
  out << "  collision_probability:\n";
  for (const auto& a : d.sensing)
    out << "    " << a.name << ": " << exact(a.collision_probability) << "\n";
  out << "observation:\n  type: table\n  symbols: " << names(d.observation_symbols)
      << "\n  table:\n";
  for (std::size_t a = 0; a < d.sensing.size(); ++a) {
    out << "    " << d.sensing[a].name << ":\n";
    for (std::size_t k = 0; k < d.objects.size(); ++k) {
      out << "      " << d.objects[k] << ": " << flow_list(d.observation_table[a][k]) << "\n";
    }
  }
  out << "reward:\n  sensing:\n";
  for (const auto& a : d.sensing) out << "    " << a.name << ": " << exact(a.reward) << "\n";
  out << "  sorting:\n";
  for (std::size_t j = 0; j < d.sorting.size(); ++j) {
    out << "    " << d.sorting[j] << ":\n";
    for (std::size_t k = 0; k < d.objects.size(); ++k) {
      out << "      " << d.objects[k] << ": " << exact(d.sorting_reward[j][k]) << "\n";
    }
  }
  out << "  collision: " << exact(d.collision_reward) << "\n"
      << "terminal:\n  type: sorting_or_collision\n"
      << "heuristic:\n  type: known_object\n"
      << "belief:\n  type: " << (belief.type == BeliefSettings::Type::exact ? "exact" : "particle")
      << "\n"
      << "  particles: " << belief.particles << "\n"
      << "planner:\n  solver: " << planner.solver << "\n  budget:\n";
  if (planner.episodes > 0) {
    out << "    episodes: " << planner.episodes << "\n";
  } else {
    out << "    step_ms: " << exact(planner.step_ms) << "\n";
  }
  out << "  depth: " << planner.depth << "\n  exploration: " << exact(planner.exploration) << "\n";
}

}  // namespace echoplan::pomdp
