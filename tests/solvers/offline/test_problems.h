// The shipped problems (problems/*.pomdp) as plain tables for the offline solver's tests: loaded
// from the files users run, then copied into nested vectors a test can edit.
#pragma once

#include <string>
#include <vector>

#include "../../common/source_dir.h"
#include "pomdp/model.h"
#include "pomdp/problem.h"

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

// A shipped problem file's tables, copied so that a test can change one entry.
inline TableModel shipped_tables(const std::string& file) {
  const pomdp::Problem problem =
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/" + file);
  const pomdp::TabularModel& m = *problem.model->tabular();
  TableModel t;
  const int S = m.num_states(), A = m.num_actions(), O = m.num_observations();
  t.T.assign(A, std::vector<std::vector<double>>(S, std::vector<double>(S)));
  t.Z.assign(A, std::vector<std::vector<double>>(S, std::vector<double>(O)));
  t.R.assign(S, std::vector<double>(A));
  for (int a = 0; a < A; ++a) {
    for (int s = 0; s < S; ++s) {
      for (int s2 = 0; s2 < S; ++s2) t.T[a][s][s2] = m.transition(s, a, s2);
      for (int o = 0; o < O; ++o) t.Z[a][s][o] = m.observation(a, s, o);
      t.R[s][a] = m.reward(s, a);
    }
  }
  for (int s = 0; s < S; ++s) t.is_terminal.push_back(m.terminal(s));
  t.b0 = m.initial_belief();
  t.gamma = m.discount();
  return t;
}

// Tiger (Kaelbling, Littman & Cassandra 1998; problems/tiger.pomdp): states tiger-left,
// tiger-right; actions listen, open-left, open-right; listening is right with probability 0.85;
// opening resets the problem; discount 0.95.
inline TableModel tiger() { return shipped_tables("tiger.pomdp"); }

// The report's problem (section 3.3; problems/audio_objects.pomdp): objects 0..3 and a
// terminal state 4; actions slide, strike, move_to_A, move_to_B; objects 0 and 2 belong at A, 1
// and 3 at B; observations the four classes and "none" (heard only after sorting); discount 0.99.
inline constexpr int kSlide = 0, kStrike = 1, kMoveA = 2, kMoveB = 3, kDone = 4, kNone = 4;
inline TableModel audio_objects() { return shipped_tables("audio_objects.pomdp"); }

}  // namespace echoplan::solvers::offline::testing
