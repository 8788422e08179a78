#include "pomdp/object_identification_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "pomdp/distribution.h"

namespace echoplan::pomdp {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("object problem: " + what);
}

// Cumulative sums scaled so the last is exactly 1: rows that sum to 1 only within the tolerance
// can then never yield a symbol of probability 0 from a draw in [0, 1).
std::vector<double> cumulative(const std::vector<double>& p) {
  std::vector<double> cdf(p.size());
  double acc = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) cdf[i] = acc += p[i];
  for (double& c : cdf) c /= acc;
  cdf.back() = 1.0;
  return cdf;
}

bool is_distribution(const std::vector<double>& row) {
  return check_row(row.data(), row.size()).ok();
}

// Depth first from `a`: the path so far in `path`, each action's state in `mark` (0 unvisited,
// 1 on the path, 2 done). True when a cycle closes; `path` then ends with it.
bool closes_cycle(const std::vector<SensingAction>& sensing, int a, std::vector<int>& mark,
                  std::vector<int>& path) {
  mark[a] = 1;
  path.push_back(a);
  for (int r : sensing[a].prerequisites) {
    if (r < 0 || r >= static_cast<int>(sensing.size())) continue;
    if (mark[r] == 1) {
      path.push_back(r);
      return true;
    }
    if (mark[r] == 0 && closes_cycle(sensing, r, mark, path)) return true;
  }
  mark[a] = 2;
  path.pop_back();
  return false;
}

}  // namespace

std::vector<int> prerequisite_cycle(const std::vector<SensingAction>& sensing) {
  std::vector<int> mark(sensing.size(), 0), path;
  for (int a = 0; a < static_cast<int>(sensing.size()); ++a) {
    if (mark[a] != 0 || !closes_cycle(sensing, a, mark, path)) continue;
    // The path is the walk from `a`; the cycle starts where its last action first appears.
    const auto start = std::find(path.begin(), path.end(), path.back());
    return {start, path.end()};
  }
  return {};
}

void validate_object_problem(const ObjectProblemData& d) {
  const std::size_t k = d.objects.size(), m = d.sensing.size(), j = d.sorting.size(),
                    c = d.observation_symbols.size();
  require(k > 0 && m > 0 && j > 0 && c > 0,
          "needs at least one object, sensing action, sorting action and observation symbol");
  require(d.discount > 0.0 && d.discount < 1.0, "discount must be in (0, 1)");
  require(d.prior.size() == k && is_distribution(d.prior),
          "prior must be a distribution over objects");
  require(d.observation_table.size() == m, "observation table needs one block per sensing action");
  for (const auto& block : d.observation_table) {
    require(block.size() == k, "observation table needs one row per object");
    for (const auto& row : block) {
      require(row.size() == c && is_distribution(row),
              "each observation row must be a distribution over the symbols");
    }
  }
  require(d.sorting_reward.size() == j, "sorting rewards need one row per sorting action");
  for (const auto& row : d.sorting_reward)
    require(row.size() == k, "sorting reward row per object");
  for (const auto& a : d.sensing) {
    require(a.collision_probability >= 0.0 && a.collision_probability <= 1.0,
            "collision probability must be in [0, 1]");
    require(a.uses >= 0, "a sensing action's use limit must be >= 0 (0: no limit)");
    for (int r : a.prerequisites)
      require(r >= 0 && r < static_cast<int>(m), "a prerequisite must be a sensing action");
  }
  require(prerequisite_cycle(d.sensing).empty(),
          "the sensing actions' prerequisites go round in a circle");
}

// ---- tabular view ----

ObjectIdentificationTabular::ObjectIdentificationTabular(const ObjectProblemData& data)
    : data_(data),
      num_objects_(static_cast<int>(data.objects.size())),
      num_sensing_(static_cast<int>(data.sensing.size())),
      num_sorting_(static_cast<int>(data.sorting.size())),
      num_symbols_(static_cast<int>(data.observation_symbols.size())),
      discount_(data.discount) {}

double ObjectIdentificationTabular::transition(int s, int a, int s_next) const {
  const int done = num_objects_;
  // 'done' absorbs; sorting always ends; sensing ends only by collision.
  if (s == done || a >= num_sensing_) return s_next == done ? 1.0 : 0.0;
  const double p = data_.sensing[a].collision_probability;
  if (s_next == done) return p;
  return s_next == s ? 1.0 - p : 0.0;
}

double ObjectIdentificationTabular::observation(int a, int s_next, int o) const {
  // Nothing is heard on arriving at 'done', and a sensing action that did not collide is heard.
  if (s_next == num_objects_ || a >= num_sensing_) return o == num_symbols_ ? 1.0 : 0.0;
  if (o == num_symbols_) return 0.0;
  return data_.observation_table[a][s_next][o];
}

double ObjectIdentificationTabular::reward(int s, int a) const {
  if (s == num_objects_) return 0.0;
  if (a >= num_sensing_) return data_.sorting_reward[a - num_sensing_][s];
  const SensingAction& act = data_.sensing[a];
  return (1.0 - act.collision_probability) * act.reward +
         act.collision_probability * data_.collision_reward;
}

std::vector<double> ObjectIdentificationTabular::initial_belief() const {
  std::vector<double> b = data_.prior;
  b.push_back(0.0);
  return b;
}

// ---- generative model ----

