// Tiny object-identification problems whose numbers are easy to work by hand, and a belief that is
// whatever a test says it is, for the baseline strategies' tests.
#pragma once

#include <memory>
#include <vector>

#include "pomdp/belief.h"
#include "pomdp/object_identification_model.h"

namespace echoplan::solvers::testing {

// Two objects a, b (uniform prior), symbols named like them, discount 0.99.
// Sensing actions (reward -1 each, no collisions), P(symbol | object) rows:
//   0 tap    a: [0.6, 0.4]  b: [0.4, 0.6]   accuracy 0.5·0.6 + 0.5·0.6 = 0.60
//   1 press  a: [0.9, 0.1]  b: [0.2, 0.8]   accuracy 0.5·0.9 + 0.5·0.8 = 0.85
//   2 shake  a: [0.7, 0.3]  b: [0.3, 0.7]   accuracy 0.5·0.7 + 0.5·0.7 = 0.70
// Sorting actions: 3 to_a (+10 for a, -100 for b), 4 to_b (-100 for a, +10 for b).
inline pomdp::ObjectProblemData two_objects() {
  pomdp::ObjectProblemData d;
  d.name = "two_objects";
  d.discount = 0.99;
  d.objects = {"a", "b"};
  d.prior = {0.5, 0.5};
  d.sensing = {{"tap", -1.0}, {"press", -1.0}, {"shake", -1.0}};
  d.sorting = {"to_a", "to_b"};
  d.observation_symbols = {"a", "b"};
  d.observation_table = {
      {{0.6, 0.4}, {0.4, 0.6}}, {{0.9, 0.1}, {0.2, 0.8}}, {{0.7, 0.3}, {0.3, 0.7}}};
  d.sorting_reward = {{10, -100}, {-100, 10}};
  return d;
}

// Three objects x, y, z (uniform prior) and one sensing action (listen, perfect, reward -1);
// sorting: 1 to_A (+10 for x, -100 for y and z), 2 to_B (-10 for x, +10 for y and z): a wrong B
// costs little, so the best expected reward and the bin most likely right can differ.
inline pomdp::ObjectProblemData three_objects() {
  pomdp::ObjectProblemData d;
  d.name = "three_objects";
  d.objects = {"x", "y", "z"};
  d.prior = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  d.sensing = {{"listen", -1.0}};
  d.sorting = {"to_A", "to_B"};
  d.observation_symbols = {"x", "y", "z"};
  d.observation_table = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  d.sorting_reward = {{10, -100, -100}, {-10, 10, 10}};
  return d;
}

// Four objects a1, a2 (bin A) and b1, b2 (bin B), uniform prior, symbols x, y, discount 0.99,
// where the sort is coarser than the identity. Sensing actions (reward -1 each, no collisions):
//   0 split  tells a1 from a2 for sure, says nothing of b1, b2:
//            a1 [1, 0]  a2 [0, 1]  b1 [0.5, 0.5]  b2 [0.5, 0.5]
//   1 bins   tells the bins apart, wrong one time in five:
//            a1, a2 [0.8, 0.2]  b1, b2 [0.2, 0.8]
// Sorting: 2 to_A (+10 for a1, a2; -100 for b1, b2), 3 to_B (the other way round).
inline pomdp::ObjectProblemData four_objects() {
  pomdp::ObjectProblemData d;
  d.name = "four_objects";
  d.discount = 0.99;
  d.objects = {"a1", "a2", "b1", "b2"};
  d.prior = {0.25, 0.25, 0.25, 0.25};
  d.sensing = {{"split", -1.0}, {"bins", -1.0}};
  d.sorting = {"to_A", "to_B"};
  d.observation_symbols = {"x", "y"};
  d.observation_table = {{{1, 0}, {0, 1}, {0.5, 0.5}, {0.5, 0.5}},
                         {{0.8, 0.2}, {0.8, 0.2}, {0.2, 0.8}, {0.2, 0.8}}};
  d.sorting_reward = {{10, 10, -100, -100}, {-100, -100, 10, 10}};
  return d;
}

inline pomdp::ModelPtr model_of(pomdp::ObjectProblemData data) {
  return std::make_shared<pomdp::ObjectIdentificationModel>(std::move(data));
}

// A belief over the objects that is what the test sets (it never updates itself).
class GivenBelief final : public pomdp::Belief {
 public:
  explicit GivenBelief(std::vector<double> objects) : objects_(std::move(objects)) {}
  pomdp::State sample(Rng& /*rng*/) const override { return {{}, {0}}; }
  bool update(int, const pomdp::Observation&, Rng&) override { return true; }
  std::vector<double> discrete_marginal(int /*variable*/) const override { return objects_; }
  std::unique_ptr<pomdp::Belief> clone() const override {
    return std::make_unique<GivenBelief>(*this);
  }

 private:
  std::vector<double> objects_;
};

}  // namespace echoplan::solvers::testing
