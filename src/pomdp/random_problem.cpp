#include "pomdp/random_problem.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <stdexcept>

namespace echoplan::pomdp {

namespace {

constexpr double kResolution = 1e-4;

// Zero-padded names so files list objects in order: object_01 ... object_64.
std::string numbered(const char* prefix, int i, int count) {
  const int width = static_cast<int>(std::to_string(count).size());
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%s_%0*d", prefix, width, i + 1);
  return buffer;
}

// A Dirichlet draw (normalised gamma variates), rounded to kResolution with a floor of
// kResolution; entry `keep` absorbs the rounding so the row sums to 1.
std::vector<double> dirichlet_row(const std::vector<double>& alpha, int keep, Rng& rng) {
  std::vector<double> row(alpha.size());
  double total = 0.0;
  for (std::size_t i = 0; i < alpha.size(); ++i) {
    std::gamma_distribution<double> gamma(alpha[i], 1.0);
    row[i] = gamma(rng);
    total += row[i];
  }
  long long units_left = std::llround(1.0 / kResolution);
  std::vector<long long> units(row.size());
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (static_cast<int>(i) == keep) continue;
    units[i] = std::max<long long>(1, std::llround(row[i] / total / kResolution));
    units_left -= units[i];
  }
  units[keep] = units_left;
  // The true class keeps at least its floor: take any excess back from the largest other entries.
  while (units[keep] < 1) {
    auto largest = std::max_element(units.begin(), units.end());
    --*largest;
    ++units[keep];
  }
  for (std::size_t i = 0; i < row.size(); ++i)
    row[i] = static_cast<double>(units[i]) /
             10000.0;  // division gives the double nearest the 4-decimal value
  return row;
}

}  // namespace

ObjectProblemData make_random_object_problem(const RandomProblemSettings& s, Rng& rng) {
  if (s.objects < 2) throw std::invalid_argument("a problem needs at least 2 objects");
  if (s.objects > 1000) throw std::invalid_argument("at most 1000 objects");
  if (s.sensing_actions < 1 || s.sensing_actions > 100)
    throw std::invalid_argument("1 to 100 sensing actions");
  if (!(s.concentration > 0.0) || !std::isfinite(s.concentration)) {
    throw std::invalid_argument("concentration must be positive");
  }
  if (s.bins < 2 || s.bins > 26 || s.bins > s.objects)
    throw std::invalid_argument("2 to 26 sorting bins, and no more bins than objects");
  if (s.objects * kResolution > 0.5)
    throw std::invalid_argument("too many objects for 4-decimal rows");
  ObjectProblemData d;
  d.name = "random_" + std::to_string(s.objects) + "_objects_" + std::to_string(s.sensing_actions) +
           "_actions_seed_" + std::to_string(s.seed);
  d.discount = 0.99;
  for (int k = 0; k < s.objects; ++k) d.objects.push_back(numbered("object", k, s.objects));
  d.observation_symbols = d.objects;
  d.prior.assign(s.objects, 1.0 / s.objects);
  d.initial_joints = {-2.89527, 1.45058, -0.18396, 2.07696, -0.310356, 0.630897, -1.54233};
  d.initial_offset = {0.1, 0.0, 0.0};
  for (int a = 0; a < s.sensing_actions; ++a)
    d.sensing.push_back(SensingAction{numbered("sense", a, s.sensing_actions)});
  for (int j = 0; j < s.bins; ++j) d.sorting.push_back(std::string("move_to_") + char('A' + j));

  const double diagonal = s.concentration * (s.objects - 1);
  d.observation_table.assign(s.sensing_actions, {});
  for (int a = 0; a < s.sensing_actions; ++a) {
    for (int k = 0; k < s.objects; ++k) {
      std::vector<double> alpha(s.objects, 1.0);
      alpha[k] = diagonal;
      d.observation_table[a].push_back(dirichlet_row(alpha, k, rng));
    }
  }

  // Groups: objects in a uniformly random order, floor(K / J) to each bin but the last, which takes
  // the rest (with 2 bins: a random half, rounded down, goes to A).
  std::vector<int> order(s.objects);
  std::iota(order.begin(), order.end(), 0);
  for (int i = s.objects - 1; i > 0; --i) {
    const int j = static_cast<int>(uniform01(rng) * (i + 1));
    std::swap(order[i], order[std::min(j, i)]);
  }
  const int group = s.objects / s.bins;
  d.sorting_reward.assign(s.bins, std::vector<double>(s.objects, -100.0));
  for (int i = 0; i < s.objects; ++i)
    d.sorting_reward[std::min(s.bins - 1, i / group)][order[i]] = 10.0;
  return d;
}

}  // namespace echoplan::pomdp
