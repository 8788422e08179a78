#include "solvers/baseline_strategies.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"
#include "solvers/fixed_strategy.h"
#include "solvers/strategy_measures.h"

namespace echoplan::solvers {

namespace {

class AllActions final : public FixedStrategy {
 public:
  explicit AllActions(pomdp::ModelPtr model) : FixedStrategy("all_actions", std::move(model)) {}

 private:
  int decide(Rng& /*rng*/) override {
    for (int a : available_sensing())
      if (uses(a) == 0) return a;
    return sort_action();
  }
};

class BestSingle final : public FixedStrategy {
 public:
  explicit BestSingle(pomdp::ModelPtr model)
      : FixedStrategy("best_single", std::move(model)), lookahead_(problem()) {
    // By value, cost included; equal values (equal costs and accuracy) go to the more accurate,
    // so that with one cost for every action the choice is the most accurate one.
    double best_value = -std::numeric_limits<double>::infinity(), best_accuracy = -1.0;
    // A behaviour that waits for others (Model::prerequisites) costs theirs too.
    for (int a = 0; a < problem().num_sensing(); ++a) {
      double value = single_action_value(problem().data(), a);
      for (int r : all_prerequisites(a)) value += problem().data().sensing[r].reward;
      const double accuracy = held_out_accuracy(problem().data(), a);
      if (value > best_value || (value == best_value && accuracy > best_accuracy))
        best_value = value, best_accuracy = accuracy, action_ = a;
    }
  }

 private:
  int decide(Rng& /*rng*/) override {
    const int next = toward(action_);
    if (next < 0) return sort_action();  // used up
    if (next != action_) return next;    // a prerequisite on its way
    if (problem().max_uses(action_) > 0) return action_;
    const double look = lookahead_.sense_then_commit_value(objects(), action_);
    values()[action_] = look;
    return look > lookahead_.commit_value(objects()) ? action_ : sort_action();
  }

  OneStepLookahead lookahead_;
  int action_ = 0;
};

// information_gain and decision_region: the same commit rule and cost normalisation, so the two
// differ only in gain(), what one performance of a sensing action is expected to tell.
class GreedyPerCost : public FixedStrategy {
 protected:
  GreedyPerCost(const std::string& name, pomdp::ModelPtr model)
      : FixedStrategy(name, std::move(model)), lookahead_(problem()) {}

  virtual double gain(int a) const = 0;  // at objects()
  const OneStepLookahead& lookahead() const { return lookahead_; }

 private:
  int decide(Rng& /*rng*/) override {
    const std::vector<int> sensing = available_sensing();
    if (sensing.empty()) return sort_action();
    const int M = problem().num_sensing(),
              A = M + static_cast<int>(problem().data().sorting.size());
    for (int a = M; a < A; ++a) values()[a] = lookahead_.expected_reward(objects(), a);
    const double commit = lookahead_.commit_value(objects());
    double best_look = -std::numeric_limits<double>::infinity();
    for (int a : sensing)
      best_look =
          std::max(best_look, values()[a] = lookahead_.sense_then_commit_value(objects(), a));
    if (commit >= best_look) return sort_action();
    return greatest_gain_per_cost(sensing);
  }

  int greatest_gain_per_cost(const std::vector<int>& sensing) const {
    int chosen = sensing.front();
    double chosen_rate = -std::numeric_limits<double>::infinity();
    for (int a : sensing) {
      const double cost = std::abs(problem().data().sensing[a].reward);
      const double rate = cost > 0.0 ? gain(a) / cost : gain(a);
      if (rate > chosen_rate) chosen = a, chosen_rate = rate;
    }
    return chosen;
  }

  OneStepLookahead lookahead_;
};

class InformationGain final : public GreedyPerCost {
 public:
  explicit InformationGain(pomdp::ModelPtr model)
      : GreedyPerCost("information_gain", std::move(model)) {}

 private:
  double gain(int a) const override { return lookahead().expected_entropy_reduction(objects(), a); }
};

class DecisionRegion final : public GreedyPerCost {
 public:
  explicit DecisionRegion(pomdp::ModelPtr model)
      : GreedyPerCost("decision_region", std::move(model)), cut_(problem().data()) {}

 private:
  double gain(int a) const override { return cut_.expected_cut(objects(), a); }

  EdgeCut cut_;
};

class RandomChoice final : public FixedStrategy {
 public:
  explicit RandomChoice(pomdp::ModelPtr model) : FixedStrategy("random", std::move(model)) {}

 private:
  int decide(Rng& rng) override {
    const std::vector<int> sensing = available_sensing();
    if (sensing.empty()) return sort_action();
    // Choice n (one past the sensing actions) is "sort now".
    const std::size_t n = sensing.size();
    const auto pick = std::min(n, static_cast<std::size_t>(uniform01(rng) * (n + 1)));
    return pick == n ? sort_action() : sensing[pick];
  }
};

}  // namespace

std::vector<std::string> strategy_names() {
  return {"all_actions", "best_single", "decision_region", "information_gain", "random"};
}

bool is_strategy(const std::string& name) {
  const auto names = strategy_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::unique_ptr<Solver> make_strategy(const std::string& name, pomdp::ModelPtr model) {
  if (name == "all_actions") return std::make_unique<AllActions>(std::move(model));
  if (name == "best_single") return std::make_unique<BestSingle>(std::move(model));
  if (name == "decision_region") return std::make_unique<DecisionRegion>(std::move(model));
  if (name == "information_gain") return std::make_unique<InformationGain>(std::move(model));
  if (name == "random") return std::make_unique<RandomChoice>(std::move(model));
  throw InputError(
      fmt::format("strategy '{}' is not one of {}", name, fmt::join(strategy_names(), ", ")));
}

}  // namespace echoplan::solvers
