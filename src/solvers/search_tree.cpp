#include "solvers/search_tree.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/error.h"

namespace echoplan::solvers {

namespace {
constexpr UnheardOutcomes kUnheardOutcomes[] = {UnheardOutcomes::share, UnheardOutcomes::commit};
}  // namespace

const char* unheard_outcomes_name(UnheardOutcomes unheard) {
  return unheard == UnheardOutcomes::share ? "share" : "commit";
}

std::vector<std::string> unheard_outcomes_names() {
  std::vector<std::string> names;
  for (UnheardOutcomes u : kUnheardOutcomes) names.emplace_back(unheard_outcomes_name(u));
  return names;
}

UnheardOutcomes parse_unheard_outcomes(const std::string& text) {
  for (UnheardOutcomes u : kUnheardOutcomes)
    if (text == unheard_outcomes_name(u)) return u;
  throw InputError("unheard outcomes '" + text + "' is not one of share, commit");
}

void SearchOptions::validate() const {
  if (!(exploration >= 0.0)) throw InputError("exploration constant must be >= 0");
  if (max_depth < 1) throw InputError("max depth must be >= 1");
  if (root_particles < 1) throw InputError("root particles must be >= 1");
  if (min_root_particles < 0) throw InputError("min root particles must be >= 0");
  if (leaf.expand_after < 1) throw InputError("expand-after must be >= 1");
  if (!(leaf.exact_share >= 0.0 && leaf.exact_share <= 1.0))
    throw InputError("exact share must be in [0, 1]");
  if (leaf.offline_expansions < 1) throw InputError("offline expansions must be >= 1");
  // Only a leaf that follows the exact belief knows P(o | b, a) and the value of committing after
  // o.
  if (unheard == UnheardOutcomes::commit && !follows_exact_belief(leaf.mode))
    throw InputError(std::string("unheard outcomes at commit needs a leaf value that follows the "
                                 "exact belief (policy, exact or exact-offline), not ") +
                     leaf_mode_name(leaf.mode));
  if (!(branching.continuous_threshold >= 0.0))
    throw InputError("observation branching threshold must be >= 0");
}

BeliefNode::BeliefNode(NodeCounts* c) : counts(c) { ++counts->belief; }
BeliefNode::~BeliefNode() { --counts->belief; }
ActionNode::ActionNode(NodeCounts* c) : counts(c) { ++counts->action; }
ActionNode::~ActionNode() { --counts->action; }

TreeSearchSolver::TreeSearchSolver(pomdp::ModelPtr model, SearchOptions options, LeafUse use)
    : model_(std::move(model)), options_(options) {
  if (!model_) throw std::invalid_argument("TreeSearchSolver needs a model");
  use_limits_ = UseLimits(*model_);
  options_.validate();
  leaf_value_ = make_leaf_value(options_.leaf, model_, use);
}

std::unique_ptr<BeliefNode> TreeSearchSolver::new_belief_node() {
  auto node = std::make_unique<BeliefNode>(&counts_);
  node->actions.resize(model_->num_actions());
  return node;
}

void TreeSearchSolver::replace_model(pomdp::ModelPtr model) {
  if (!model) throw std::invalid_argument("replace_model(): no model");
  const pomdp::ModelSpec& old_spec = model_->spec();
  const pomdp::ModelSpec& new_spec = model->spec();
  if (new_spec.action_names != old_spec.action_names ||
      new_spec.observation.names != old_spec.observation.names ||
      new_spec.observation.discrete != old_spec.observation.discrete ||
      new_spec.discount != old_spec.discount)
    throw InputError("model change: the new model '" + new_spec.name +
                     "' does not share the actions, observations and discount of '" +
                     old_spec.name + "'");
  model_ = std::move(model);
  use_limits_ = UseLimits(*model_);
}

void TreeSearchSolver::reset(const pomdp::Belief& belief, Rng& rng) {
  if (root_) before_reroot(nullptr);
  root_.reset();
  root_ = new_belief_node();
  root_->expanded = true;  // the root always branches: it is where the decision is made
  episodes_total_ = 0;
  episodes_last_ = 0;
  root_uses_.clear();
  replenish_root(belief, rng);
}

void TreeSearchSolver::replenish_root(const pomdp::Belief& belief, Rng& rng) {
  const auto target = static_cast<std::size_t>(options_.root_particles);
  root_->particles.reserve(target);
  while (root_->particles.size() < target) {
    root_->particles.push_back(belief.sample(rng));
    root_particle_added(*root_, root_->particles.back(), rng);
  }
}

void TreeSearchSolver::improve(const Budget& budget, Rng& rng) {
  if (!root_) throw std::logic_error("improve() before reset()");
  if (budget.amount <= 0) throw InputError("search budget must be > 0");
  episodes_last_ = 0;
  // An episode budget never reads the clock, so it replays exactly; a time budget checks the clock
  // after every episode and always runs at least one.
  if (budget.kind == Budget::Kind::episodes) {
    for (std::int64_t i = 0; i < budget.amount; ++i) run_episode(rng), ++episodes_last_;
  } else {
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::milliseconds(budget.amount);
    do {
      run_episode(rng);
      ++episodes_last_;
    } while (std::chrono::steady_clock::now() < deadline);
  }
  episodes_total_ += episodes_last_;
}

int TreeSearchSolver::best_action() const {
  if (!root_) throw std::logic_error("best_action() before reset()");
  int best = -1;
  double best_value = -std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < root_->actions.size(); ++a) {
    const ActionNode* node = root_->actions[a].get();
    if (!use_limits_.allows(root_uses_, static_cast<int>(a))) continue;
    if (node && node->value > best_value) best = static_cast<int>(a), best_value = node->value;
  }
  if (best < 0) throw std::logic_error("best_action() before any episode");
  return best;
}

