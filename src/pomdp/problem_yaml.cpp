// Reading YAML object-identification problems (format: docs/problems.md). Writing them:
// problem_yaml_writer.cpp; choosing the reader by file type: load_problem.cpp.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "common/error.h"
#include "common/yaml_reader.h"
#include "pomdp/distribution.h"
#include "pomdp/problem.h"

namespace echoplan::pomdp {

namespace {

// Index of `name` in `list`, or an error at `node` listing the known names.
int index_of(const YamlReader& f, const YAML::Node& node, const std::vector<std::string>& list,
             const std::string& name, const std::string& kind) {
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (list[i] == name) return static_cast<int>(i);
  }
  std::string known;
  for (const auto& n : list) known += (known.empty() ? "" : ", ") + n;
  f.fail(node, "unknown " + kind + " '" + name + "' (known: " + known + ")");
}

// A `type:` key that must be one of the kinds this version supports.
void check_type(const YamlReader& f, const YAML::Node& section, const std::string& what,
                const std::string& expected) {
  const YAML::Node t = f.require(section, "type", what);
  const std::string got = f.name(t, what + ".type");
  if (got != expected)
    f.fail(t, "unsupported " + what + ".type '" + got + "' (supported: " + expected + ")");
}

// A probability row: entries in [0, 1] summing to 1 within kProbabilityTolerance.
std::vector<double> probability_row(const YamlReader& f, const YAML::Node& node, std::size_t size,
                                    const std::string& what) {
  std::vector<double> row = f.numbers(node, what);
  if (row.size() != size) {
    f.fail(node, what + " has " + std::to_string(row.size()) + " entries, expected " +
                     std::to_string(size) + " (one per observation symbol)");
  }
  const RowCheck check = check_row(row.data(), row.size());
  if (!check.in_range) f.fail(node, what + " has a probability outside [0, 1]");
  if (!check.ok()) {
    std::ostringstream msg;
    msg << what << " sums to " << std::setprecision(10) << check.sum << ", not 1 (tolerance 1e-6)";
    f.fail(node, msg.str());
  }
  return row;
}

template <std::size_t N>
std::array<double, N> fixed_vector(const YamlReader& f, const YAML::Node& node,
                                   const std::string& what) {
  const std::vector<double> v = f.numbers(node, what, N);
  std::array<double, N> out{};
  std::copy(v.begin(), v.end(), out.begin());
  return out;
}

void read_initial_belief(const YamlReader& f, const YAML::Node& root, ObjectProblemData& d) {
  const YAML::Node ib = f.require(root, "initial_belief", "the problem");
  f.only_keys(ib, {"type", "joints", "offset", "objects"}, "initial_belief");
  check_type(f, ib, "initial_belief", "fixed_configuration");
  d.initial_joints =
      fixed_vector<7>(f, f.require(ib, "joints", "initial_belief"), "initial_belief.joints");
  d.initial_offset =
      fixed_vector<3>(f, f.require(ib, "offset", "initial_belief"), "initial_belief.offset");
  const YAML::Node objects = f.optional(ib, "objects", "initial_belief");
  const std::size_t k = d.objects.size();
  if (!objects.IsDefined() || (objects.IsScalar() && objects.Scalar() == "uniform")) {
    d.prior.assign(k, 1.0 / static_cast<double>(k));
    return;
  }
  if (!objects.IsMap())
    f.fail(objects, "initial_belief.objects must be 'uniform' or a map object: weight");
  d.prior.assign(k, 0.0);
  double total = 0.0;
  for (auto it = objects.begin(); it != objects.end(); ++it) {
    const int i = index_of(f, it->first, d.objects, f.name(it->first, "object name"), "object");
    const double w = f.number(it->second, "weight of " + d.objects[i]);
    if (w < 0.0) f.fail(it->second, "weight of " + d.objects[i] + " must not be negative");
    d.prior[i] = w;
    total += w;
  }
  if (total <= 0.0) f.fail(objects, "initial_belief.objects weights must not all be zero");
  for (double& p : d.prior) p /= total;
}

void read_transition(const YamlReader& f, const YAML::Node& root, ObjectProblemData& d) {
  const YAML::Node t = f.require(root, "transition", "the problem");
  f.only_keys(t, {"type", "offset_change", "collision_probability"}, "transition");
  check_type(f, t, "transition", "kinematic");
  std::vector<std::string> sensing_names;
  for (const auto& a : d.sensing) sensing_names.push_back(a.name);
  if (const YAML::Node oc = f.optional(t, "offset_change", "transition"); oc.IsDefined()) {
    f.expect_map(oc, "transition.offset_change");
    for (auto it = oc.begin(); it != oc.end(); ++it) {
      const int a =
          index_of(f, it->first, sensing_names, f.name(it->first, "action"), "sensing action");
      d.sensing[a].offset_change =
          fixed_vector<3>(f, it->second, "offset_change of " + sensing_names[a]);
    }
  }
  if (const YAML::Node cp = f.optional(t, "collision_probability", "transition"); cp.IsDefined()) {
    f.expect_map(cp, "transition.collision_probability");
    for (auto it = cp.begin(); it != cp.end(); ++it) {
      const int a =
          index_of(f, it->first, sensing_names, f.name(it->first, "action"), "sensing action");
      const double p = f.number(it->second, "collision probability of " + sensing_names[a]);
      if (p < 0.0 || p > 1.0) f.fail(it->second, "collision probability must be in [0, 1]");
      d.sensing[a].collision_probability = p;
    }
  }
}

// `actions.uses`: a map `sensing action: N` (N >= 1) of per-episode use limits; unlisted actions
// have none (SensingAction::uses = 0).
void read_use_limits(const YamlReader& f, const YAML::Node& actions, ObjectProblemData& d) {
  const YAML::Node uses = f.optional(actions, "uses", "actions");
  if (!uses.IsDefined()) return;
  f.expect_map(uses, "actions.uses");
  std::vector<std::string> sensing_names;
  for (const auto& a : d.sensing) sensing_names.push_back(a.name);
  for (auto it = uses.begin(); it != uses.end(); ++it) {
    const int a =
        index_of(f, it->first, sensing_names, f.name(it->first, "action"), "sensing action");
    const std::string what = "use limit of " + sensing_names[a];
    const int n = f.non_negative_int(it->second, what);
    if (n == 0) f.fail(it->second, what + " must be a positive integer (leave it out: no limit)");
    d.sensing[a].uses = n;
  }
}

// `actions.requires`: a map `sensing action: [sensing action...]`: each listed action must have
// been performed at least once before the key's action is available (SensingAction::
// prerequisites). A sorting action, the action itself, a repeat, or a circle of requirements (which
// no episode could ever enter) is an error at its line.
void read_prerequisites(const YamlReader& f, const YAML::Node& actions, ObjectProblemData& d) {
  const YAML::Node requires_map = f.optional(actions, "requires", "actions");
  if (!requires_map.IsDefined()) return;
  f.expect_map(requires_map, "actions.requires");
  std::vector<std::string> sensing_names;
  for (const auto& a : d.sensing) sensing_names.push_back(a.name);
  std::vector<YAML::Node> where(d.sensing.size());
  for (auto it = requires_map.begin(); it != requires_map.end(); ++it) {
    const int a =
        index_of(f, it->first, sensing_names, f.name(it->first, "action"), "sensing action");
    const std::string what = "actions.requires of " + sensing_names[a];
    // A copy: the iterator's pair is a temporary, and a range-for over its member would outlive it.
    const YAML::Node required = it->second;
    if (!required.IsSequence()) f.fail(required, what + " must be a list of sensing actions");
    for (const YAML::Node& item : required) {
      const int r = index_of(f, item, sensing_names, f.name(item, "action"), "sensing action");
      if (r == a) f.fail(item, sensing_names[a] + " cannot require itself");
      auto& list = d.sensing[a].prerequisites;
      if (std::find(list.begin(), list.end(), r) != list.end())
        f.fail(item, sensing_names[r] + " is listed twice in " + what);
      list.push_back(r);
    }
    where[a] = it->first;
  }
  const std::vector<int> cycle = prerequisite_cycle(d.sensing);
  if (cycle.empty()) return;
  std::string chain;
  for (int a : cycle) chain += (chain.empty() ? "" : " -> ") + sensing_names[a];
  f.fail(where[cycle.front()], "actions.requires goes round in a circle (" + chain +
                                   "): none of them could ever be done");
}

void read_observation(const YamlReader& f, const YAML::Node& root, ObjectProblemData& d) {
  const YAML::Node o = f.require(root, "observation", "the problem");
  f.only_keys(o, {"type", "symbols", "table"}, "observation");
  check_type(f, o, "observation", "table");
  const YAML::Node symbols = f.optional(o, "symbols", "observation");
  d.observation_symbols = symbols.IsDefined() ? f.names(symbols, "observation.symbols") : d.objects;
  for (std::size_t i = 0; i < d.observation_symbols.size(); ++i) {
    if (d.observation_symbols[i] == "none") {
      f.fail(symbols, "observation symbol 'none' is reserved for 'nothing heard'");
    }
  }
  const YAML::Node table = f.require(o, "table", "observation");
  f.expect_map(table, "observation.table");
  std::vector<std::string> sensing_names;
  for (const auto& a : d.sensing) sensing_names.push_back(a.name);
  d.observation_table.assign(d.sensing.size(), std::vector<std::vector<double>>(d.objects.size()));
  std::vector<std::vector<bool>> seen(d.sensing.size(), std::vector<bool>(d.objects.size(), false));
  for (auto it = table.begin(); it != table.end(); ++it) {
    const int a =
        index_of(f, it->first, sensing_names, f.name(it->first, "action"), "sensing action");
    f.expect_map(it->second, "observation.table." + sensing_names[a]);
    for (auto jt = it->second.begin(); jt != it->second.end(); ++jt) {
      const int k = index_of(f, jt->first, d.objects, f.name(jt->first, "object"), "object");
      const std::string what = "observation row (" + sensing_names[a] + ", " + d.objects[k] + ")";
      d.observation_table[a][k] =
          probability_row(f, jt->second, d.observation_symbols.size(), what);
      seen[a][k] = true;
    }
  }
  for (std::size_t a = 0; a < d.sensing.size(); ++a) {
    for (std::size_t k = 0; k < d.objects.size(); ++k) {
      if (!seen[a][k]) {
        f.fail(table, "missing observation row for action '" + sensing_names[a] + "' and object '" +
                          d.objects[k] + "' in observation.table");
      }
    }
  }
}

// Every key of `map` must name an entry of `list` (catches misspelt action and object names).
void keys_must_name(const YamlReader& f, const YAML::Node& map,
                    const std::vector<std::string>& list, const std::string& kind) {
  for (auto it = map.begin(); it != map.end(); ++it)
    index_of(f, it->first, list, f.name(it->first, kind), kind);
}

void read_reward(const YamlReader& f, const YAML::Node& root, ObjectProblemData& d) {
  const YAML::Node r = f.require(root, "reward", "the problem");
  f.only_keys(r, {"sensing", "sorting", "collision"}, "reward");
  std::vector<std::string> sensing_names;
  for (const auto& a : d.sensing) sensing_names.push_back(a.name);

  const YAML::Node sensing = f.require(r, "sensing", "reward");
  f.expect_map(sensing, "reward.sensing");
  keys_must_name(f, sensing, sensing_names, "sensing action");
  for (auto& a : d.sensing) {
    a.reward = f.number(f.require(sensing, a.name, "reward.sensing"), "reward of " + a.name);
  }

  const YAML::Node sorting = f.require(r, "sorting", "reward");
  f.expect_map(sorting, "reward.sorting");
  keys_must_name(f, sorting, d.sorting, "sorting action");
  d.sorting_reward.assign(d.sorting.size(), std::vector<double>(d.objects.size(), 0.0));
  for (std::size_t j = 0; j < d.sorting.size(); ++j) {
    const YAML::Node row = f.require(sorting, d.sorting[j], "reward.sorting");
    f.expect_map(row, "reward.sorting." + d.sorting[j]);
    keys_must_name(f, row, d.objects, "object");
    for (std::size_t k = 0; k < d.objects.size(); ++k) {
      d.sorting_reward[j][k] =
          f.number(f.require(row, d.objects[k], "reward.sorting." + d.sorting[j]),
                   "reward of " + d.sorting[j] + " for " + d.objects[k]);
    }
  }
  if (const YAML::Node c = f.optional(r, "collision", "reward"); c.IsDefined()) {
    d.collision_reward = f.number(c, "reward.collision");
  }
}

BeliefSettings read_belief(const YamlReader& f, const YAML::Node& root) {
  BeliefSettings b;
  const YAML::Node node = f.optional(root, "belief", "the problem");
  if (!node.IsDefined()) return b;
  f.only_keys(node, {"type", "particles"}, "belief");
  const YAML::Node type = f.require(node, "type", "belief");
  const std::string t = f.name(type, "belief.type");
  if (t == "particle") {
    b.type = BeliefSettings::Type::particle;
  } else if (t == "exact") {
    b.type = BeliefSettings::Type::exact;
  } else {
    f.fail(type, "unknown belief.type '" + t + "' (expected particle or exact)");
  }
  if (const YAML::Node n = f.optional(node, "particles", "belief"); n.IsDefined()) {
    b.particles = f.non_negative_int(n, "belief.particles");
    if (b.particles == 0) f.fail(n, "belief.particles must be at least 1");
    // Each particle is a full state; past this the belief would not fit in memory.
    if (b.particles > 10'000'000) f.fail(n, "belief.particles must be at most 10000000");
  }
  return b;
}

PlannerDefaults read_planner(const YamlReader& f, const YAML::Node& root) {
  PlannerDefaults p;
  const YAML::Node node = f.optional(root, "planner", "the problem");
  if (!node.IsDefined()) return p;
  f.only_keys(node, {"solver", "budget", "depth", "exploration"}, "planner");
  if (const YAML::Node s = f.optional(node, "solver", "planner"); s.IsDefined()) {
    p.solver = f.name(s, "planner.solver");
    if (p.solver != "abt" && p.solver != "pomcp" && p.solver != "offline") {
      f.fail(s, "unknown planner.solver '" + p.solver + "' (expected abt, pomcp or offline)");
    }
  }
  if (const YAML::Node b = f.optional(node, "budget", "planner"); b.IsDefined()) {
    f.only_keys(b, {"episodes", "step_ms"}, "planner.budget");
    const YAML::Node e = f.optional(b, "episodes", "planner.budget");
    const YAML::Node ms = f.optional(b, "step_ms", "planner.budget");
    if (e.IsDefined() == ms.IsDefined())
      f.fail(b, "planner.budget needs exactly one of episodes or step_ms");
    if (e.IsDefined()) {
      p.episodes = f.non_negative_int(e, "planner.budget.episodes");
      if (p.episodes == 0) f.fail(e, "planner.budget.episodes must be at least 1");
      p.step_ms = 0.0;
    } else {
      p.step_ms = f.number(ms, "planner.budget.step_ms");
      if (p.step_ms <= 0.0) f.fail(ms, "planner.budget.step_ms must be positive");
      p.episodes = 0;
    }
  }
  if (const YAML::Node dn = f.optional(node, "depth", "planner"); dn.IsDefined()) {
    p.depth = f.non_negative_int(dn, "planner.depth");
    if (p.depth == 0) f.fail(dn, "planner.depth must be at least 1");
  }
  if (const YAML::Node c = f.optional(node, "exploration", "planner"); c.IsDefined()) {
    p.exploration = f.number(c, "planner.exploration");
    if (p.exploration < 0.0) f.fail(c, "planner.exploration must not be negative");
  }
  return p;
}

Problem read_problem(const YamlReader& f, const YAML::Node& root) {
  if (!root.IsDefined() || root.IsNull()) {
    throw InputError(f.file(), 1,
                     "the file is empty; expected a YAML problem (see docs/problems.md)");
  }
  if (!root.IsMap()) f.fail(root, "expected a YAML mapping of problem keys (see docs/problems.md)");
  f.reject_duplicate_keys(root);
  f.only_keys(root,
              {"name", "discount", "objects", "actions", "initial_belief", "transition",
               "observation", "reward", "terminal", "heuristic", "belief", "planner"},
              "the problem");
  ObjectProblemData d;
  d.name = f.name(f.require(root, "name", "the problem"), "name");
  const YAML::Node discount = f.require(root, "discount", "the problem");
  d.discount = f.number(discount, "discount");
  if (!(d.discount > 0.0 && d.discount < 1.0)) f.fail(discount, "discount must be in (0, 1)");
  d.objects = f.names(f.require(root, "objects", "the problem"), "objects");

  const YAML::Node actions = f.require(root, "actions", "the problem");
  f.only_keys(actions, {"sensing", "sorting", "uses", "requires"}, "actions");
  for (const auto& n : f.names(f.require(actions, "sensing", "actions"), "actions.sensing")) {
    d.sensing.push_back(SensingAction{n});
  }
  d.sorting = f.names(f.require(actions, "sorting", "actions"), "actions.sorting");
  for (const auto& a : d.sensing) {
    for (const auto& s : d.sorting) {
      if (a.name == s) f.fail(actions, "action '" + s + "' is both a sensing and a sorting action");
    }
  }
  read_use_limits(f, actions, d);
  read_prerequisites(f, actions, d);

  read_initial_belief(f, root, d);
  read_transition(f, root, d);
  read_observation(f, root, d);
  read_reward(f, root, d);
  // Terminal and heuristic are parts a problem composes; this version has one kind of each.
  const YAML::Node terminal = f.require(root, "terminal", "the problem");
  f.only_keys(terminal, {"type"}, "terminal");
  check_type(f, terminal, "terminal", "sorting_or_collision");
  const YAML::Node heuristic = f.require(root, "heuristic", "the problem");
  f.only_keys(heuristic, {"type"}, "heuristic");
  check_type(f, heuristic, "heuristic", "known_object");

  Problem p;
  p.belief = read_belief(f, root);
  p.planner = read_planner(f, root);
  p.model = std::make_shared<const ObjectIdentificationModel>(std::move(d));
  p.source_path = f.file();
  return p;
}

}  // namespace

Problem parse_problem_yaml(const std::string& text, const std::string& source_name) {
  const YAML::Node root = parse_yaml(text, source_name);
  return read_yaml_guarded(source_name,
                           [&] { return read_problem(YamlReader(source_name), root); });
}

}  // namespace echoplan::pomdp
