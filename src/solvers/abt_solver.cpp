#include "solvers/abt_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/error.h"

namespace echoplan::solvers {

namespace {
void add_particle_rewards(BeliefNode& node, const std::vector<double>& rewards, double sign) {
  node.particle_reward_sums.resize(rewards.size(), 0.0);
  for (std::size_t a = 0; a < rewards.size(); ++a)
    node.particle_reward_sums[a] += sign * rewards[a];
  node.particles_evaluated += sign > 0 ? 1 : -1;
}
}  // namespace

AbtSolver::AbtSolver(pomdp::ModelPtr model, SearchOptions options)
    : TreeSearchSolver(std::move(model), options, LeafUse::belief_tree) {}

void AbtSolver::reset(const pomdp::Belief& belief, Rng& rng) {
  TreeSearchSolver::reset(belief, rng);
  leaf_value().reset(belief);
}

void AbtSolver::improve(const Budget& budget, Rng& rng) {
  root_values_stale_ = true;
  TreeSearchSolver::improve(leaf_value().episode_budget(budget), rng);
}

int AbtSolver::best_action() const {
  const int decided = leaf_value().root_decision(model().num_actions());
  return decided >= 0 ? decided : TreeSearchSolver::best_action();
}

void AbtSolver::update(int action, const pomdp::Observation& observation,
                       const pomdp::Belief& belief_after, Rng& rng) {
  TreeSearchSolver::update(action, observation, belief_after, rng);
  leaf_value().follow(action, observation, belief_after);
}

const std::vector<double>& AbtSolver::evaluate_particle(BeliefNode& node, const pomdp::State& state,
                                                        Rng& rng) {
  const pomdp::Model& m = model();
  const int actions = m.num_actions();
  one_step_each_.clear();
  rewards_.resize(actions);
  for (int a = 0; a < actions; ++a) {
    one_step_each_.push_back(m.step(state, a, rng));
    rewards_[a] = one_step_each_.back().reward;
  }
  add_particle_rewards(node, rewards_, +1.0);
  return rewards_;
}

void AbtSolver::root_particle_added(BeliefNode& root, const pomdp::State& state, Rng& rng) {
  evaluate_particle(root, state, rng);
}

namespace {

// The exact-belief terms of `action` at `belief` (the belief `node` holds now): computed once per
// belief, and for each child once, in the order children were added. The commit terms only for
// `unheard` at commit (they cost a Bayes update per outcome).
void weigh(const SensingPolicy& beliefs, UnheardOutcomes unheard, BeliefNode& node,
           ActionNode& action, int a, const std::vector<double>& belief) {
  const bool commit = unheard == UnheardOutcomes::commit && !beliefs.is_terminal(a);
  if (node.weighed_belief != belief) {
    node.weighed_belief = belief;
    for (const auto& other : node.actions)
      if (other) {
        other->weighed = false;
        other->child_probability.clear();
        other->child_commit.clear();
      }
  }
  if (!action.weighed) {
    action.expected_reward = beliefs.expected_reward(belief, a);
    // Each estimate needs one of these two: share scales by the chance of going on, commit sums
    // each outcome's commit term.
    action.live_probability = commit ? 0.0 : beliefs.live_probability(belief, a);
    action.commit_after_sensing = commit ? beliefs.commit_after_sensing(belief, a) : 0.0;
    action.weighed = true;
  }
  for (std::size_t k = action.child_probability.size(); k < action.children.size(); ++k) {
    const int o = action.children[k].observation.index;
    if (commit) {
      const SensingPolicy::OutcomeTerm term = beliefs.commit_after(belief, a, o);
      action.child_probability.push_back(term.probability);
      action.child_commit.push_back(term.commit);
    } else {
      action.child_probability.push_back(beliefs.observation_probability(belief, a, o));
    }
  }
}

// Σ_o P(o | b, a) V(b after o), the heard outcomes at their children's values and the unheard as
// `unheard` says (search_tree.h); outcomes that end the episode count 0. A child every episode
// through which was revised away counts as unheard.
double future_value(const ActionNode& action, UnheardOutcomes unheard) {
  if (unheard == UnheardOutcomes::commit && !action.child_commit.empty()) {
    double future = action.commit_after_sensing;
    for (std::size_t k = 0; k < action.children.size(); ++k) {
      const ObservationChild& child = action.children[k];
      if (child.arrivals == 0) continue;
      // Committing after o is open to the child too: its value is at least that.
      const double commit = action.child_commit[k];
      future += std::max(action.child_probability[k] * child.node->value, commit) - commit;
    }
    return future;
  }
  double weighted = 0.0, seen = 0.0;
  for (std::size_t k = 0; k < action.children.size(); ++k) {
    const ObservationChild& child = action.children[k];
    if (child.arrivals == 0) continue;
    const double p = action.child_probability[k];
    weighted += p * child.node->value;
    seen += p;
  }
  return seen > 0.0 ? action.live_probability * weighted / seen : 0.0;
}

}  // namespace

double AbtSolver::action_value(BeliefNode& node, int a, const std::vector<double>* belief) const {
  ActionNode& action = *node.actions[a];
  // An action whose every episode was revised away counts as untried (NaN, as for a missing node).
  if (action.visits == 0) return std::numeric_limits<double>::quiet_NaN();
  const double gamma = model().spec().discount;
  if (!belief)
    return node.particle_reward_sums[a] / static_cast<double>(node.particles_evaluated) +
           gamma * action.future_sum / static_cast<double>(action.visits);
  // With the exact belief, the children are weighted by P(o | b, a) instead of by how often the
  // episodes happened to hear o.
  weigh(*leaf_value().belief_model(), options().unheard, node, action, a, *belief);
  return action.expected_reward + gamma * future_value(action, options().unheard);
}

void AbtSolver::refresh_child(ActionNode& action, std::size_t child) {
  ObservationChild& c = action.children[child];
  action.future_sum += static_cast<double>(c.arrivals) * (c.node->value - c.counted_value);
  c.counted_value = c.node->value;
}

void AbtSolver::recompute_node_value(BeliefNode& node) const {
  if (!node.expanded) {
    node.value = node.leaf.value();
    return;
  }
  double best = -std::numeric_limits<double>::infinity();
  for (const auto& candidate : node.actions)
    if (candidate && candidate->visits > 0) best = std::max(best, candidate->value);
  node.value = std::isfinite(best) ? best : 0.0;
}

void AbtSolver::simulate_from(Episode& episode, BeliefNode* node, pomdp::State state, int depth,
                              Rng& rng) {
  const pomdp::Model& m = model();
  for (;; ++depth) {
    const bool keep = options().keep_episodes;
    ++node->visits;
    EpisodeStep step;
    step.node = node;
    if (depth > 0) {
      node->particles.push_back(state);
      const std::vector<double>& rewards = evaluate_particle(*node, state, rng);
      if (keep) step.particle_rewards = rewards;
    }
    if (leaf_or_expand(*node, depth)) {
      std::vector<double> before;
      if (keep) before = node->leaf.sums();
      leaf_value().add(
          node->leaf,
          LeafVisit{m, state, static_cast<std::size_t>(depth), options().max_depth - depth,
                    depth > 0 ? &one_step_each_ : nullptr, &use_limits(), &path_uses_},
          rng);
      if (keep) {
        step.leaf_contribution = node->leaf.sums();
        before.resize(step.leaf_contribution.size(), 0.0);
        for (std::size_t i = 0; i < before.size(); ++i) step.leaf_contribution[i] -= before[i];
        step.state = std::move(state);
      }
      node->value = node->leaf.value();
      episode.push_back(std::move(step));
      return;
    }
    const int a = select_action(*node, path_uses_);
    use_limits().count(path_uses_, a);
    ActionNode& action = action_node(*node, a);
    pomdp::StepResult result = m.step(state, a, rng);
    ++node->action_visits;
    ++action.visits;
    step.action = a;
    step.terminal = result.terminal;
    if (keep) {
      step.observation = result.observation;
      step.reward = result.reward;
      step.state = std::move(state);
    }
    if (result.terminal) {
      episode.push_back(std::move(step));
      return;
    }
    const std::size_t child = child_for(action, result.observation);
    ObservationChild& c = action.children[child];
    ++c.arrivals;
    action.future_sum += c.counted_value;
    step.child = static_cast<std::ptrdiff_t>(child);
    episode.push_back(std::move(step));
    leaf_value().descend(static_cast<std::size_t>(depth), a, c.observation.index);
    node = c.node.get();
    state = std::move(result.next);
  }
}

void AbtSolver::backup(const Episode& episode, std::size_t last) {
  for (std::size_t i = last + 1; i-- > 0;) {
    const EpisodeStep& step = episode[i];
    BeliefNode& node = *step.node;
    if (step.action >= 0) {
      ActionNode& action = *node.actions[step.action];
      if (step.child >= 0) refresh_child(action, static_cast<std::size_t>(step.child));
      action.value = action_value(node, step.action, step_belief(i));
    }
    recompute_node_value(node);
    node.value = leaf_value().clamp(i, node.value);
  }
}

void AbtSolver::run_episode(Rng& rng) {
  // The root's particle set changes on update (replenishment), so its Q values are refreshed here:
  // every episode when they are particle means, once per improve() over an exact belief.
  BeliefNode& top = root();
  leaf_value().start_episode();
  if (root_values_stale_ || !step_belief(0))
    for (std::size_t a = 0; a < top.actions.size(); ++a)
      if (top.actions[a] && top.actions[a]->visits > 0)
        top.actions[a]->value = action_value(top, static_cast<int>(a), step_belief(0));
  root_values_stale_ = false;

  path_uses_ = path_uses_at_root();
  if (!options().keep_episodes) {
    path_.clear();
    simulate_from(path_, &top, sample_root_particle(rng), 0, rng);
    backup(path_, path_.size() - 1);
    return;
  }
  Episode episode;
  simulate_from(episode, &top, sample_root_particle(rng), 0, rng);
  backup(episode, episode.size() - 1);
  episodes_.push_back(std::move(episode));
}

void AbtSolver::remove_step(const EpisodeStep& step) {
  BeliefNode& node = *step.node;
  --node.visits;
  auto it = std::find(node.particles.begin(), node.particles.end(), step.state);
  if (it == node.particles.end())
    throw std::logic_error("AbtSolver: an episode's particle is missing from its node");
  if (it + 1 != node.particles.end()) *it = std::move(node.particles.back());
  node.particles.pop_back();
  add_particle_rewards(node, step.particle_rewards, -1.0);
  if (step.action < 0) {
    // A leaf estimate is freed when its node is expanded; until then it holds this particle.
    if (!node.expanded) node.leaf.remove(step.leaf_contribution);
    return;
  }
  --node.action_visits;
  ActionNode& action = *node.actions[step.action];
  --action.visits;
  if (step.child >= 0) {
    ObservationChild& c = action.children[static_cast<std::size_t>(step.child)];
    --c.arrivals;
    action.future_sum -= c.counted_value;
  }
}

pomdp::Observation AbtSolver::couple_observation(const pomdp::Model& before,
                                                 const EpisodeStep& step, const pomdp::State& next,
                                                 Rng& rng) const {
  const pomdp::Model& after = model();
  const double p_old = before.observation_likelihood(next, step.action, step.observation);
  const double p_new = after.observation_likelihood(next, step.action, step.observation);
  // Keep the old observation with probability min(1, p_new / p_old) ...
  if (p_old > 0.0 && uniform01(rng) * p_old < p_new) return step.observation;
  // ... otherwise draw from the excess max(0, P_new - P_old): together exactly a draw from P_new.
  const int symbols = static_cast<int>(after.spec().observation.names.size());
  std::vector<double> excess(symbols, 0.0);
  double total = 0.0;
  for (int o = 0; o < symbols; ++o) {
    const pomdp::Observation candidate{o, {}};
    excess[o] = std::max(0.0, after.observation_likelihood(next, step.action, candidate) -
                                  before.observation_likelihood(next, step.action, candidate));
    total += excess[o];
  }
  if (!(total > 0.0)) return step.observation;  // the row did not change after all
  double u = uniform01(rng) * total;
  for (int o = 0; o < symbols; ++o) {
    if (u < excess[o]) return pomdp::Observation{o, {}};
    u -= excess[o];
  }
  for (int o = symbols; o-- > 0;)
    if (excess[o] > 0.0) return pomdp::Observation{o, {}};
  return step.observation;
}

RevisionStats AbtSolver::revise(const ModelChange& change, Rng& rng) {
  if (!has_root()) throw std::logic_error("revise() before reset()");
  if (!options().keep_episodes)
    throw std::logic_error("revise() needs SearchOptions::keep_episodes: no episodes were kept");
  // The policy leaf's values come from rollouts under the old table from every node's exact
  // belief, which the table also changed: every node would need revaluing, not only those on the
  // affected episodes; the exact leaves' solver was built from the old table. Rebuilding the tree
  // is the honest cost there.
  if (leaf_value().belief_model() != nullptr)
    throw std::logic_error(std::string("revise() works with the lookahead, heuristic and rollout "
                                       "leaves; with the ") +
                           leaf_mode_name(options().leaf.mode) +
                           " leaf every node's value depends on the observation table: reset() "
                           "the solver instead");
  const pomdp::ModelPtr before = model_ptr();
  replace_model(change.model);
  const bool discrete = model().spec().observation.discrete;

  RevisionStats stats;
  stats.episodes = stored_episodes();
  for (Episode& episode : episodes_) {
    for (std::size_t k = 0; k + 1 < episode.size(); ++k) {
      EpisodeStep& step = episode[k];
      if (step.action < 0 || step.terminal) continue;
      pomdp::State next = episode[k + 1].state;
      if (!change.affects(next, step.action)) continue;
      ++stats.affected_steps;
      pomdp::Observation heard;
      if (discrete) {
        heard = couple_observation(*before, step, next, rng);
      } else {
        pomdp::StepResult result = model().step(step.state, step.action, rng);
        if (result.terminal) continue;  // dynamics are unchanged: keep what was sampled
        heard = std::move(result.observation);
        next = std::move(result.next);
      }
      BeliefNode& node = *step.node;
      ActionNode& action = *node.actions[step.action];
      const auto old_child = static_cast<std::size_t>(step.child);
      if (options().branching.same_branch(action.children[old_child].observation, heard) &&
          next == episode[k + 1].state) {
        step.observation = std::move(heard);
        ++stats.kept_observations;
        continue;
      }
      // The episode leaves through another branch: take its old continuation out of the tree,
      // revalue the nodes it passed (deepest first), then continue it with the search policy.
      ++stats.resimulated_episodes;
      for (std::size_t j = episode.size(); j-- > k + 1;) remove_step(episode[j]);
      for (std::size_t j = episode.size(); j-- > k + 1;) {
        const EpisodeStep& gone = episode[j];
        if (gone.action >= 0) {
          ActionNode& a = *gone.node->actions[gone.action];
          if (gone.child >= 0) refresh_child(a, static_cast<std::size_t>(gone.child));
          a.value = action_value(*gone.node, gone.action, nullptr);  // no policy leaf here
        }
        recompute_node_value(*gone.node);
      }
      ObservationChild& left = action.children[old_child];
      --left.arrivals;
      action.future_sum -= left.counted_value;
      refresh_child(action, old_child);
      episode.resize(k + 1);
      // The uses up to the new branch: the real episode's, then the stored steps' actions.
      path_uses_ = path_uses_at_root();
      for (const EpisodeStep& taken : episode)
        if (taken.action >= 0) use_limits().count(path_uses_, taken.action);
      step.observation = std::move(heard);
      const std::size_t child = child_for(action, step.observation);
      ObservationChild& entered = action.children[child];
      ++entered.arrivals;
      action.future_sum += entered.counted_value;
      step.child = static_cast<std::ptrdiff_t>(child);
      simulate_from(episode, entered.node.get(), std::move(next), static_cast<int>(k) + 1, rng);
      backup(episode, episode.size() - 1);
      break;  // the new continuation was sampled from the new model
    }
  }
  return stats;
}

void AbtSolver::before_reroot(const BeliefNode* kept) {
  // Episodes through the new root keep their part from it on; the rest leave with the old tree.
  std::vector<Episode> through;
  if (kept)
    for (Episode& episode : episodes_) {
      auto it = std::find_if(episode.begin(), episode.end(),
                             [kept](const EpisodeStep& s) { return s.node == kept; });
      if (it == episode.end()) continue;
      episode.erase(episode.begin(), it);
      through.push_back(std::move(episode));
    }
  episodes_ = std::move(through);
}

}  // namespace echoplan::solvers
