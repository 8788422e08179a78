#include "solvers/model_change.h"

#include <string>

#include "common/error.h"

namespace echoplan::solvers {

bool ModelChange::affects(const pomdp::State& next, int action) const {
  for (const ObservationRow& row : rows)
    if (row.action == action &&
        (row.object < 0 || (!next.discrete.empty() && next.discrete[0] == row.object)))
      return true;
  return false;
}

namespace {
void require_same(bool same, const std::string& what) {
  if (!same)
    throw InputError("model change: the new model differs in " + what +
                     ", not only in its observation table; plan afresh (reset) instead");
}
}  // namespace

ModelChange observation_table_change(
    const pomdp::ObjectIdentificationModel& before,
    std::shared_ptr<const pomdp::ObjectIdentificationModel> after) {
  if (!after) throw std::invalid_argument("observation_table_change: no new model");
  const pomdp::ObjectProblemData& a = before.data();
  const pomdp::ObjectProblemData& b = after->data();
  require_same(a.objects == b.objects, "its objects");
  require_same(a.prior == b.prior, "its prior");
  require_same(a.discount == b.discount, "its discount");
  require_same(a.initial_joints == b.initial_joints && a.initial_offset == b.initial_offset,
               "its initial configuration");
  require_same(a.sensing.size() == b.sensing.size(), "its sensing actions");
  for (std::size_t i = 0; i < a.sensing.size(); ++i)
    require_same(a.sensing[i].name == b.sensing[i].name &&
                     a.sensing[i].reward == b.sensing[i].reward &&
                     a.sensing[i].offset_change == b.sensing[i].offset_change &&
                     a.sensing[i].collision_probability == b.sensing[i].collision_probability,
                 "sensing action '" + a.sensing[i].name + "'");
  require_same(a.sorting == b.sorting && a.sorting_reward == b.sorting_reward &&
                   a.collision_reward == b.collision_reward,
               "its sorting actions or rewards");
  require_same(a.observation_symbols == b.observation_symbols, "its observation symbols");
  ModelChange change;
  change.model = after;
  for (std::size_t action = 0; action < a.observation_table.size(); ++action)
    for (std::size_t k = 0; k < a.objects.size(); ++k)
      if (a.observation_table[action][k] != b.observation_table[action][k])
        change.rows.push_back({static_cast<int>(action), static_cast<int>(k)});
  return change;
}

}  // namespace echoplan::solvers
