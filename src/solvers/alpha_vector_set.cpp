#include "solvers/alpha_vector_set.h"

#include <algorithm>
#include <limits>

namespace echoplan::solvers {

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

namespace {

bool dominates(const std::vector<double>& a, const std::vector<double>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] < b[i]) return false;
  }
  return true;
}

}  // namespace

bool AlphaVectorSet::add(AlphaVector vector) {
  for (const AlphaVector& existing : vectors_) {
    if (dominates(existing.values, vector.values)) return false;
  }
  // The new vector is not dominated; the ones it dominates can never be the maximum again.
  std::erase_if(vectors_, [&](const AlphaVector& existing) {
    return dominates(vector.values, existing.values);
  });
  vectors_.push_back(std::move(vector));
  return true;
}

int AlphaVectorSet::best_index(const BeliefVector& belief) const {
  int best = 0;
  double best_value = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < vectors_.size(); ++i) {
    const double v = dot(vectors_[i].values, belief);
    if (v > best_value) {
      best_value = v;
      best = static_cast<int>(i);
    }
  }
  return best;
}

double AlphaVectorSet::value(const BeliefVector& belief) const {
  return dot(vectors_[best_index(belief)].values, belief);
}

}  // namespace echoplan::solvers
