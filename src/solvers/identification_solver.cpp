#include "solvers/identification_solver.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/rng.h"

namespace echoplan::solvers {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The default node cap: about 2 GB of beliefs and bounds.
std::size_t default_max_nodes(int live_states, std::size_t sensing_observation_pairs) {
  // Belief and plan (L doubles each), counts (one uint16 per sensing action and observation),
  // key, bounds, reach, expansion mark, index entry.
  const std::size_t bytes_per_node =
      16 * static_cast<std::size_t>(live_states) + 2 * sensing_observation_pairs + 16 + 16 + 48;
  return std::size_t{2} * 1024 * 1024 * 1024 / bytes_per_node;
}

}  // namespace

namespace {
// `m`, once identification_shape_problem() has found nothing wrong with it.
const pomdp::TabularModel& identification_model(const pomdp::TabularModel& m) {
  if (auto why = identification_shape_problem(m))
    throw std::invalid_argument("not an identification problem: " + *why);
  return m;
}
}  // namespace

IdentificationSolver::IdentificationSolver(const pomdp::TabularModel& m,
                                           const IdentificationOptions& options)
    : IdentificationSolver(read_identification_tables(identification_model(m)), options) {}

IdentificationSolver::IdentificationSolver(std::shared_ptr<const IdentificationTables> tables,
                                           const IdentificationOptions& options)
    : tables_(std::move(tables)), options_(options) {
  const IdentificationTables& t = *tables_;
  // Points bound V* only at nodes with their uses spent (see the header).
  limited_ = t.limits.any();
  if (limited_) options_.sawtooth_upper_bound = false;
  // Without limits every stored plan fits every belief, and "sense once" measured only slower.
  if (!limited_) options_.sense_once_lower_bound = false;
  num_states_ = t.states;
  num_actions_ = t.actions;
  num_observations_ = t.observations;
  discount_ = t.discount;
  num_live_ = t.live_states;
  const int L = num_live_, O = num_observations_, A = num_actions_;
  kind_.assign(A, ActionKind::terminal);
  count_slot_.assign(A, -1);
  int sensing = 0;
  for (int a = 0; a < A; ++a)
    if (!t.terminal[a]) kind_[a] = ActionKind::sensing, count_slot_[a] = sensing++ * O;
  count_pairs_ = std::size_t(sensing) * O;
  max_nodes_ = options.max_nodes > 0 ? options.max_nodes : default_max_nodes(L, count_pairs_);
  // The plans every belief starts with: commit now (one vector per terminal action). The upper
  // bound's vectors: each action followed by knowing the state (its FIB vectors, since the state
  // is fixed); the corners are then the known-state values.
  std::vector<std::vector<double>> one_more_sensing(A, std::vector<double>(L));
  double reward_max = 0.0, reward_min = 0.0;
  for (int a = 0; a < A; ++a) {
    for (int l = 0; l < L; ++l) {
      const double r = tables_->reward[a * L + l];
      reward_max = std::max(reward_max, r);
      reward_min = std::min(reward_min, r);
      one_more_sensing[a][l] =
          kind_[a] == ActionKind::terminal
              ? r
              : r + discount_ * tables_->stay[a * L + l] * tables_->known_value[l];
    }
    if (kind_[a] == ActionKind::terminal)
      add_plan(AlphaVector{
          a, std::vector<double>(&tables_->reward[a * L], &tables_->reward[a * L] + L)});
  }
  upper_points_ = SawtoothUpperBound(std::move(one_more_sensing),
                                     (reward_max - reward_min) / (1.0 - discount_));
  if (options_.pair_upper_bound) {
    pair_bound_ = PairRelaxationBound(t, options_.pair_relaxation);
  }
  if (limited_ && options_.readings_left_upper_bound)
    readings_bound_ = ReadingsLeftBound(tables_, options_.readings_left);

  // The codes only need to be fixed and well mixed, not drawn from the user's seed (they do not
  // change any result, only how nodes are found).
  std::uint64_t state = 0x6964656e74696679ULL;  // "identify"
  pair_code_.resize(std::size_t(A) * O);
  for (Key& k : pair_code_) k = Key{splitmix64_next(state), splitmix64_next(state)};

  const std::vector<double>& b0_all = t.initial_belief;
  std::vector<double> b0(L);
  double total = 0.0;
  for (int l = 0; l < L; ++l) total += b0_all[t.model_state[l]];
  for (int l = 0; l < L; ++l) b0[l] = b0_all[t.model_state[l]] / total;
  belief_scratch_.resize(L);
  plan_scratch_.resize(L);
  uses_scratch_.resize(A);
  child_uses_scratch_.resize(A);
  child_plan_uses_scratch_.resize(A);
  children_scratch_.resize(O);
  if (options_.sense_once_lower_bound) read_sort_rewards();
  insert(Key{}, b0.data(), 0.0, nullptr);
}

