// Small POMDPs written out as tables for the offline solver's tests, independent of any file
// loader.
#pragma once

#include <vector>

#include "pomdp/model.h"

namespace echoplan::solvers::offline::testing {

// A TabularModel backed by plain nested vectors: T[a][s][s'], Z[a][s'][o], R[s][a].
class TableModel : public pomdp::TabularModel {
 public:
  std::vector<std::vector<std::vector<double>>> T, Z;
  std::vector<std::vector<double>> R;
  std::vector<bool> is_terminal;
  std::vector<double> b0;
  double gamma = 0.95;

  int num_states() const override { return static_cast<int>(R.size()); }
  int num_actions() const override { return static_cast<int>(T.size()); }
  int num_observations() const override { return static_cast<int>(Z[0][0].size()); }
  double transition(int s, int a, int s2) const override { return T[a][s][s2]; }
  double observation(int a, int s2, int o) const override { return Z[a][s2][o]; }
  double reward(int s, int a) const override { return R[s][a]; }
  bool terminal(int s) const override { return is_terminal[s]; }
  double discount() const override { return gamma; }
  std::vector<double> initial_belief() const override { return b0; }
};

// Tiger (Kaelbling, Littman & Cassandra 1998): states tiger-left, tiger-right; actions listen,
// open-left, open-right; listening is right with probability 0.85; opening resets the problem.
inline TableModel tiger() {
  TableModel m;
  m.gamma = 0.95;
  const std::vector<std::vector<double>> stay{{1, 0}, {0, 1}}, reset{{0.5, 0.5}, {0.5, 0.5}};
  m.T = {stay, reset, reset};
  const std::vector<std::vector<double>> hear{{0.85, 0.15}, {0.15, 0.85}};
  m.Z = {hear, reset, reset};
  m.R = {{-1, -100, 10}, {-1, 10, -100}};
  m.is_terminal = {false, false};
  m.b0 = {0.5, 0.5};
  return m;
}

// The seed report's problem (section 3.3): objects 0..3 and a terminal state 4; actions slide,
// strike, move_to_A, move_to_B; objects 0 and 2 belong at A, 1 and 3 at B; discount 0.99.
inline constexpr int kSlide = 0, kStrike = 1, kMoveA = 2, kMoveB = 3, kDone = 4;
inline TableModel audio_objects() {
  TableModel m;
  m.gamma = 0.99;
  const int S = 5;
  std::vector<std::vector<double>> identity(S, std::vector<double>(S, 0.0)), to_done = identity;
  for (int s = 0; s < S; ++s) {
    identity[s][s] = 1.0;
    to_done[s][kDone] = 1.0;
  }
  m.T = {identity, identity, to_done, to_done};
  // P(o | object, action) from section 3.3; the terminal state and the sorting actions always give
  // observation 0 (uninformative).
  const std::vector<std::vector<double>> slide{{0.5, 0.3, 0.15, 0.05},
                                               {0.11, 0.67, 0.11, 0.11},
                                               {0.11, 0.11, 0.67, 0.11},
                                               {0.01, 0.01, 0.48, 0.5},
                                               {1, 0, 0, 0}};
  const std::vector<std::vector<double>> strike{{0.6, 0.05, 0.3, 0.05},
                                                {0.05, 0.6, 0.3, 0.05},
                                                {0.11, 0.11, 0.67, 0.11},
                                                {0.11, 0.11, 0.11, 0.67},
                                                {1, 0, 0, 0}};
  const std::vector<std::vector<double>> silent(S, {1, 0, 0, 0});
  m.Z = {slide, strike, silent, silent};
  m.R = {
      {-1, -1, 10, -100}, {-1, -1, -100, 10}, {-1, -1, 10, -100}, {-1, -1, -100, 10}, {0, 0, 0, 0}};
  m.is_terminal = {false, false, false, false, true};
  m.b0 = {0.25, 0.25, 0.25, 0.25, 0.0};
  return m;
}

}  // namespace echoplan::solvers::offline::testing
