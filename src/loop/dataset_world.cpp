#include "loop/dataset_world.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>

#include "common/error.h"

namespace echoplan::loop {

namespace {

int data_action_index(const perception::FeatureSet& data, const std::string& name) {
  for (std::size_t a = 0; a < data.actions.size(); ++a)
    if (data.actions[a].name == name) return static_cast<int>(a);
  throw InputError(
      data.root, 0,
      fmt::format("the problem's sensing action '{}' is not an action of the data", name));
}

// The rows of `session` in action `a`'s data, in file order.
std::vector<int> session_rows(const perception::ActionData& action, int session) {
  std::vector<int> rows;
  for (std::size_t r = 0; r < action.rows.size(); ++r)
    if (action.rows[r].session == session) rows.push_back(static_cast<int>(r));
  return rows;
}

}  // namespace

std::vector<int> session_uses(const pomdp::ObjectProblemData& problem,
                              const perception::FeatureSet& data, int session) {
  std::vector<int> uses;
  for (const pomdp::SensingAction& act : problem.sensing) {
    const int recorded = static_cast<int>(
        session_rows(data.actions[data_action_index(data, act.name)], session).size());
    // A limit of 0 means "no limit" (pomdp::SensingAction::uses), so a session that never
    // performed a behaviour cannot be replayed as it stands.
    if (recorded == 0)
      throw InputError(
          data.root, 0,
          fmt::format("session '{}' of object '{}' has no recording of '{}': a dataset world "
                      "replays sessions that performed every behaviour (a recordings tree needs a "
                      "manifest `session` column that groups each exploration's recordings)",
                      data.sessions.at(session).name,
                      data.objects.at(data.sessions.at(session).object), act.name));
    uses.push_back(recorded);
  }
  return uses;
}

DatasetWorld::DatasetWorld(const pomdp::ObjectIdentificationModel& problem, DatasetWorldSpec spec)
    : problem_(problem), spec_(std::move(spec)) {
  if (!spec_.data || !spec_.model)
    throw std::invalid_argument("DatasetWorld: the data and the fitted model are needed");
  // The model's symbols are the planner's observations by index: its labels, or its graded
  // symbols when the problem plans with grades.
  const std::vector<std::string>& symbols = problem_.data().observation_symbols;
  if (spec_.model->graded() &&
      symbols == spec_.model->observation_symbols(perception::ObservationKind::graded))
    kind_ = perception::ObservationKind::graded;
  else if (spec_.model->levelled() &&
           symbols == spec_.model->observation_symbols(perception::ObservationKind::levels))
    kind_ = perception::ObservationKind::levels;
  else if (spec_.model->observation_symbols() != symbols)
    throw InputError(
        spec_.data->root, 0,
        fmt::format("the model hears [{}] but the problem's observations are [{}]: train the "
                    "model for the problem's classes (the same groups and hold-out, no reject)",
                    fmt::join(spec_.model->observation_symbols(), ", "),
                    fmt::join(problem_.data().observation_symbols, ", ")));
  for (const pomdp::SensingAction& act : problem_.data().sensing) {
    const int data_action = data_action_index(*spec_.data, act.name);
    readers_.emplace_back(*spec_.model, act.name, *spec_.data);
    rows_.push_back(session_rows(spec_.data->actions[data_action], spec_.session));
  }
  next_.assign(rows_.size(), 0);
}

void DatasetWorld::reset(const pomdp::State& true_state, Rng& /*rng*/) {
  true_class_ = true_state.discrete.at(0);
  next_.assign(rows_.size(), 0);
}

WorldStep DatasetWorld::execute(int action, Rng& /*rng*/) {
  const pomdp::ObjectProblemData& data = problem_.data();
  pomdp::Outcome outcome;
  if (problem_.is_sensing(action)) {
    if (next_[action] >= rows_[action].size())
      throw InputError(fmt::format(
          "the planner chose '{}' more often than the session recorded it ({} times): its "
          "problem's use limits are not the session's",
          data.sensing[action].name, rows_[action].size()));
    const int row = rows_[action][next_[action]++];
    const perception::Prediction heard = readers_[action].classify(row);
    outcome.observation.index = spec_.model->symbol(heard, kind_);
    // As a robot world logs it: the calibrated probability of the heard (or nearest) class.
    outcome.heard_probability = heard.probabilities.at(static_cast<std::size_t>(heard.best_class));
    // The level measured from the performance's recording, as a robot world logs its clip's.
    outcome.heard_ebr_db = readers_[action].level(row);
    outcome.reward = data.sensing[action].reward;
    return {outcome, {}};
  }
  const int sort = action - problem_.num_sensing();
  outcome.observation.index = problem_.none_symbol();
  outcome.reward = data.sorting_reward.at(sort).at(true_class_);
  outcome.terminal = true;
  return {outcome, {}};
}

}  // namespace echoplan::loop
