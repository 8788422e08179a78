// The planning-side model of a POMDP: what a solver may ask of a problem.
//
// In the spirit of OPPT's plugins and POMDPs.jl's generative interface: a solver only ever samples
// an initial state, steps a state with an action, and weighs an observation. The model never holds
// mutable state of its own (beliefs, trees and simulators keep theirs elsewhere) and every random
// choice comes from the `Rng&` passed in, so a rollout can be replayed from its seed.
//
// Essential (every model):   spec(), sample_initial_state(), step(), observation_likelihood().
// Optional (sensible default): heuristic_value(), tabular(), object_identification().
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/rng.h"

namespace echoplan::pomdp {

class ObjectIdentificationModel;

// A state: a vector of continuous variables (joint angles, object offset, ...) and one of discrete
// ones (object identity, ...). `StateSpec` names them. For a tabular problem, discrete[0] is the
// state index and continuous is empty.
struct State {
  std::vector<double> continuous;
  std::vector<int> discrete;

  friend bool operator==(const State&, const State&) = default;
};

// An observation: either a discrete symbol (`index`, with `values` empty) or a continuous vector
// (`values`, with index = -1). `ObservationSpec` says which kind a model emits.
struct Observation {
  int index = -1;
  std::vector<double> values;

  friend bool operator==(const Observation&, const Observation&) = default;
};

// What one step of the world produced.
struct StepResult {
  State next;
  Observation observation;
  double reward = 0.0;
  bool terminal = false;   // the episode ends after this step (sorting action, collision, ...)
  bool collision = false;  // the step ended in a collision (reported separately for logs)
};

struct StateSpec {
  std::vector<std::string> continuous_names;  // e.g. "joint1".."joint7", "offset_x", ...
  std::vector<std::string> discrete_names;    // e.g. "object"
  // For each discrete variable, the names of its values (e.g. the object names). Same length as
  // discrete_names.
  std::vector<std::vector<std::string>> discrete_value_names;
};

struct ObservationSpec {
  bool discrete = true;
  std::vector<std::string> names;  // discrete: one name per symbol; continuous: one per dimension
};

// Everything about a model that never changes while planning.
struct ModelSpec {
  std::string name;
  std::vector<std::string> action_names;
  StateSpec state;
  ObservationSpec observation;
  double discount = 0.95;
  // Sound bounds on a single step's reward, used by solvers for initial bounds and normalisation.
  double min_reward = 0.0;
  double max_reward = 0.0;
};

class TabularModel;

// The model interface. Implementations must be safe to call concurrently from several threads as
// long as each thread passes its own Rng (const methods, no hidden caches).
class Model {
 public:
  virtual ~Model() = default;

  virtual const ModelSpec& spec() const = 0;

  // A state drawn from the initial belief b0.
  virtual State sample_initial_state(Rng& rng) const = 0;

  // The generative step: next state, observation, reward and termination for taking `action` in
  // `state`. Must not be called on a terminal state.
  virtual StepResult step(const State& state, int action, Rng& rng) const = 0;

  // P(observation | next_state, action): used to weight belief particles. For continuous
  // observations, a density.
  virtual double observation_likelihood(const State& next_state, int action,
                                        const Observation& observation) const = 0;

  // An estimate of the optimal value from `state` (used at new leaves of search trees). The
  // default, 0, is always available but is a poor guide; models should override it.
  virtual double heuristic_value(const State& /*state*/) const { return 0.0; }

  // The same model as explicit tables, when it is small and discrete (enables the exact Bayes
  // filter and the offline bound solver); nullptr otherwise.
  virtual const TabularModel* tabular() const { return nullptr; }

  // The full model state that tabular state `s` stands for at the start of an episode (only
  // meaningful when tabular() is not null). The default, a state with discrete[0] = s and no
  // continuous part, is right for models that are tabular through and through; models with a
  // deterministic continuous part (arm joints, object offset) fill it in from their initial
  // configuration. Used by ExactBelief to hand solvers states they can step.
  virtual State tabular_state(int s) const { return State{{}, {s}}; }

  // The model as an object-identification problem (named objects, sensing and sorting actions),
  // when it is one; nullptr otherwise. What the closed loop, calibration and checks ask instead of
  // casting.
  virtual const ObjectIdentificationModel* object_identification() const { return nullptr; }

  // How many times `action` may be taken in one episode; 0 (the default): no limit. A limit is a
  // fact about the episode's history (the actions taken so far), not the state, so solvers count
  // the uses along each path of their trees and beliefs stay what they are.
  virtual int max_uses(int /*action*/) const { return 0; }
  // The actions that must each have been taken at least once in the episode before `action` is
  // available (a shake only after a grasp); empty (the default): available from the start. Like a
  // use limit, a fact about the history, counted by solvers along each path.
  virtual std::vector<int> prerequisites(int /*action*/) const { return {}; }

  int num_actions() const { return static_cast<int>(spec().action_names.size()); }
};

// A discrete POMDP as explicit tables: S states, A actions, O observations.
//   transition(s, a, s') = P(s' | s, a)
//   observation(a, s', o) = P(o | s', a)
//   reward(s, a)          = expected immediate reward
// A state whose every action leaves it unchanged with zero reward is absorbing (treated as
// terminal).
class TabularModel {
 public:
  virtual ~TabularModel() = default;
  virtual int num_states() const = 0;
  virtual int num_actions() const = 0;
  virtual int num_observations() const = 0;
  virtual double transition(int s, int a, int s_next) const = 0;
  virtual double observation(int a, int s_next, int o) const = 0;
  virtual double reward(int s, int a) const = 0;
  virtual bool terminal(int s) const = 0;
  virtual double discount() const = 0;
  virtual std::vector<double> initial_belief() const = 0;  // length num_states(), sums to 1
};

using ModelPtr = std::shared_ptr<const Model>;

}  // namespace echoplan::pomdp