void IdentificationSolver::read_sort_rewards() {
  const int L = num_live_;
  sort_scratch_.resize(std::size_t(num_actions_) * num_observations_);
  sort_floor_.assign(L, std::numeric_limits<double>::infinity());
  for (int a = 0; a < num_actions_; ++a)
    if (kind_[a] == ActionKind::terminal)
      for (int l = 0; l < L; ++l)
        sort_floor_[l] = std::min(sort_floor_[l], tables_->reward[a * L + l]);
  sort_bonus_start_.assign(1, 0);
  for (int a = 0; a < num_actions_; ++a) {
    if (kind_[a] != ActionKind::terminal) continue;
    sort_terminals_.push_back(a);
    for (int l = 0; l < L; ++l)
      if (const double bonus = tables_->reward[a * L + l] - sort_floor_[l]; bonus > 0.0)
        sort_bonus_.push_back({l, bonus});
    sort_bonus_start_.push_back(sort_bonus_.size());
  }
  heard_floor_.assign(std::size_t(num_actions_) * L, 0.0);
  for (int a = 0; a < num_actions_; ++a)
    for (int o = 0; kind_[a] == ActionKind::sensing && o < num_observations_; ++o)
      for (int l = 0; l < L; ++l)
        heard_floor_[a * L + l] +=
            tables_->emission[(std::size_t(a) * num_observations_ + o) * L + l] * sort_floor_[l];
}

double IdentificationSolver::expected_reward(const double* b, int a) const {
  double r = 0.0;
  for (int l = 0; l < num_live_; ++l) r += b[l] * tables_->reward[a * num_live_ + l];
  return r;
}

Bounds IdentificationSolver::simple_bounds(const double* b, const std::uint16_t* uses, double* plan,
                                           std::uint16_t* plan_uses, bool lower_wanted) const {
  double lower = -std::numeric_limits<double>::infinity(), upper = lower;
  int best = -1;
  for (int a = 0; a < num_actions_; ++a) {
    const double r = expected_reward(b, a);
    if (kind_[a] == ActionKind::terminal) {
      if (r > lower) lower = r, best = a;
      upper = std::max(upper, r);
    } else if (allowed(uses, a)) {  // only what may be taken now can earn more
      double future = 0.0;
      for (int l = 0; l < num_live_; ++l)
        future += b[l] * tables_->stay[a * num_live_ + l] * tables_->known_value[l];
      upper = std::max(upper, r + discount_ * future);
    }
  }
  if (plan != nullptr)
    std::copy(&tables_->reward[best * num_live_], &tables_->reward[(best + 1) * num_live_], plan);
  if (plan_uses != nullptr) std::fill_n(plan_uses, num_actions_, 0);
  if (lower_wanted && options_.sense_once_lower_bound)
    lower = sense_once(b, uses, lower, plan, plan_uses);
  if (pair_bound_.num_pairs() > 0) upper = std::min(upper, pair_bound_.value(b));
  if (readings_bound_.applies()) upper = std::min(upper, readings_bound_.value(b, uses));
  return {lower, std::max(lower, upper)};
}

bool IdentificationSolver::allowed(const std::uint16_t* uses, int a) const {
  return kind_[a] != ActionKind::sensing ||
         tables_->limits.allows_after([&](int x) { return uses == nullptr ? 0 : int(uses[x]); }, a);
}

double IdentificationSolver::best_sort_bonus(const double* b, const double* e,
                                             int& terminal) const {
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < sort_terminals_.size(); ++k) {
    double bonus = 0.0;
    for (std::size_t i = sort_bonus_start_[k]; i < sort_bonus_start_[k + 1]; ++i) {
      const int l = sort_bonus_[i].state;
      bonus += b[l] * e[l] * sort_bonus_[i].bonus;
    }
    if (bonus > best) best = bonus, terminal = sort_terminals_[k];
  }
  return best;
}

