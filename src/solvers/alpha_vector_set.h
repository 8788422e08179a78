// A lower bound on V*: a set of alpha vectors, each the value of a conditional plan starting with
// its action. V*(b) >= max_alpha alpha . b, and acting greedily on these vectors earns at least
// that. Used by the offline point-based solver and the exact identification solver.
#pragma once

#include <vector>

namespace echoplan::solvers {

// A belief as a vector of probabilities, one per state, summing to 1.
using BeliefVector = std::vector<double>;

struct AlphaVector {
  int action = 0;              // the plan's first action
  std::vector<double> values;  // [s]: the plan's expected discounted reward from state s
};

class AlphaVectorSet {
 public:
  // Adds `vector` unless an existing vector dominates it pointwise, and removes the vectors it
  // dominates pointwise. Returns true when it was added.
  bool add(AlphaVector vector);

  // Index of the vector with the highest value at `belief`; the set must not be empty.
  int best_index(const BeliefVector& belief) const;
  double value(const BeliefVector& belief) const;
  // The first action of the best plan at `belief`.
  int best_action(const BeliefVector& belief) const { return vectors_[best_index(belief)].action; }

  const std::vector<AlphaVector>& vectors() const { return vectors_; }
  std::size_t size() const { return vectors_.size(); }

 private:
  std::vector<AlphaVector> vectors_;
};

double dot(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace echoplan::solvers
