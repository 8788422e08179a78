// An upper bound on V* for identification problems whose sensing actions all have use limits:
// an agent told, at once, every reading the limits still allow can only do better.
//
// Why it holds. After some uses, at most k readings are left (Σ_a limit(a) − uses(a)). A policy
// at belief b either sorts now or senses first; then its sort comes at a step t in [1, k] and
// depends on some of those readings. An agent told all k outcomes before it sorts (an information
// relaxation, Brown, Smith & Sun 2010) earns at least as much, and the sensing after the first
// only costs, so
//   V*(b) <= max( commit now,
//                 max_{a allowed} R(b, a) + E_{o_1..o_k}[ max_t Σ_s b(s) P(o_1..o_k | s) r̂(s, t) ]
//                 )
// with r̂ = γ r where r >= 0 and γ^k r where r < 0 (the least and most a sort at a step in [1, k]
// is discounted). The pair relaxation and "one more sensing" assume sensing can go on until the
// state is known; with few behaviours left and several objects still likely, this bound sees that
// it cannot (docs/BENCHMARKS.md, "ABT, the exact solver and certify at 20 and 100 classes").
//
// Where it applies: every sensing action has a limit, no sensing reward is positive and no
// sensing action can end the episode (a collision); otherwise applies() is false.
//
// Cost. The outcomes form a tree of O^k leaves. It is refined best first from the root: a node is
// a partial outcome sequence with its weights Σ_s b(s) P(outcomes so far | s) over the belief's
// main support, valued until it is expanded as if its state were then known (which can only
// raise the value); the node whose known-state value exceeds its best sort the most is expanded
// next, up to a budget of expansions. States below the main support are valued as known too: the
// relaxed value is convex and positively homogeneous in b, so it is subadditive over a split of
// b. Every cut only raises the result, so the bound is sound at any budget; with budget 0 it is
// "one more sensing" (the state known after one reading).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "solvers/identification_tables.h"

namespace echoplan::solvers {

struct ReadingsLeftOptions {
  // Expansions of the outcome tree per evaluation (each costs observations × support states).
  // 16, with max_readings 3: on 20 classes with 9 behaviours used once each, certify's looseness
  // on its deepest trials fell 10% for 1.4x the time (docs/BENCHMARKS.md); 64 and 4: 13% for
  // 3.9x.
  int budget = 16;
  // Only beliefs with at most this many readings left are bounded (others get +inf): with more,
  // the readings tell the object apart nearly surely, and the bound is no lower than one more
  // sensing's, at a cost per belief that grows with the readings.
  int max_readings = 3;
  // The main support: the most likely states, at most this many, each at least this likely.
  int max_support = 16;
  double min_probability = 1e-4;
};

class ReadingsLeftBound {
 public:
  ReadingsLeftBound() = default;
  ReadingsLeftBound(std::shared_ptr<const IdentificationTables> tables,
                    const ReadingsLeftOptions& options = {});

  // True when the problem has the shape the bound needs (see the header comment).
  bool applies() const { return applies_; }
  // An upper bound on V*(b) at a belief over the live states (normalised) after `uses` (per
  // action; null: none); +inf when the bound does not apply or more than max_readings are left.
  double value(const double* belief, const std::uint16_t* uses) const;

 private:
  // The relaxed value of the readings in readings_ from weights `w` over support_ (see the .cpp).
  double told_all_value(const double* w) const;
  // Over the support: the best sort's value at weights w, and the value if the state were known.
  double best_sort(const double* w) const;
  double known(const double* w) const;
  // A terminal action's r̂ in live state l, a wrong sort discounted by `discount_left` (γ^k for k
  // readings left; see the header comment).
  double relaxed(int terminal, int l, double discount_left) const;
  // The per-call tables, in order: support_ and known_ from belief b (returns the tail's
  // known-state value), the sorts over the support, the readings left after `uses`.
  double read_support(const double* b, double discount_left) const;
  void read_sorts(double discount_left) const;
  void read_readings(const std::uint16_t* uses) const;

  std::shared_ptr<const IdentificationTables> tables_;
  ReadingsLeftOptions options_;
  bool applies_ = false;
  std::vector<int> sensing_, terminals_;
  // Per call (mutable scratch space; the bound is not thread-safe, as its user is not):
  mutable std::vector<int> support_;  // live states, most likely first
  // The readings left, most informative first, each as its action's slot in emission_.
  mutable std::vector<int> readings_;
  // The distinct sorts' r̂ over the support: a floor per state, and each sort's bonus entries
  // (support index, r̂ − floor) where it pays more, sort c's from bonus_start_[c].
  mutable std::vector<std::vector<double>> columns_;  // [k][i]: sort k's r̂, then sorted
  mutable std::vector<double> floor_;
  mutable std::vector<std::pair<int, double>> bonus_;
  mutable std::vector<std::size_t> bonus_start_;
  mutable std::vector<double> known_;  // [i]: max_t r̂(support_[i], t)
  // [(slot * O + o) * S + i]: the emissions of the actions with readings left, over the support.
  mutable std::vector<double> emission_;
  mutable std::vector<double> nodes_;    // open tree nodes' weights, S each
  mutable std::vector<int> node_level_;  // [n]: how many readings node n has heard
  mutable std::vector<double> scratch_;
};

}  // namespace echoplan::solvers