double IdentificationSolver::sense_once(const double* b, const std::uint16_t* uses, double lower,
                                        double* plan, std::uint16_t* plan_uses) const {
  const int L = num_live_, O = num_observations_;
  int* sort_after = sort_scratch_.data();
  int best_action = -1;
  for (int a = 0; a < num_actions_; ++a) {
    if (kind_[a] != ActionKind::sensing || !allowed(uses, a)) continue;
    // Whatever is heard, the sort earns at least the floor (summed over the observations once),
    // and the best sort after each observation its bonus above it. Every observation gets a sort,
    // even one this belief cannot hear: the plan is also a lower bound at other beliefs.
    double future = 0.0;
    for (int l = 0; l < L; ++l) future += b[l] * heard_floor_[a * L + l];
    for (int o = 0; o < O; ++o)
      future += best_sort_bonus(b, &tables_->emission[(std::size_t(a) * O + o) * L],
                                sort_after[a * O + o]);
    const double value = expected_reward(b, a) + discount_ * future;
    if (value > lower) lower = value, best_action = a;
  }
  if (best_action < 0) return lower;
  if (plan != nullptr) {
    const int a = best_action;
    for (int l = 0; l < L; ++l) plan[l] = tables_->reward[a * L + l];
    for (int o = 0; o < O; ++o) {
      const int t = sort_after[a * O + o];
      const double* e = &tables_->emission[(std::size_t(a) * O + o) * L];
      for (int l = 0; l < L; ++l) plan[l] += discount_ * e[l] * tables_->reward[t * L + l];
    }
  }
  if (plan_uses != nullptr) plan_uses[best_action] = 1;
  return lower;
}

Bounds IdentificationSolver::frontier_bounds(const double* b, double* plan, double upper_cap,
                                             const std::uint16_t* node_uses,
                                             std::size_t* index) const {
  const BeliefVector belief(b, b + num_live_);
  double lower = 0.0;
  const double* best = best_plan(b, lower, node_uses, index);
  if (plan != nullptr) std::copy(best, best + num_live_, plan);
  // Without points the sawtooth is max over the one-more-sensing vectors. (The pair relaxation
  // is in every node's bounds from the start: simple_bounds.)
  return {lower, std::max(lower, upper_points_.value_below(belief, upper_cap))};
}

const double* IdentificationSolver::best_plan(const double* b, double& value,
                                              const std::uint16_t* node_uses,
                                              std::size_t* index) const {
  const int L = num_live_;
  const std::size_t count = plan_matrix_.size() / L;
  std::size_t best = 0;
  value = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < count; ++k) {
    if (node_uses != nullptr && !plan_fits(k, node_uses)) continue;
    const double* alpha = &plan_matrix_[k * L];
    double v = 0.0;
    for (int l = 0; l < L; ++l) v += alpha[l] * b[l];
    if (v > value) value = v, best = k;
  }
  if (index != nullptr) *index = best;
  return &plan_matrix_[best * L];
}

bool IdentificationSolver::plan_fits(std::size_t plan, const std::uint16_t* node_uses) const {
  const std::uint16_t* needs = &plan_uses_matrix_[plan * num_actions_];
  // A plan found at another node fits this one when its uses fit the remaining ones and every
  // action it takes is available here from the start, whatever order the plan takes them in:
  // prerequisites only ever open actions, so a plan whose actions are all open here stays
  // feasible (one that opens its own, grasp then shake, is not reused here; that only weakens the
  // bound, never breaks it).
  const UseLimits& limits = tables_->limits;
  for (int a = 0; a < num_actions_; ++a) {
    if (needs[a] == 0) continue;
    const int limit = limits.max_uses(a);
    if (limit > 0 && node_uses[a] + needs[a] > limit) return false;
    for (int r : limits.prerequisites(a))
      if (node_uses[r] == 0) return false;
  }
  return true;
}

const std::uint16_t* IdentificationSolver::node_uses(NodeId node) const {
  for (int a = 0; a < num_actions_; ++a)
    uses_scratch_[a] = static_cast<std::uint16_t>(uses(node, a));
  return uses_scratch_.data();
}

