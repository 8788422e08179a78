#include "solvers/offline/offline_policy_solver.h"

#include <stdexcept>

#include "common/error.h"
#include "solvers/offline/belief_expansion.h"
#include "solvers/offline/policy_file.h"
#include "solvers/use_limits.h"

namespace echoplan::solvers::offline {

OfflinePolicySolver::OfflinePolicySolver(pomdp::ModelPtr model,
                                         std::shared_ptr<const FlatPomdp> pomdp,
                                         AlphaVectorSet vectors)
    : model_(std::move(model)), pomdp_(std::move(pomdp)), vectors_(std::move(vectors)) {
  const pomdp::TabularModel* tables = model_ ? model_->tabular() : nullptr;
  if (tables == nullptr) throw std::invalid_argument("OfflinePolicySolver needs a tabular model");
  if (tables->num_states() != pomdp_->num_states || tables->num_actions() != pomdp_->num_actions) {
    throw std::invalid_argument("OfflinePolicySolver: the tables and the solved model differ");
  }
  if (vectors_.size() == 0) throw std::invalid_argument("OfflinePolicySolver needs alpha vectors");
  for (const AlphaVector& v : vectors_.vectors()) {
    if (static_cast<int>(v.values.size()) != pomdp_->num_states || v.action < 0 ||
        v.action >= pomdp_->num_actions) {
      throw std::invalid_argument("OfflinePolicySolver: a vector does not fit the model");
    }
  }
  belief_ = std::make_unique<pomdp::ExactBelief>(model_);
}

void OfflinePolicySolver::reset(const pomdp::Belief& belief, Rng& /*rng*/) {
  const std::vector<double>* exact = belief.exact_probabilities();
  if (exact != nullptr && static_cast<int>(exact->size()) == pomdp_->num_states) {
    belief_ = belief.clone();
  } else {
    belief_ = std::make_unique<pomdp::ExactBelief>(model_);
  }
}

void OfflinePolicySolver::improve(const Budget& /*budget*/, Rng& /*rng*/) {}

int OfflinePolicySolver::best_action() const { return vectors_.best_action(belief()); }

std::vector<double> OfflinePolicySolver::root_action_values() const {
  std::vector<double> q(pomdp_->num_actions);
  for (int a = 0; a < pomdp_->num_actions; ++a) {
    const BeliefExpansion children = expand(*pomdp_, belief(), a);
    double future = 0.0;
    for (int o = 0; o < pomdp_->num_observations; ++o) {
      const double p = children.observation_probability[o];
      if (p > 0.0) future += p * vectors_.value(children.next_belief[o]);
    }
    q[a] = expected_reward(*pomdp_, belief(), a) + pomdp_->discount * future;
  }
  return q;
}

void OfflinePolicySolver::update(int action, const pomdp::Observation& observation,
                                 const pomdp::Belief& /*belief_after*/, Rng& rng) {
  belief_->update(action, observation, rng);
}

std::unique_ptr<Solver> make_offline_solver(const pomdp::ModelPtr& model,
                                            const SolverOptions& options,
                                            const std::string& policy_path,
                                            const std::string& source) {
  const pomdp::TabularModel* tables = model->tabular();
  if (tables == nullptr) {
    throw InputError(source, 0,
                     "the offline solver needs a problem with tables (discrete states, "
                     "actions and observations)");
  }
  // Its alpha vectors are over beliefs alone; a use limit or a prerequisite makes the value
  // depend on the history.
  if (UseLimits(*model).any())
    throw InputError(source, 0,
                     "the offline solver does not support per-action use limits or prerequisites "
                     "(actions.uses, actions.requires); use --solver abt or pomcp");
  auto flat = std::make_shared<const FlatPomdp>(make_flat_pomdp(*tables, source));
  if (!policy_path.empty()) {
    return std::make_unique<OfflinePolicySolver>(model, flat, load_policy(policy_path, *flat));
  }
  PointBasedSolver solver(flat, options);
  solver.solve();
  return std::make_unique<OfflinePolicySolver>(model, flat, solver.lower_bound());
}

}  // namespace echoplan::solvers::offline