ObjectIdentificationModel::ObjectIdentificationModel(ObjectProblemData data)
    : data_((validate_object_problem(data), std::move(data))),
      tabular_(data_),
      num_objects_(static_cast<int>(data_.objects.size())),
      num_symbols_(static_cast<int>(data_.observation_symbols.size())) {
  spec_.name = data_.name;
  for (const auto& a : data_.sensing) spec_.action_names.push_back(a.name);
  for (const auto& a : data_.sorting) spec_.action_names.push_back(a);
  for (int i = 1; i <= kNumJoints; ++i)
    spec_.state.continuous_names.push_back("joint" + std::to_string(i));
  for (const char* axis : {"offset_x", "offset_y", "offset_z"})
    spec_.state.continuous_names.push_back(axis);
  spec_.state.discrete_names = {"object"};
  spec_.state.discrete_value_names = {data_.objects};
  spec_.observation.discrete = true;
  spec_.observation.names = data_.observation_symbols;
  spec_.observation.names.push_back("none");
  spec_.discount = data_.discount;

  // Reward bounds over everything a step can return (the collision reward only if one can happen).
  double lo = data_.sensing[0].reward, hi = lo;
  for (const auto& a : data_.sensing) {
    lo = std::min(lo, a.reward);
    hi = std::max(hi, a.reward);
    if (a.collision_probability > 0.0) {
      lo = std::min(lo, data_.collision_reward);
      hi = std::max(hi, data_.collision_reward);
    }
  }
  for (const auto& row : data_.sorting_reward) {
    for (double r : row) {
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
  }
  spec_.min_reward = lo;
  spec_.max_reward = hi;

  // Cumulative rows so that a step samples a symbol with one uniform draw and no allocation.
  const int m = num_sensing();
  for (int a = 0; a < m; ++a) {
    for (int k = 0; k < num_objects_; ++k) {
      const std::vector<double> cdf = cumulative(data_.observation_table[a][k]);
      obs_cdf_.insert(obs_cdf_.end(), cdf.begin(), cdf.end());
    }
  }
  prior_cdf_ = cumulative(data_.prior);

  // Known-object value: sorting now versus the best stationary sensing loop, whose value solves
  // V = (1-p) r + p r_collision + gamma (1-p) V.
  double sense_forever = -1e300;
  for (const auto& a : data_.sensing) {
    const double p = a.collision_probability;
    const double expected = (1.0 - p) * a.reward + p * data_.collision_reward;
    sense_forever = std::max(sense_forever, expected / (1.0 - data_.discount * (1.0 - p)));
  }
  for (int k = 0; k < num_objects_; ++k) {
    double best = sense_forever;
    for (const auto& row : data_.sorting_reward) best = std::max(best, row[k]);
    known_object_value_.push_back(best);
  }
}

State ObjectIdentificationModel::tabular_state(int s) const {
  State state;
  state.continuous.assign(data_.initial_joints.begin(), data_.initial_joints.end());
  state.continuous.insert(state.continuous.end(), data_.initial_offset.begin(),
                          data_.initial_offset.end());
  state.discrete = {s};
  return state;
}

State ObjectIdentificationModel::sample_initial_state(Rng& rng) const {
  const int k = sample_from_cdf(prior_cdf_.data(), num_objects_, uniform01(rng));
  return tabular_state(k);
}

StepResult ObjectIdentificationModel::step(const State& state, int action, Rng& rng) const {
  StepResult r;
  r.next = state;
  r.observation.index = none_symbol();
  const int k = state.discrete[0];
  if (!is_sensing(action)) {
    r.reward = data_.sorting_reward[action - num_sensing()][k];
    r.terminal = true;
    return r;
  }
  const SensingAction& act = data_.sensing[action];
  // Only draw for a collision when one is possible, so collision-free problems use one draw per
  // step and stay reproducible if collision data is added to other actions.
  if (act.collision_probability > 0.0 && uniform01(rng) < act.collision_probability) {
    r.reward = data_.collision_reward;
    r.terminal = true;
    r.collision = true;
    return r;
  }
  for (int i = 0; i < 3; ++i) r.next.continuous[kOffsetX + i] += act.offset_change[i];
  const double* cdf =
      &obs_cdf_[(static_cast<std::size_t>(action) * num_objects_ + k) * num_symbols_];
  r.observation.index = sample_from_cdf(cdf, num_symbols_, uniform01(rng));
  r.reward = act.reward;
  return r;
}

double ObjectIdentificationModel::observation_likelihood(const State& next_state, int action,
                                                         const Observation& observation) const {
  const int o = observation.index;
  if (o < 0 || o > num_symbols_ || action < 0 || action >= num_actions()) return 0.0;
  if (!is_sensing(action)) return o == num_symbols_ ? 1.0 : 0.0;
  if (o == num_symbols_) return 0.0;
  return data_.observation_table[action][next_state.discrete[0]][o];
}

int ObjectIdentificationModel::max_uses(int action) const {
  return is_sensing(action) ? data_.sensing[action].uses : 0;
}

std::vector<int> ObjectIdentificationModel::prerequisites(int action) const {
  // Sensing actions come first, so an index into data_.sensing is the model's action index.
  return is_sensing(action) ? data_.sensing[action].prerequisites : std::vector<int>{};
}

double ObjectIdentificationModel::heuristic_value(const State& state) const {
  return known_object_value_[state.discrete[0]];
}

}  // namespace echoplan::pomdp