void IdentificationSolver::add_plan(AlphaVector plan, const std::uint16_t* plan_uses) {
  if (limited_) {
    // No pruning by dominance: a dominated plan that needs fewer uses still bounds nodes the
    // dominating one does not fit.
    plan_matrix_.insert(plan_matrix_.end(), plan.values.begin(), plan.values.end());
    if (plan_uses != nullptr)
      plan_uses_matrix_.insert(plan_uses_matrix_.end(), plan_uses, plan_uses + num_actions_);
    else
      plan_uses_matrix_.resize(plan_uses_matrix_.size() + num_actions_, 0);
    return;
  }
  if (!plans_.add(std::move(plan))) return;
  // The set may have dropped plans the new one dominates: copy it afresh (as costly as the add).
  plan_matrix_.clear();
  for (const AlphaVector& alpha : plans_.vectors())
    plan_matrix_.insert(plan_matrix_.end(), alpha.values.begin(), alpha.values.end());
}

void IdentificationSolver::refresh(NodeId node) {
  const double* b = node_belief(node);
  double* plan = &plan_[std::size_t(node) * num_live_];
  // The node's own upper bound caps the sawtooth: points that cannot beat it are cut short.
  std::size_t index = 0;
  const Bounds f = frontier_bounds(b, plan_scratch_.data(), upper_[node],
                                   limited_ ? node_uses(node) : nullptr, &index);
  if (f.lower > lower_[node]) {
    lower_[node] = f.lower;
    std::copy(plan_scratch_.begin(), plan_scratch_.end(), plan);
    if (limited_)
      std::copy_n(&plan_uses_matrix_[index * num_actions_], num_actions_,
                  &node_plan_uses_[std::size_t(node) * num_actions_]);
  }
  upper_[node] = std::max(lower_[node], std::min(upper_[node], f.upper));
}

double IdentificationSolver::child_belief(const double* b, int a, int o, double* out) const {
  const double* e = &tables_->emission[(std::size_t(a) * num_observations_ + o) * num_live_];
  double weight = 0.0;
  for (int l = 0; l < num_live_; ++l) {
    out[l] = b[l] * e[l];
    weight += out[l];
  }
  if (weight > 0.0)
    for (int l = 0; l < num_live_; ++l) out[l] /= weight;
  return weight;
}

IdentificationSolver::NodeId IdentificationSolver::NodeIndex::find(const Key& key) const {
  if (slots_.empty()) return kEnded;
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = key.a & mask;; i = (i + 1) & mask) {
    const Slot& slot = slots_[i];
    if (slot.id == kEnded) return kEnded;
    if (slot.key == key) return slot.id;
  }
}

void IdentificationSolver::NodeIndex::insert(const Key& key, NodeId id) {
  // At most 5/8 full, so that probes stay short.
  if (8 * (size_ + 1) > 5 * slots_.size()) grow();
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = key.a & mask;
  while (slots_[i].id != kEnded) i = (i + 1) & mask;
  slots_[i] = Slot{key, id};
  ++size_;
}

void IdentificationSolver::NodeIndex::grow() {
  std::vector<Slot> old(std::max<std::size_t>(1024, 2 * slots_.size()));
  old.swap(slots_);
  size_ = 0;
  for (const Slot& slot : old)
    if (slot.id != kEnded) insert(slot.key, slot.id);
}

IdentificationSolver::Key IdentificationSolver::child_key(NodeId node, int a, int o) const {
  const Key& k = keys_[node];
  const Key& c = pair_code_[std::size_t(a) * num_observations_ + o];
  return Key{k.a + c.a, k.b + c.b};
}

IdentificationSolver::NodeId IdentificationSolver::insert(const Key& key, const double* b,
                                                          double log_reach,
                                                          const std::uint16_t* counts) {
  const auto id = static_cast<NodeId>(lower_.size());
  beliefs_.insert(beliefs_.end(), b, b + num_live_);
  if (counts != nullptr)
    counts_.insert(counts_.end(), counts, counts + count_pairs_);
  else
    counts_.resize(counts_.size() + count_pairs_, 0);
  log_reach_.push_back(log_reach);
  keys_.push_back(key);
  plan_.resize(plan_.size() + num_live_);
  const std::uint16_t* node_uses = limited_ ? this->node_uses(id) : nullptr;
  std::uint16_t* plan_uses = child_plan_uses_scratch_.data();
  const Bounds f = simple_bounds(b, node_uses, &plan_[std::size_t(id) * num_live_], plan_uses);
  lower_.push_back(f.lower);
  upper_.push_back(f.upper);
  expanded_at_.push_back(std::numeric_limits<double>::infinity());
  if (limited_) node_plan_uses_.insert(node_plan_uses_.end(), plan_uses, plan_uses + num_actions_);
  index_.insert(key, id);
  return id;
}

