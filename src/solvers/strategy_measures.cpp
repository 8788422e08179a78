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

std::vector<int> decision_regions(const pomdp::ObjectProblemData& data) {
  std::vector<int> region(data.objects.size(), 0);
  for (std::size_t k = 0; k < region.size(); ++k)
    for (std::size_t j = 1; j < data.sorting_reward.size(); ++j)
      if (data.sorting_reward[j][k] > data.sorting_reward[region[k]][k])
        region[k] = static_cast<int>(j);
  return region;
}

EdgeCut::EdgeCut(const pomdp::ObjectProblemData& data)
    : region_(decision_regions(data)),
      num_regions_(static_cast<int>(data.sorting.size())),
      num_symbols_(static_cast<int>(data.observation_symbols.size())) {
  const int K = static_cast<int>(data.objects.size()), C = num_symbols_;
  for (std::size_t a = 0; a < data.sensing.size(); ++a) {
    std::vector<double> table(K * C), consistency(K * C), offset(C, 0.0);
    for (int k = 0; k < K; ++k) {
      const std::vector<double>& row = data.observation_table[a][k];
      const double likeliest = *std::max_element(row.begin(), row.end());
      for (int o = 0; o < C; ++o) {
        table[k * C + o] = row[o];
        consistency[k * C + o] = likeliest > 0.0 ? row[o] / likeliest : 0.0;
        offset[o] = std::max(offset[o], consistency[k * C + o]);
      }
    }
    for (double& m : offset) m *= m;
    table_.push_back(std::move(table));
    consistency_.push_back(std::move(consistency));
    offset_.push_back(std::move(offset));
    always_collides_.push_back(data.sensing[a].collision_probability >= 1.0);
  }
}

double EdgeCut::cross_mass(const std::vector<double>& w) const {
  region_sum_.assign(num_regions_, 0.0);
  double total = 0.0;
  for (std::size_t k = 0; k < w.size(); ++k) region_sum_[region_[k]] += w[k], total += w[k];
  double within = 0.0;
  for (double r : region_sum_) within += r * r;
  return std::max(0.0, 0.5 * (total * total - within));
}

double EdgeCut::edge_mass(const std::vector<double>& objects) const { return cross_mass(objects); }

double EdgeCut::expected_cut(const std::vector<double>& objects, int a) const {
  if (always_collides_.at(a)) return 0.0;
  const std::vector<double>& table = table_[a];
  const std::vector<double>& consistency = consistency_[a];
  const std::size_t K = objects.size(), C = num_symbols_;
  const double mass = cross_mass(objects);
  double cut = 0.0;
  weighted_.resize(K);
  for (std::size_t o = 0; o < C; ++o) {
    double p = 0.0;  // P(o | b, a)
    for (std::size_t k = 0; k < K; ++k) {
      p += objects[k] * table[k * C + o];
      weighted_[k] = objects[k] * consistency[k * C + o];
    }
    if (p > 0.0) cut += p * (offset_[a][o] * mass - cross_mass(weighted_));
  }
  return cut;
}

}  // namespace echoplan::solvers