std::vector<double> TreeSearchSolver::root_action_values() const {
  std::vector<double> values(model_->num_actions(), std::numeric_limits<double>::quiet_NaN());
  if (!root_) return values;
  for (std::size_t a = 0; a < root_->actions.size(); ++a)
    if (root_->actions[a]) values[a] = root_->actions[a]->value;
  return values;
}

void TreeSearchSolver::update(int action, const pomdp::Observation& observation,
                              const pomdp::Belief& belief_after, Rng& rng) {
  if (!root_) throw std::logic_error("update() before reset()");
  if (action < 0 || action >= model_->num_actions())
    throw std::out_of_range("update(): bad action");
  use_limits_.count(root_uses_, action);
  // Keep the subtree the real step leads to; everything else goes when the old root is destroyed.
  std::unique_ptr<BeliefNode> kept;
  if (ActionNode* taken = root_->actions[action].get()) {
    for (ObservationChild& child : taken->children)
      if (options_.branching.same_branch(child.observation, observation)) {
        kept = std::move(child.node);
        break;
      }
  }
  before_reroot(kept.get());
  root_.reset();
  root_ = kept ? std::move(kept) : new_belief_node();
  if (!root_->expanded) {
    root_->expanded = true;
    root_->leaf.release();
  }
  if (root_->particles.size() < static_cast<std::size_t>(options_.min_root_particles) ||
      root_->particles.empty())
    replenish_root(belief_after, rng);
}

namespace {
int deepest(const BeliefNode& node, int depth) {
  int best = depth;
  for (const auto& action : node.actions)
    if (action)
      for (const ObservationChild& child : action->children)
        best = std::max(best, deepest(*child.node, depth + 1));
  return best;
}

void count_reachable(const BeliefNode& node, NodeCounts& counts) {
  ++counts.belief;
  for (const auto& action : node.actions)
    if (action) {
      ++counts.action;
      for (const ObservationChild& child : action->children) count_reachable(*child.node, counts);
    }
}
}  // namespace

SolverStats TreeSearchSolver::stats() const {
  SolverStats s;
  s.episodes_total = episodes_total_;
  s.episodes_last = episodes_last_;
  s.belief_nodes = counts_.belief;
  s.action_nodes = counts_.action;
  if (root_) {
    s.max_depth = deepest(*root_, 0);
    s.root_particles = static_cast<std::int64_t>(root_->particles.size());
  }
  return s;
}

std::int64_t TreeSearchSolver::subtree_belief_nodes(int action,
                                                    const pomdp::Observation& observation) const {
  if (!root_ || action < 0 || action >= model_->num_actions() || !root_->actions[action]) return 0;
  for (const ObservationChild& child : root_->actions[action]->children)
    if (options_.branching.same_branch(child.observation, observation)) {
      NodeCounts counts;
      count_reachable(*child.node, counts);
      return counts.belief;
    }
  return 0;
}

NodeCounts TreeSearchSolver::reachable_nodes() const {
  NodeCounts counts;
  if (root_) count_reachable(*root_, counts);
  return counts;
}

const pomdp::State& TreeSearchSolver::sample_root_particle(Rng& rng) const {
  const auto& particles = root_->particles;
  return particles[static_cast<std::size_t>(uniform01(rng) * particles.size())];
}

bool TreeSearchSolver::leaf_or_expand(BeliefNode& node, int depth) {
  if (depth >= options_.max_depth) return true;
  if (node.expanded) return false;
  if (node.visits <= options_.leaf.expand_after) return true;
  node.expanded = true;
  node.leaf.release();
  return false;
}

int TreeSearchSolver::select_action(const BeliefNode& node, const UseCounts& uses) const {
  const double log_n = std::log(static_cast<double>(std::max<std::int64_t>(node.action_visits, 1)));
  int best = use_limits_.any() ? -1 : 0;
  double best_score = -std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < node.actions.size(); ++a) {
    if (!use_limits_.allows(uses, static_cast<int>(a))) continue;
    const ActionNode* action = node.actions[a].get();
    if (!action || action->visits == 0) return static_cast<int>(a);
    const double score = action->value + options_.exploration *
                                             std::sqrt(log_n / static_cast<double>(action->visits));
    if (score > best_score) best = static_cast<int>(a), best_score = score;
  }
  if (best < 0) throw std::logic_error("the use limits leave no action to take");
  return best;
}

ActionNode& TreeSearchSolver::action_node(BeliefNode& node, int action) {
  auto& slot = node.actions[action];
  if (!slot) slot = std::make_unique<ActionNode>(&counts_);
  return *slot;
}

std::size_t TreeSearchSolver::child_for(ActionNode& action, const pomdp::Observation& observation) {
  for (std::size_t i = 0; i < action.children.size(); ++i)
    if (options_.branching.same_branch(action.children[i].observation, observation)) return i;
  action.children.push_back(ObservationChild{observation, new_belief_node()});
  return action.children.size() - 1;
}

}  // namespace echoplan::solvers