int IdentificationSolver::uses(NodeId node, int action) const {
  if (kind_[action] != ActionKind::sensing) return 0;
  const std::uint16_t* n = &counts_[std::size_t(node) * count_pairs_ + count_slot_[action]];
  int total = 0;
  for (int o = 0; o < num_observations_; ++o) total += n[o];
  return total;
}

bool IdentificationSolver::available(NodeId node, int action) const {
  return kind_[action] != ActionKind::sensing ||
         tables_->limits.allows_after([&](int x) { return uses(node, x); }, action);
}

IdentificationSolver::NodeId IdentificationSolver::child(NodeId node, int action, int observation) {
  if (node < 0 || static_cast<std::size_t>(node) >= num_nodes())
    throw std::invalid_argument("no such node");
  if (action < 0 || action >= num_actions_ || kind_[action] != ActionKind::sensing)
    throw std::invalid_argument(fmt::format("action {} is not a sensing action", action));
  if (!available(node, action))
    throw std::invalid_argument(fmt::format(
        "action {} is not available here (used up: {} uses allowed; or a prerequisite not yet "
        "taken)",
        action, tables_->limits.max_uses(action)));
  if (observation < 0 || observation >= num_observations_)
    throw std::invalid_argument(fmt::format("observation {} is out of range", observation));
  const Key key = child_key(node, action, observation);
  if (const NodeId found = index_.find(key); found != kEnded) return found;
  std::vector<double> b(num_live_);
  const double p = child_belief(node_belief(node), action, observation, b.data());
  if (p <= 0.0) return kEnded;
  // The child's reach weight: every history with the same counts has the same probability, and
  // there are at most Π_a n_a! / Π_o n_ao! of them; one more (a, o) multiplies that count by
  // (n_a + 1) / (n_ao + 1).
  const std::uint16_t* node_counts = &counts_[std::size_t(node) * count_pairs_];
  std::vector<std::uint16_t> counts(node_counts, node_counts + count_pairs_);
  const int n_a = uses(node, action);
  std::uint16_t& n_ao = counts[count_slot_[action] + observation];
  if (n_ao == std::numeric_limits<std::uint16_t>::max())
    throw std::length_error("identification search: a count outgrew 65535");
  const double log_reach = log_reach_[node] + std::log(discount_ * p) +
                           std::log(static_cast<double>(n_a + 1) / (n_ao + 1.0));
  ++n_ao;
  return insert(key, b.data(), log_reach, counts.data());
}

Bounds IdentificationSolver::value(NodeId node) const { return {lower_[node], upper_[node]}; }

