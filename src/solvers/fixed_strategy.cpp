#include "solvers/fixed_strategy.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "common/error.h"

namespace echoplan::solvers {

int most_likely_right_sort(const pomdp::ObjectProblemData& data,
                           const std::vector<double>& object_belief) {
  const int J = static_cast<int>(data.sorting.size());
  const int K = static_cast<int>(data.objects.size());
  std::vector<double> best_reward(K, -std::numeric_limits<double>::infinity());
  for (int j = 0; j < J; ++j)
    for (int k = 0; k < K; ++k)
      best_reward[k] = std::max(best_reward[k], data.sorting_reward[j][k]);
  int chosen = 0;
  double chosen_right = -1.0;
  for (int j = 0; j < J; ++j) {
    double right = 0.0;  // P(sorting action j is right)
    for (int k = 0; k < K; ++k)
      if (data.sorting_reward[j][k] == best_reward[k]) right += object_belief[k];
    if (right > chosen_right) chosen = j, chosen_right = right;
  }
  return chosen;
}

FixedStrategy::FixedStrategy(const std::string& strategy, pomdp::ModelPtr model)
    : model_(std::move(model)) {
  problem_ = model_->object_identification();
  if (problem_ == nullptr)
    throw InputError(
        "strategy '" + strategy + "' needs an object-identification problem (objects, " +
        "sensing and sorting actions: it decides from the belief over the objects and " +
        "sorts into a bin), and '" + model_->spec().name + "' is not one");
  limits_ = UseLimits(*model_);
  uses_.assign(model_->num_actions(), 0);
  values_.assign(model_->num_actions(), std::numeric_limits<double>::quiet_NaN());
}

void FixedStrategy::read_belief(const pomdp::Belief& belief) {
  objects_ = belief.discrete_marginal(0);
  if (objects_.size() != problem_->data().objects.size())
    throw std::invalid_argument("FixedStrategy: the belief is not over the problem's objects");
}

void FixedStrategy::reset(const pomdp::Belief& belief, Rng& /*rng*/) {
  read_belief(belief);
  uses_.assign(uses_.size(), 0);
  decision_ = -1;
}

void FixedStrategy::improve(const Budget& /*budget*/, Rng& rng) {
  values_.assign(values_.size(), std::numeric_limits<double>::quiet_NaN());
  decision_ = decide(rng);
}

int FixedStrategy::best_action() const {
  if (decision_ < 0) throw std::logic_error("FixedStrategy: best_action() before improve()");
  return decision_;
}

void FixedStrategy::update(int action, const pomdp::Observation& /*observation*/,
                           const pomdp::Belief& belief_after, Rng& /*rng*/) {
  ++uses_.at(action);
  read_belief(belief_after);
  decision_ = -1;
}

bool FixedStrategy::available(int action) const { return limits_.allows(uses_, action); }

std::vector<int> FixedStrategy::available_sensing() const {
  std::vector<int> actions;
  for (int a = 0; a < problem_->num_sensing(); ++a)
    if (available(a)) actions.push_back(a);
  return actions;
}

int FixedStrategy::toward(int action) const {
  if (available(action)) return action;
  if (limits_.max_uses(action) > 0 && uses_[action] >= limits_.max_uses(action)) return -1;
  for (int r : limits_.prerequisites(action))
    if (uses_[r] == 0)
      if (const int next = toward(r); next >= 0) return next;
  return -1;
}

std::vector<int> FixedStrategy::all_prerequisites(int action) const {
  std::vector<int> found;
  std::vector<int> open = limits_.prerequisites(action);
  while (!open.empty()) {
    const int r = open.back();
    open.pop_back();
    if (std::find(found.begin(), found.end(), r) != found.end()) continue;
    found.push_back(r);
    for (int q : limits_.prerequisites(r)) open.push_back(q);
  }
  return found;
}

int FixedStrategy::sort_action() const {
  return problem_->num_sensing() + most_likely_right_sort(problem_->data(), objects_);
}

}  // namespace echoplan::solvers
