#include "loop/dataset_problem.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "common/error.h"

namespace echoplan::loop {

namespace {

using Table = std::vector<std::vector<std::vector<double>>>;

// Where `behaviour` is among the data's `actions`; a name the data does not have, given in the
// task's `key`, is a typing mistake, not a setting to ignore.
int behaviour_index(const char* key, const std::string& behaviour,
                    const std::vector<std::string>& actions) {
  const auto it = std::find(actions.begin(), actions.end(), behaviour);
  if (it == actions.end())
    throw InputError(fmt::format("{}: '{}' is not a behaviour of the data (it has: {})", key,
                                 behaviour, fmt::join(actions, ", ")));
  return static_cast<int>(it - actions.begin());
}

void check_costs(const TaskSpec& rewards, const std::vector<std::string>& actions) {
  for (const auto& [behaviour, cost] : rewards.costs) {
    behaviour_index("costs", behaviour, actions);
    if (!(cost >= 0.0) || !std::isfinite(cost))
      throw InputError(fmt::format("costs: the cost of '{}' is {}; a cost is a finite number >= 0",
                                   behaviour, cost));
  }
}

// The prerequisites of task.prerequisites as indices of `actions`, checked (names the data has,
// none of its own, no circle) before pomdp::validate_object_problem would refuse them without
// names.
void set_prerequisites(const TaskSpec& rewards, const std::vector<std::string>& actions,
                       std::vector<pomdp::SensingAction>& sensing) {
  for (const auto& [behaviour, required] : rewards.prerequisites) {
    const int a = behaviour_index("requires", behaviour, actions);
    for (const std::string& first : required) {
      if (first == behaviour)
        throw InputError(fmt::format("requires: '{}' cannot require itself", behaviour));
      sensing[a].prerequisites.push_back(behaviour_index("requires", first, actions));
    }
  }
  const std::vector<int> cycle = pomdp::prerequisite_cycle(sensing);
  if (cycle.empty()) return;
  std::vector<std::string> chain;
  for (int a : cycle) chain.push_back(actions[a]);
  throw InputError(
      fmt::format("requires goes round in a circle ({}): none of them could ever be "
                  "performed",
                  fmt::join(chain, " -> ")));
}

pomdp::ObjectProblemData problem_of(const perception::DatasetTask& task,
                                    const std::vector<std::string>& actions,
                                    std::vector<std::string> symbols, const Table& table,
                                    const TaskSpec& rewards, std::vector<int> uses) {
  if (uses.size() != actions.size())
    throw InputError(fmt::format("{} use limits for {} actions; expected one per action",
                                 uses.size(), actions.size()));
  check_costs(rewards, actions);
  pomdp::ObjectProblemData data;
  data.name = "dataset";
  data.discount = 0.99;
  data.objects = task.classes;
  data.prior.assign(task.classes.size(), 1.0 / static_cast<double>(task.classes.size()));
  for (std::size_t a = 0; a < actions.size(); ++a) {
    if (uses[a] < 0)
      throw InputError(fmt::format("action '{}': use limit {} is negative", actions[a], uses[a]));
    pomdp::SensingAction sensing;
    sensing.name = actions[a];
    sensing.reward = rewards.sensing_reward(actions[a]);
    sensing.uses = uses[a];
    data.sensing.push_back(std::move(sensing));
  }
  set_prerequisites(rewards, actions, data.sensing);
  data.sorting = task.bins;
  for (std::size_t j = 0; j < task.bins.size(); ++j) {
    std::vector<double> row;
    for (int bin : task.bin_of_class)
      row.push_back(bin == static_cast<int>(j) ? rewards.right : rewards.wrong);
    data.sorting_reward.push_back(std::move(row));
  }
  data.observation_symbols = std::move(symbols);
  data.observation_table = table;
  pomdp::validate_object_problem(data);
  return data;
}

// Appends a hidden state for each of the first `classes` objects, named `name_of(class)`, with
// share `rho` of its class's prior; `what` says what the copy is, for the error when its name is
// taken.
void add_copy_states(pomdp::ObjectProblemData& data, std::size_t classes, double rho,
                     std::string (*name_of)(const std::string&), const char* what) {
  for (std::size_t k = 0; k < classes; ++k) {
    const std::string name = name_of(data.objects[k]);
    if (std::find(data.objects.begin(), data.objects.end(), name) != data.objects.end())
      throw InputError(fmt::format("class '{}' is also the name of {} class '{}': rename it", name,
                                   what, data.objects[k]));
    data.objects.push_back(name);
    data.prior.push_back(data.prior[k] * rho);
    data.prior[k] *= 1.0 - rho;
  }
}

// Appends the lookalike copy of every class (dataset_problem.h) with share `rho`: heard through
// its class's rows, sorted as any other class would be.
void add_lookalike_copies(pomdp::ObjectProblemData& data, double rho) {
  const std::size_t classes = data.objects.size();
  add_copy_states(data, classes, rho, lookalike_name, "the lookalike of");
  for (auto& row : data.sorting_reward) {
    double total = 0.0;
    for (std::size_t k = 0; k < classes; ++k) total += row[k];
    for (std::size_t j = 0; j < classes; ++j)
      row.push_back(classes > 1 ? (total - row[j]) / static_cast<double>(classes - 1) : row[j]);
  }
  for (auto& table : data.observation_table) {
    const std::vector<std::vector<double>> of_classes(table.begin(),
                                                      table.begin() + static_cast<long>(classes));
    table.insert(table.end(), of_classes.begin(), of_classes.end());
  }
  pomdp::validate_object_problem(data);
}

}  // namespace

std::string lookalike_name(const std::string& name) { return name + "~lookalike"; }

double TaskSpec::sensing_reward(const std::string& behaviour) const {
  const auto priced = costs.find(behaviour);
  return priced == costs.end() ? sense : -priced->second;
}

pomdp::ObjectProblemData dataset_problem(const perception::DatasetTask& task,
                                         const perception::ObservationModel& model,
                                         const TaskSpec& rewards, std::vector<int> uses,
                                         perception::ObservationKind kind,
                                         std::optional<double> lookalike_share) {
  if (model.classes() != task.classes || model.reject())
    throw InputError(fmt::format(
        "the model's classes ({}{}) are not the task's ({}): a dataset problem needs a model "
        "fitted on sessions for the same classes",
        fmt::join(model.classes(), ", "), model.reject() ? ", unknown" : "",
        fmt::join(task.classes, ", ")));
  const bool lookalikes =
      lookalike_share && *lookalike_share > 0.0 && model.lookalikes_untempered(kind);
  Table table;
  for (const std::string& action : model.actions())
    table.push_back(lookalikes ? model.untempered_table(action, kind)
                               : model.observation_table(action, kind));
  pomdp::ObjectProblemData data = problem_of(task, model.actions(), model.observation_symbols(kind),
                                             table, rewards, std::move(uses));
  if (lookalike_share) add_lookalike_copies(data, *lookalike_share);
  return data;
}

pomdp::ObjectProblemData dataset_problem_shape(const perception::DatasetTask& task,
                                               const perception::FeatureSet& set,
                                               const TaskSpec& rewards, bool lookalike) {
  std::vector<std::string> actions;
  for (const perception::ActionData& action : set.actions) actions.push_back(action.name);
  const std::size_t classes = task.classes.size();
  const Table uniform(actions.size(), std::vector<std::vector<double>>(
                                          classes, std::vector<double>(classes, 1.0 / classes)));
  pomdp::ObjectProblemData data =
      problem_of(task, actions, task.classes, uniform, rewards, default_uses(set));
  if (lookalike) add_lookalike_copies(data, 0.5);
  return data;
}

std::vector<int> default_uses(const perception::FeatureSet& set) {
  std::vector<int> uses;
  for (const perception::ActionData& action : set.actions) {
    std::map<int, int> per_session;
    int most = 0;
    for (const perception::RowLabel& row : action.rows)
      most = std::max(most, ++per_session[row.session]);
    uses.push_back(most);
  }
  return uses;
}

}  // namespace echoplan::loop
