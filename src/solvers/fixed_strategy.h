// What the baseline strategies (baseline_strategies.h) share: a Solver that decides by a fixed rule
// from the belief over the objects and the actions taken so far, with no search.
//
// A strategy reads P(object k) from belief.discrete_marginal(0) (given in reset() and update()),
// counts the uses of each action since reset() from update()'s calls (an action is available while
// Model::max_uses(a) is 0, no limit, or above its uses, and each of its Model::prerequisites has
// been taken), and decides in improve() (the budget is
// ignored: nothing is searched). It only works on object-identification problems
// (Model::object_identification()), since its rules talk about objects, sensing and sorting.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "pomdp/object_identification_model.h"
#include "solvers/solver.h"
#include "solvers/use_limits.h"

namespace echoplan::solvers {

// "Sort" for every baseline: the sorting action most likely to be right,
//   argmax_j Σ_k b(k) · [sorting_reward[j][k] is the best sorting reward for object k],
// the first such j on ties. Not the best expected reward: a -100 for a wrong bin would otherwise
// pull the choice towards a "safe" bin that is right for fewer objects. Returns j in [0, J).
int most_likely_right_sort(const pomdp::ObjectProblemData& data,
                           const std::vector<double>& object_belief);

class FixedStrategy : public Solver {
 public:
  void reset(const pomdp::Belief& belief, Rng& rng) override;
  // Decides (decide()); the budget is ignored and no episode is simulated.
  void improve(const Budget& budget, Rng& rng) override;
  // The decision of the last improve(). Throws std::logic_error before the first one.
  int best_action() const override;
  // What the last decide() computed per action (NaN where it computed nothing).
  std::vector<double> root_action_values() const override { return values_; }
  void update(int action, const pomdp::Observation& observation, const pomdp::Belief& belief_after,
              Rng& rng) override;
  // All zero: there is no tree and no episode.
  SolverStats stats() const override { return {}; }

 protected:
  // Throws InputError naming `strategy` when `model` is not an object-identification problem.
  FixedStrategy(const std::string& strategy, pomdp::ModelPtr model);

  // The action to take now, from objects() and uses(). May fill values(), which improve() has
  // reset to NaN; `rng` is the one improve() was given.
  virtual int decide(Rng& rng) = 0;

  const pomdp::ObjectIdentificationModel& problem() const { return *problem_; }
  const std::vector<double>& objects() const { return objects_; }  // P(object k), k < K
  int uses(int action) const { return uses_[action]; }
  bool available(int action) const;
  std::vector<int> available_sensing() const;  // in the problem's order
  // The next step towards `action`: itself when available, else the first prerequisite on its way
  // not yet taken that is available (depth first); -1 when none is (used up).
  int toward(int action) const;
  // The prerequisites of `action`, theirs, and so on, each once.
  std::vector<int> all_prerequisites(int action) const;
  int sort_action() const;  // the model's index of most_likely_right_sort()
  std::vector<double>& values() { return values_; }

 private:
  void read_belief(const pomdp::Belief& belief);

  pomdp::ModelPtr model_;
  const pomdp::ObjectIdentificationModel* problem_ = nullptr;
  UseLimits limits_;
  std::vector<double> objects_;
  UseCounts uses_;  // every action's uses since reset() (all_actions reads them without limits)
  std::vector<double> values_;
  int decision_ = -1;
};

}  // namespace echoplan::solvers
