#include "solvers/strategy_measures.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace echoplan::solvers {

namespace {

// The symbol named like each object, or -1.
std::vector<int> symbols_named_like_objects(const pomdp::ObjectProblemData& data) {
  std::vector<int> symbol(data.objects.size(), -1);
  for (std::size_t k = 0; k < data.objects.size(); ++k) {
    const auto& names = data.observation_symbols;
    const auto found = std::find(names.begin(), names.end(), data.objects[k]);
    if (found != names.end()) symbol[k] = static_cast<int>(found - names.begin());
  }
  return symbol;
}

double entropy(const std::vector<double>& p) {
  double h = 0.0;
  for (double x : p)
    if (x > 0.0) h -= x * std::log(x);
  return h;
}

}  // namespace

double held_out_accuracy(const pomdp::ObjectProblemData& data, int a) {
  const auto& table = data.observation_table.at(a);
  const std::vector<int> symbol = symbols_named_like_objects(data);
  const bool named = std::any_of(symbol.begin(), symbol.end(), [](int o) { return o >= 0; });
  double accuracy = 0.0;
  if (named) {
    for (std::size_t k = 0; k < symbol.size(); ++k)
      if (symbol[k] >= 0) accuracy += data.prior[k] * table[k][symbol[k]];
    return accuracy;
  }
  for (std::size_t o = 0; o < data.observation_symbols.size(); ++o) {
    double best = 0.0;
    for (std::size_t k = 0; k < data.objects.size(); ++k)
      best = std::max(best, data.prior[k] * table[k][o]);
    accuracy += best;
  }
  return accuracy;
}

double single_action_value(const pomdp::ObjectProblemData& data, int a) {
  double right = 0.0, wrong = 0.0;
  for (std::size_t k = 0; k < data.objects.size(); ++k) {
    double best = -std::numeric_limits<double>::infinity();
    double worst = std::numeric_limits<double>::infinity();
    for (const std::vector<double>& bin : data.sorting_reward)
      best = std::max(best, bin[k]), worst = std::min(worst, bin[k]);
    right += data.prior[k] * best;
    wrong += data.prior[k] * worst;
  }
  const double accuracy = held_out_accuracy(data, a);
  // wrong + accuracy (right − wrong), not accuracy right + (1 − accuracy) wrong: each operation is
  // then monotone in the accuracy even when rounded, so equal costs order exactly as accuracy does.
  return data.sensing.at(a).reward + data.discount * (wrong + accuracy * (right - wrong));
}

OneStepLookahead::OneStepLookahead(const pomdp::ObjectIdentificationModel& model)
    : tables_(*model.tabular()),
      num_observations_(model.tabular()->num_observations()),
      discount_(model.spec().discount) {}

std::vector<double> OneStepLookahead::states(const std::vector<double>& objects) const {
  std::vector<double> b = objects;
  b.push_back(0.0);  // the absorbing 'done' state holds no belief
  return b;
}

double OneStepLookahead::expected_reward(const std::vector<double>& objects, int action) const {
  return tables_.expected_reward(states(objects), action);
}

double OneStepLookahead::commit_value(const std::vector<double>& objects) const {
  return tables_.commit_value(states(objects));
}

double OneStepLookahead::sense_then_commit_value(const std::vector<double>& objects, int a) const {
  const std::vector<double> b = states(objects);
  return tables_.expected_reward(b, a) + discount_ * tables_.commit_after_sensing(b, a);
}

double OneStepLookahead::expected_entropy_reduction(const std::vector<double>& objects,
                                                    int a) const {
  const std::vector<double> b = states(objects);
  const double live = tables_.live_probability(b, a);
  if (live <= 0.0) return 0.0;
  double after = 0.0;
  for (int o = 0; o < num_observations_; ++o) {
    const double p = tables_.update(b, a, o, after_);
    if (p > 0.0) after += p / live * entropy(after_);
  }
  return entropy(b) - after;
}

}  // namespace echoplan::solvers
