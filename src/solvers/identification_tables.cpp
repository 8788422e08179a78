#include "solvers/identification_tables.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace echoplan::solvers {

namespace {
// Transition and reward entries are compared exactly against 0 and 1 where the shape depends on
// them; tables read from files keep exact zeros, and a row sum is checked elsewhere.
constexpr double kZero = 0.0;
}  // namespace

std::optional<std::string> identification_shape_problem(const pomdp::TabularModel& m) {
  const int S = m.num_states(), A = m.num_actions();
  const std::vector<double> b0 = m.initial_belief();
  for (int s = 0; s < S; ++s) {
    if (!m.terminal(s)) continue;
    for (int a = 0; a < A; ++a) {
      if (m.transition(s, a, s) != 1.0 || m.reward(s, a) != kZero)
        return fmt::format("absorbing state {} is left or pays a reward under action {}", s, a);
    }
    if (b0[s] > kZero) return fmt::format("the start belief puts mass on absorbing state {}", s);
  }
  bool any_terminal_action = false;
  for (int a = 0; a < A; ++a) {
    bool ends_everywhere = true;
    for (int s = 0; s < S; ++s) {
      if (m.terminal(s)) continue;
      for (int t = 0; t < S; ++t) {
        if (t == s || m.terminal(t) || m.transition(s, a, t) <= kZero) continue;
        return fmt::format(
            "action {} moves state {} to state {}: the hidden state must stay fixed until an "
            "action ends the episode (for example, Tiger's doors reset the state instead)",
            a, s, t);
      }
      if (m.transition(s, a, s) > kZero) ends_everywhere = false;
    }
    any_terminal_action = any_terminal_action || ends_everywhere;
  }
  if (!any_terminal_action)
    return std::string(
        "no action ends the episode from every state (an identification problem ends by "
        "committing, e.g. sorting the object)");
  return std::nullopt;
}

std::shared_ptr<const IdentificationTables> read_identification_tables(const pomdp::TabularModel& m,
                                                                       const UseLimits& limits) {
  auto t = std::make_shared<IdentificationTables>();
  t->limits = limits;
  t->states = m.num_states();
  t->actions = m.num_actions();
  t->observations = m.num_observations();
  t->discount = m.discount();
  t->initial_belief = m.initial_belief();
  for (int s = 0; s < t->states; ++s)
    if (!m.terminal(s)) t->model_state.push_back(s);
  t->live_states = static_cast<int>(t->model_state.size());
  const int L = t->live_states, O = t->observations, A = t->actions;
  t->terminal.assign(A, true);
  t->reward.assign(std::size_t(A) * L, 0.0);
  t->stay.assign(std::size_t(A) * L, 0.0);
  t->emission.assign(std::size_t(A) * O * L, 0.0);
  for (int a = 0; a < A; ++a) {
    for (int l = 0; l < L; ++l) {
      const int s = t->model_state[l];
      t->reward[a * L + l] = m.reward(s, a);
      t->stay[a * L + l] = m.transition(s, a, s);
      if (t->stay[a * L + l] > kZero) t->terminal[a] = false;
      for (int o = 0; o < O; ++o)
        t->emission[(std::size_t(a) * O + o) * L + l] = t->stay[a * L + l] * m.observation(a, s, o);
    }
  }
  // The value of a known state: with the state fixed, the best stationary plan either ends the
  // episode now or repeats one sensing action for ever (until a collision ends it). With use
  // limits this stays an upper bound (a limit only removes plans).
  t->known_value.assign(L, -std::numeric_limits<double>::infinity());
  for (int l = 0; l < L; ++l) {
    for (int a = 0; a < A; ++a) {
      const double r = t->reward[a * L + l];
      const double v = t->terminal[a] ? r : r / (1.0 - t->discount * t->stay[a * L + l]);
      t->known_value[l] = std::max(t->known_value[l], v);
    }
  }
  return t;
}

}  // namespace echoplan::solvers