Bounds IdentificationSolver::lookahead(NodeId node, int a, std::vector<ChildView>& children,
                                       double* plan, std::uint16_t* plan_uses,
                                       bool lower_wanted) const {
  const double* b = node_belief(node);
  const double r = expected_reward(b, a);
  const int L = num_live_;
  if (plan != nullptr) std::copy(&tables_->reward[a * L], &tables_->reward[a * L] + L, plan);
  if (plan_uses != nullptr) {
    std::fill_n(plan_uses, num_actions_, 0);
    if (kind_[a] == ActionKind::sensing) plan_uses[a] = 1;
  }
  if (kind_[a] == ActionKind::terminal) return {r, r};
  if (!available(node, a)) {
    constexpr double kNever = -std::numeric_limits<double>::infinity();
    for (ChildView& c : children) c = ChildView{};
    return {kNever, kNever};
  }
  double* scratch = belief_scratch_.data();
  double* child_plan = plan_scratch_.data();
  // With limits, the children's uses (this node's and one more of a) decide what their frontier
  // bounds may sense; without, every action stays allowed (null: none spent).
  std::uint16_t* child_uses = nullptr;
  std::uint16_t* child_plan_uses = child_plan_uses_scratch_.data();
  if (limited_) {
    child_uses = child_uses_scratch_.data();
    for (int x = 0; x < num_actions_; ++x) child_uses[x] = std::uint16_t(uses(node, x) + (x == a));
  }
  Bounds q{r, r};
  for (int o = 0; o < num_observations_; ++o) {
    ChildView& c = children[o];
    c = ChildView{};
    const double* e = &tables_->emission[(std::size_t(a) * num_observations_ + o) * L];
    const Key key = child_key(node, a, o);
    if (const NodeId found = index_.find(key); found != kEnded) {
      c.id = found;
      // The probability still comes from this node's belief (the child's belief is normalised).
      for (int l = 0; l < L; ++l) c.probability += b[l] * e[l];
      c.bounds = value(c.id);
      if (plan != nullptr)
        std::copy(&plan_[std::size_t(c.id) * L], &plan_[std::size_t(c.id) * L] + L, child_plan);
      // The plan's uses on its worst branch: a more, then the most any child's plan needs.
      if (plan_uses != nullptr)
        for (int x = 0; x < num_actions_; ++x)
          plan_uses[x] = std::max<std::uint16_t>(
              plan_uses[x], (x == a) + node_plan_uses_[std::size_t(c.id) * num_actions_ + x]);
    } else {
      // A child no live state here can reach still needs a plan for the states that can (the
      // plan bounds other beliefs too); its weight here is 0.
      c.probability = child_belief(b, a, o, scratch);
      c.bounds = simple_bounds(scratch, child_uses, child_plan, child_plan_uses, lower_wanted);
      if (plan_uses != nullptr)
        for (int x = 0; x < num_actions_; ++x)
          plan_uses[x] = std::max<std::uint16_t>(plan_uses[x], (x == a) + child_plan_uses[x]);
    }
    q.lower += discount_ * c.probability * c.bounds.lower;
    q.upper += discount_ * c.probability * c.bounds.upper;
    if (plan != nullptr)
      for (int l = 0; l < L; ++l) plan[l] += discount_ * e[l] * child_plan[l];
  }
  return q;
}

Bounds IdentificationSolver::action_value(NodeId node, int action) const {
  if (action < 0 || action >= num_actions_) throw std::invalid_argument("action out of range");
  std::vector<ChildView> children(num_observations_);
  return lookahead(node, action, children);
}

double IdentificationSolver::observation_probability(NodeId node, int action, int o) const {
  if (kind_[action] != ActionKind::sensing) return 0.0;
  const double* b = node_belief(node);
  const double* e = &tables_->emission[(std::size_t(action) * num_observations_ + o) * num_live_];
  double p = 0.0;
  for (int l = 0; l < num_live_; ++l) p += b[l] * e[l];
  return p;
}

std::vector<double> IdentificationSolver::belief(NodeId node) const {
  std::vector<double> full(num_states_, 0.0);
  const double* b = node_belief(node);
  for (int l = 0; l < num_live_; ++l) full[tables_->model_state[l]] = b[l];
  return full;
}

bool IdentificationSolver::backup(NodeId node) {
  const int L = num_live_;
  std::vector<double> plan(L), chosen(L);
  // With limits, the plans' worst-case uses per action (else unused).
  std::vector<std::uint16_t> uses(limited_ ? num_actions_ : 0), chosen_uses(uses.size());
  double lower = -std::numeric_limits<double>::infinity(), upper = lower;
  int best_action = 0;
  for (int a = 0; a < num_actions_; ++a) {
    const Bounds q =
        lookahead(node, a, children_scratch_, plan.data(), limited_ ? uses.data() : nullptr);
    if (q.lower > lower) {
      lower = q.lower;
      best_action = a;
      chosen.swap(plan);
      chosen_uses.swap(uses);
    }
    upper = std::max(upper, q.upper);
  }
  // Both the old and the new bounds are sound, so keep the tighter of each.
  const bool raised = lower > lower_[node], lowered = upper < upper_[node];
  const double* b = node_belief(node);
  if (raised) {
    lower_[node] = lower;
    std::copy(chosen.begin(), chosen.end(), &plan_[std::size_t(node) * L]);
    std::copy(chosen_uses.begin(), chosen_uses.end(),
              node_plan_uses_.begin() + std::ptrdiff_t(node) * std::ptrdiff_t(chosen_uses.size()));
    // Stored only when it beats the plans at this belief: a plan that does not would never be the
    // maximum where it was found, and every stored plan costs every later frontier evaluation.
    const std::size_t max_plans = options_.max_frontier_plans > 0 ? options_.max_frontier_plans
                                                                  : options_.max_frontier_entries;
    if (options_.plan_lower_bound && num_plans() < max_plans) {
      double known = 0.0;
      best_plan(b, known, limited_ ? node_uses(node) : nullptr);
      if (lower > known + options_.frontier_margin)
        add_plan(AlphaVector{best_action, chosen}, limited_ ? chosen_uses.data() : nullptr);
    }
  }
  if (lowered) {
    upper_[node] = std::max(lower_[node], upper);
    if (options_.sawtooth_upper_bound &&
        upper_points_.num_points() < options_.max_frontier_entries) {
      const BeliefVector belief(b, b + L);
      if (upper_[node] < upper_points_.value(belief) - options_.frontier_margin)
        upper_points_.add(belief, upper_[node]);
    }
  }
  return raised || lowered;
}

