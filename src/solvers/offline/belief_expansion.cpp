#include "solvers/offline/belief_expansion.h"

namespace echoplan::solvers::offline {

BeliefVector predict(const FlatPomdp& pomdp, const BeliefVector& belief, int action) {
  BeliefVector predicted(pomdp.num_states, 0.0);
  for (int s = 0; s < pomdp.num_states; ++s) {
    if (belief[s] == 0.0) continue;
    for (const Successor& next : pomdp.successors_of(s, action)) {
      predicted[next.state] += belief[s] * next.probability;
    }
  }
  return predicted;
}

BeliefExpansion expand(const FlatPomdp& pomdp, const BeliefVector& belief, int action) {
  const int S = pomdp.num_states, O = pomdp.num_observations;
  const BeliefVector predicted = predict(pomdp, belief, action);
  BeliefExpansion out;
  out.observation_probability.assign(O, 0.0);
  out.next_belief.assign(O, BeliefVector(S, 0.0));
  // Unnormalised posteriors first, then normalise each by its observation probability.
  for (int s2 = 0; s2 < S; ++s2) {
    if (predicted[s2] == 0.0) continue;
    const double* z = pomdp.observation_row(action, s2);
    for (int o = 0; o < O; ++o) {
      const double w = predicted[s2] * z[o];
      out.next_belief[o][s2] = w;
      out.observation_probability[o] += w;
    }
  }
  for (int o = 0; o < O; ++o) {
    const double p = out.observation_probability[o];
    if (p > 0.0) {
      for (double& x : out.next_belief[o]) x /= p;
    } else {
      out.next_belief[o] = predicted;
    }
  }
  return out;
}

double expected_reward(const FlatPomdp& pomdp, const BeliefVector& belief, int action) {
  double r = 0.0;
  for (int s = 0; s < pomdp.num_states; ++s) r += belief[s] * pomdp.reward_at(s, action);
  return r;
}

}  // namespace echoplan::solvers::offline
