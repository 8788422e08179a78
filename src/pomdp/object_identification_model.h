// The report's problem, generalised: identify which of K objects the robot holds by making sounds
// with it, then sort it into a group (report "Planning to listen", sections 3.2-3.3).
//
// State: 7 arm joint angles (rad) + 3 object offsets from the end effector (m) as `continuous`,
// and the object index as discrete[0]. The object never changes; sensing actions move the object
// by a fixed offset (the kinematics are deterministic, as in the report); sorting actions end the
// episode. Everything that names or numbers the problem (objects, actions, rewards, observation
// table) is data in ObjectProblemData, usually read from a YAML file (pomdp/problem.h).
//
// Action indices: sensing actions first (0..M-1, in data order), then sorting actions (M..M+J-1).
// Observation indices: the classifier's class symbols (0..C-1), then one extra symbol "none"
// (index C) emitted by sorting actions and collisions, where nothing is heard. The extra symbol
// keeps the tabular model's absorbing 'done' state from being confused with a heard class.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "pomdp/model.h"

namespace echoplan::pomdp {

// A sound-making action and its deterministic effect.
struct SensingAction {
  std::string name;
  double reward = -1.0;                   // reward per use (a cost, so usually negative)
  std::array<double, 3> offset_change{};  // m, added to the object offset (x, y, z)
  double collision_probability = 0.0;     // in [0, 1]: chance the action hits the table
  // How many times the action can be performed in one episode; 0: no limit. A recorded dataset
  // holds a few performances of each behaviour per session: once they are used up, the action is
  // no longer available (Model::max_uses).
  int uses = 0;
  // The sensing actions (indices into ObjectProblemData::sensing) that must each have been
  // performed at least once in the episode before this one is available: a robot shakes or lifts
  // an object only once it has grasped it (Model::prerequisites). Empty: always available.
  std::vector<int> prerequisites = {};
};

// Everything that defines an object-identification problem. Invariants (checked by
// validate_object_problem): at least one object, sensing action and sorting action; every
// probability row sums to 1 within 1e-6 with entries in [0, 1]; tables sized as documented.
struct ObjectProblemData {
  std::string name;
  double discount = 0.99;                        // in (0, 1)
  std::vector<std::string> objects;              // K object names
  std::vector<double> prior;                     // K initial probabilities of each object
  std::array<double, 7> initial_joints{};        // rad, the arm's fixed initial configuration
  std::array<double, 3> initial_offset{};        // m, the object's offset from the end effector
  std::vector<SensingAction> sensing;            // M sound-making actions
  std::vector<std::string> sorting;              // J terminal sorting actions
  std::vector<std::string> observation_symbols;  // C class symbols the classifier reports
  // observation_table[a][k][o] = P(symbol o | object k, sensing action a); shape M x K x C.
  std::vector<std::vector<std::vector<double>>> observation_table;
  // sorting_reward[j][k] = reward of sorting action j when the object is k; shape J x K.
  std::vector<std::vector<double>> sorting_reward;
  double collision_reward = -100.0;  // replaces the action's reward on a collision
};

// A chain of prerequisites that leads back to where it started (a requires b, b requires a), as
// the sensing actions' indices from the first to the one that closes it (that first again); empty
// when there is none. No action on such a chain could ever be performed. Indices out of range are
// skipped (validate_object_problem reports them).
std::vector<int> prerequisite_cycle(const std::vector<SensingAction>& sensing);

// Throws std::invalid_argument naming the first broken invariant (the YAML loader reports the
// same conditions with file and line before it gets here).
void validate_object_problem(const ObjectProblemData& data);

// The problem as tables: states 0..K-1 are the objects and state K is the absorbing 'done' state
// reached by sorting and by collisions; observations are the C classes plus "none" (index C).
// A collision leads to 'done' with the collision reward; R(k, sensing a) is its expectation
// (1-p) r_a + p r_collision.
class ObjectIdentificationTabular final : public TabularModel {
 public:
  explicit ObjectIdentificationTabular(const ObjectProblemData& data);
  int num_states() const override { return num_objects_ + 1; }
  int num_actions() const override { return num_sensing_ + num_sorting_; }
  int num_observations() const override { return num_symbols_ + 1; }
  double transition(int s, int a, int s_next) const override;
  double observation(int a, int s_next, int o) const override;
  double reward(int s, int a) const override;
  bool terminal(int s) const override { return s == num_objects_; }
  double discount() const override { return discount_; }
  std::vector<double> initial_belief() const override;

 private:
  const ObjectProblemData& data_;
  int num_objects_, num_sensing_, num_sorting_, num_symbols_;
  double discount_;
};

class ObjectIdentificationModel final : public Model {
 public:
  // Index of each continuous state variable.
  static constexpr int kNumJoints = 7;
  static constexpr int kOffsetX = 7;  // offsets are continuous[7..9]
  static constexpr int kNumContinuous = 10;

  explicit ObjectIdentificationModel(ObjectProblemData data);
  // The tabular view refers into data_, so the model stays where it was built.
  ObjectIdentificationModel(const ObjectIdentificationModel&) = delete;
  ObjectIdentificationModel& operator=(const ObjectIdentificationModel&) = delete;

  const ModelSpec& spec() const override { return spec_; }
  State sample_initial_state(Rng& rng) const override;
  StepResult step(const State& state, int action, Rng& rng) const override;
  double observation_likelihood(const State& next_state, int action,
                                const Observation& observation) const override;
  // The value of the state if the object were known: the better of sorting it correctly now and
  // sensing forever (which only matters when every sorting reward is worse than that). It never
  // underestimates the optimal value of a belief concentrated on this state (it is the MDP value),
  // so search trees that use it are optimistic at new leaves.
  double heuristic_value(const State& state) const override;
  const ObjectIdentificationModel* object_identification() const override { return this; }
  int max_uses(int action) const override;
  std::vector<int> prerequisites(int action) const override;
  const TabularModel* tabular() const override { return &tabular_; }
  State tabular_state(int s) const override;

  const ObjectProblemData& data() const { return data_; }
  int num_sensing() const { return static_cast<int>(data_.sensing.size()); }
  bool is_sensing(int action) const { return action < num_sensing(); }
  // The observation symbol emitted when nothing is heard (sorting, collision).
  int none_symbol() const { return static_cast<int>(data_.observation_symbols.size()); }

 private:
  ObjectProblemData data_;
  ModelSpec spec_;
  ObjectIdentificationTabular tabular_;
  int num_objects_, num_symbols_;
  // Cumulative observation rows, flattened: obs_cdf_[(a * K + k) * C + o] = P(symbol <= o | k, a).
  std::vector<double> obs_cdf_;
  std::vector<double> prior_cdf_;           // K cumulative initial probabilities
  std::vector<double> known_object_value_;  // K heuristic values, see heuristic_value()
};

}  // namespace echoplan::pomdp