void IdentificationSolver::expand(NodeId node, double delta, int forced_action,
                                  RefineSpend& budget) {
  const bool forced = forced_action >= 0;
  const double reach = std::exp(log_reach_[node]);
  if (!forced && reach * (upper_[node] - lower_[node]) <= delta) return;
  if (!forced && expanded_at_[node] <= delta) return;
  // New nodes start with the cheap bounds; the plans and points are consulted only for a node
  // about to be expanded, which they may spare.
  refresh(node);
  if (!forced && reach * (upper_[node] - lower_[node]) <= delta) return;
  if (budget.exhausted(*this)) return;
  ++expansions_;
  ++budget.expansions;
  std::vector<ChildView> children(num_observations_);
  // An action whose best case is worse than what the node already guarantees cannot be optimal
  // here: its subtree cannot change V's bounds. Of the others, only those whose best case lies
  // near the node's are expanded in this pass: they decide its upper bound, and the best of them
  // is the likeliest optimum. The rest wait for a later pass, when the gap (and so the margin)
  // has shrunk; as it closes every action that can still be optimal is expanded.
  const double cut =
      std::max(lower_[node], upper_[node] - options_.expand_within * (upper_[node] - lower_[node]));
  for (int a = 0; a < num_actions_; ++a) {
    if (kind_[a] != ActionKind::sensing || !available(node, a)) continue;
    if (forced && a != forced_action) continue;
    // Only the upper bound decides here, and the children are made (with their bounds) below.
    const Bounds q = lookahead(node, a, children, nullptr, nullptr, /*lower_wanted=*/false);
    if (!forced && (q.upper <= lower_[node] || q.upper < cut)) continue;
    for (int o = 0; o < num_observations_; ++o) {
      if (children[o].probability <= 0.0) continue;
      NodeId next = children[o].id;
      if (next == kEnded) next = child(node, a, o);
      expand(next, delta, -1, budget);
    }
  }
  backup(node);
  if (!budget.stopped && !forced) expanded_at_[node] = std::min(expanded_at_[node], delta);
}

