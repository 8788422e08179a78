// The simulated lab as a Robot and a Recorder: one MuJoCo world, seen through the two interfaces
// the execution loop uses for a real arm and a real microphone.
//
// SimulatedWorld owns the simulator's robot (src/sim) for the trial's object and what the world
// sounded like. SimulatedArm (a Robot) executes actions in it; SimulatedMicrophone (a Recorder)
// hears what the world emitted between start() and stop(): the synthesized sound of every action
// executed meanwhile, one after the other, or the room's background alone when nothing happened.
// Sound is only synthesized while a microphone listens.
//
// The world keeps its state through a trial: begin_trial() is the lab's reset (arm home, object at
// its place), and every action continues from where the last one left the arm and the object, so a
// slide moves the object 5 cm and the next action starts there. Pushing the object out of reach, or
// over, is reported as a failed action and a collision as a collision (ActionReport), never thrown.
//
// Sensing actions are the simulator's ("slide", "strike"). Sorting actions (e.g. "move_to_A") are
// reported done without motion or sound: the simulator has no sorting motion, and the loop only
// needs to know that the trial ended there.
//
// One world serves one thread: MuJoCo's data and the synthesis buffers are not shared. A parallel
// campaign builds one world per worker (see loop/world_spec.h).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "audio/clip.h"
#include "common/rng.h"
#include "robot/recorder.h"
#include "robot/robot.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"
#include "sim/simulated_robot.h"
#include "sim/sound_action.h"
#include "sim/sound_renderer.h"

namespace echoplan::robot {

class SimulatedWorld {
 public:
  // `sorting_actions` are the names this world accepts as sorting actions. Throws InputError when a
  // sorting action is named like a sensing action, or the config names a table the catalogue does
  // not have.
  SimulatedWorld(sim::Catalogue catalogue, sim::SimConfig config,
                 std::vector<std::string> sorting_actions);
  ~SimulatedWorld();
  SimulatedWorld(const SimulatedWorld&) = delete;
  SimulatedWorld& operator=(const SimulatedWorld&) = delete;

  // The sensing actions the simulator can execute.
  static std::vector<std::string> sensing_actions();

  // Throws InputError naming the catalogue when `object` is not in it (listing the known objects).
  void check_object(const std::string& object) const;
  // Throws InputError when `action` is neither a sensing action of the simulator
  // (sim::SoundAction) nor one of this world's sorting actions.
  void check_action(const std::string& action) const;

  // Resets the scene of `context.object` on the trial's table (the config's table, or one of its
  // list drawn from `context.seed`: sim/table_choice.h; the MuJoCo model of each object and table
  // is compiled once per world and reused), seeds the trial's physics, sound and sensor streams
  // from `context.seed` and draws the trial's placement from the physics stream. Stops listening.
  void begin_trial(const TrialContext& context);

  // Executes `action` (see the file comment). Throws InputError for an unknown action and
  // std::logic_error before the first begin_trial().
  ActionReport execute(const std::string& action);

  // The microphone's side: start() forgets what was heard before; stop() returns what was heard
  // since and stops listening. stop() without a start() throws std::logic_error.
  void start_listening();
  audio::AudioClip stop_listening();

  // The simulator's account of the last sensing action (for logs); empty before the first one and
  // after begin_trial(). Its readings are as the arm's sensors measured them: with the sensors'
  // noise (sim::add_sensor_noise, config().sensors) drawn from the trial's sensor stream, a stream
  // of its own, so the physics and the sound are the same with or without anyone reading them.
  const std::optional<sim::ActionOutcome>& last_outcome() const { return last_outcome_; }
  // The name of the table the trial is on (empty before the first begin_trial()).
  const std::string& surface() const { return surface_; }
  const sim::Catalogue& catalogue() const { return catalogue_; }
  const sim::SimConfig& config() const { return config_; }

 private:
  // The simulator's robot and its sound for one object.
  struct ObjectRig {
    std::unique_ptr<sim::SimulatedRobot> robot;
    std::unique_ptr<sim::SoundRenderer> renderer;
  };
  bool is_sorting(const std::string& action) const;
  ActionReport execute_sensing(const std::string& name, sim::SoundAction action);
  [[noreturn]] void throw_unknown_action(const std::string& action) const;
  void hear(const audio::AudioClip& clip);

  sim::Catalogue catalogue_;
  sim::SimConfig config_;
  std::vector<std::string> sorting_actions_;
  // By object and table name, built on first use.
  std::map<std::pair<std::string, std::string>, ObjectRig> rigs_;
  ObjectRig* rig_ = nullptr;  // the trial's object on its table
  std::string surface_;       // the trial's table
  std::string named_;         // the same when the config chose it, empty on the default
  Rng physics_rng_{0};        // the trial's variability (speeds, placement, ...)
  Rng sound_rng_{0};          // the trial's room, surface profile and noise
  Rng sensor_rng_{0};         // the arm sensors' noise
  bool listening_ = false;
  audio::AudioClip heard_;  // everything emitted since start_listening()
  std::optional<sim::ActionOutcome> last_outcome_;
};

// The Robot interface over a SimulatedWorld.
class SimulatedArm final : public Robot {
 public:
  explicit SimulatedArm(std::shared_ptr<SimulatedWorld> world) : world_(std::move(world)) {}
  void begin_trial(const TrialContext& context) override { world_->begin_trial(context); }
  ActionReport execute(const std::string& action) override { return world_->execute(action); }

 private:
  std::shared_ptr<SimulatedWorld> world_;
};

// The Recorder interface over a SimulatedWorld: hears what the world emits. The world's trial is
// begun by the arm, so begin_trial() has nothing to do here.
class SimulatedMicrophone final : public Recorder {
 public:
  explicit SimulatedMicrophone(std::shared_ptr<SimulatedWorld> world) : world_(std::move(world)) {}
  void start(const std::string& /*action*/) override { world_->start_listening(); }
  audio::AudioClip stop() override { return world_->stop_listening(); }

 private:
  std::shared_ptr<SimulatedWorld> world_;
};

}  // namespace echoplan::robot