bool IdentificationSolver::trial(NodeId start, int forced_action, double epsilon,
                                 RefineSpend& budget) {
  // Far deeper than any useful trial: a belief this deep is certain or its reach is negligible.
  constexpr int kMaxDepth = 10000;
  const std::size_t nodes_before = num_nodes();
  std::vector<ChildView> children(num_observations_);
  std::vector<NodeId> path{start};
  bool changed = false;
  double threshold = epsilon;  // ε γ^-t
  NodeId node = start;
  for (int depth = 0; depth < kMaxDepth; ++depth) {
    const bool forced = depth == 0 && forced_action >= 0;
    const Bounds before = value(node);
    refresh(node);
    changed = changed || value(node).lower > before.lower || value(node).upper < before.upper;
    if (!forced && upper_[node] - lower_[node] <= threshold) break;
    if (budget.exhausted(*this)) break;
    // Children are made when their parent is on a trial (so later lookaheads read them instead of
    // evaluating the frontier again); only the chosen action's are refreshed.
    for (int a = 0; a < num_actions_; ++a) {
      if (kind_[a] != ActionKind::sensing || (forced && a != forced_action)) continue;
      if (!available(node, a)) continue;
      for (int o = 0; o < num_observations_; ++o)
        if (index_.find(child_key(node, a, o)) == kEnded) child(node, a, o);
    }
    int action = forced_action;
    if (!forced) {
      // HSVI's choice: the action whose upper bound is highest (an optimistic policy).
      double best = -std::numeric_limits<double>::infinity();
      for (int a = 0; a < num_actions_; ++a) {
        const double upper = lookahead(node, a, children).upper;
        if (upper > best) best = upper, action = a;
      }
    }
    if (kind_[action] == ActionKind::terminal) break;  // its value is exact
    lookahead(node, action, children);
    for (const ChildView& c : children)
      if (c.id != kEnded) refresh(c.id);
    lookahead(node, action, children);
    // The observation whose child's gap, weighted by its probability, exceeds the child's share
    // of ε the most.
    int observation = -1;
    double best_excess = 0.0;
    for (int o = 0; o < num_observations_; ++o) {
      const ChildView& c = children[o];
      if (c.probability <= 0.0) continue;
      const double excess = c.probability * (c.bounds.gap() - threshold / discount_);
      if (excess > best_excess) best_excess = excess, observation = o;
    }
    if (observation < 0) break;
    node = children[observation].id != kEnded ? children[observation].id
                                              : child(node, action, observation);
    path.push_back(node);
    threshold /= discount_;
  }
  for (auto it = path.rbegin(); it != path.rend(); ++it) {
    ++expansions_;
    ++budget.expansions;
    changed = backup(*it) || changed;
  }
  return changed || num_nodes() > nodes_before;
}

bool IdentificationSolver::RefineSpend::exhausted(const IdentificationSolver& solver) {
  if (stopped) return true;
  if (limits.expansions > 0 && expansions >= limits.expansions) stopped = true;
  if (solver.num_nodes() >= solver.max_nodes_) stopped = true;
  // The clock is read every 16 expansions only.
  if (limits.seconds > 0.0 && (expansions & 15) == 0 && seconds_since(start) >= limits.seconds)
    stopped = true;
  return stopped;
}

bool IdentificationSolver::refine_to(NodeId node, int action, const RefineLimits& limits) {
  RefineSpend budget{limits, std::chrono::steady_clock::now()};
  auto gap = [&] {
    return action < 0 ? upper_[node] - lower_[node] : action_value(node, action).gap();
  };
  // Passes of shrinking δ: each expands every belief whose weighted gap γ^t P(path) · gap exceeds
  // δ; a pass that reaches no such belief leaves the gap below what δ allows, so δ halves until
  // the target is met.
  // δ is absolute (in units of weighted gap at b0); relative to this node it is δ / reach(node).
  // Starting coarse spreads the first passes over the likely beliefs instead of one deep corner;
  // a node already expanded to some δ (an earlier call) resumes below it.
  if (options_.search == IdentificationOptions::Search::trials) {
    // ε starts at half the gap (coarse trials spread over the likely beliefs first) and halves
    // whenever a trial finds nothing above it to improve.
    double scale = 0.5;
    while (gap() > limits.target_gap) {
      const double epsilon = std::max(limits.target_gap, scale * gap());
      const bool progress = trial(node, action, epsilon, budget);
      if (budget.stopped) return gap() <= limits.target_gap;
      if (!progress) {
        scale *= 0.5;
        if (scale < 1e-12) return false;
      }
    }
    return true;
  }
  const double reach = std::exp(log_reach_[node]);
  double delta = std::min(0.25 * gap() * reach, 0.5 * expanded_at_[node]);
  while (gap() > limits.target_gap) {
    const long before = expansions_;
    expand(node, delta, action, budget);
    if (budget.stopped) return gap() <= limits.target_gap;
    if (expansions_ == before || gap() > limits.target_gap) delta *= 0.5;
    if (delta < 1e-300) return false;
  }
  return true;
}

bool IdentificationSolver::refine(NodeId node, const RefineLimits& limits) {
  return refine_to(node, -1, limits);
}

bool IdentificationSolver::refine_action(NodeId node, int action, const RefineLimits& limits) {
  if (action < 0 || action >= num_actions_) throw std::invalid_argument("action out of range");
  if (kind_[action] == ActionKind::terminal) return true;
  if (!available(node, action)) return true;  // -inf, exactly
  return refine_to(node, action, limits);
}

}  // namespace echoplan::solvers
