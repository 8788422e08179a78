#include "robot/simulated_world.h"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "common/error.h"
#include "sim/arm_sensors.h"
#include "sim/table_choice.h"

namespace echoplan::robot {

namespace {

// Independent streams of a trial's world, so that listening (which draws sound) never shifts the
// physics of later actions.
enum WorldStream : std::uint64_t { physics = 1, sound = 2, sensors = 3 };

}  // namespace

SimulatedWorld::SimulatedWorld(sim::Catalogue catalogue, sim::SimConfig config,
                               std::vector<std::string> sorting_actions)
    : catalogue_(std::move(catalogue)),
      config_(std::move(config)),
      sorting_actions_(std::move(sorting_actions)) {
  for (const std::string& a : sorting_actions_)
    if (sim::find_sound_action(a))
      throw InputError("sorting action '" + a +
                       "' has the name of one of the simulator's sensing actions");
  sim::check_tables(catalogue_, config_);
}

SimulatedWorld::~SimulatedWorld() = default;

std::vector<std::string> SimulatedWorld::sensing_actions() { return sim::sound_action_names(); }

void SimulatedWorld::check_object(const std::string& object) const { catalogue_.object(object); }

bool SimulatedWorld::is_sorting(const std::string& action) const {
  return std::find(sorting_actions_.begin(), sorting_actions_.end(), action) !=
         sorting_actions_.end();
}

void SimulatedWorld::check_action(const std::string& action) const {
  if (!is_sorting(action) && !sim::find_sound_action(action)) throw_unknown_action(action);
}

void SimulatedWorld::throw_unknown_action(const std::string& action) const {
  throw InputError(fmt::format("the simulated robot has no action '{}' (sensing: {}; sorting: {})",
                               action, fmt::join(sensing_actions(), ", "),
                               fmt::join(sorting_actions_, ", ")));
}

void SimulatedWorld::begin_trial(const TrialContext& context) {
  named_ = sim::table_of_trial(config_, context.seed);
  const sim::TableSpec& table = catalogue_.table_named(named_);
  auto it = rigs_.find({context.object, table.name});
  if (it == rigs_.end()) {
    // Compiling a MuJoCo scene takes milliseconds; trials of the same object reuse it.
    ObjectRig rig;
    rig.robot = std::make_unique<sim::SimulatedRobot>(catalogue_, context.object, config_, table);
    rig.renderer =
        std::make_unique<sim::SoundRenderer>(rig.robot->object(), rig.robot->table(), config_);
    it = rigs_.emplace(std::pair{context.object, table.name}, std::move(rig)).first;
  }
  rig_ = &it->second;
  surface_ = table.name;
  physics_rng_.seed(derive_seed(context.seed, {physics}));
  sound_rng_.seed(derive_seed(context.seed, {sound}));
  sensor_rng_.seed(derive_seed(context.seed, {sensors}));
  // The lab's reset: arm home, object at its place (with the trial's placement drawn); every action
  // of the trial then continues from where the last one left the world.
  rig_->robot->reset_trial(physics_rng_);
  listening_ = false;
  heard_ = {};
  last_outcome_.reset();
}

ActionReport SimulatedWorld::execute(const std::string& action) {
  if (!rig_) throw std::logic_error("SimulatedWorld::execute before begin_trial()");
  if (is_sorting(action)) return ActionReport{action, ActionStatus::done, "", 0.0, false, named_};
  // The name is resolved here, once; the simulator takes the action itself.
  const std::optional<sim::SoundAction> sound = sim::find_sound_action(action);
  if (!sound) throw_unknown_action(action);
  return execute_sensing(action, *sound);
}

ActionReport SimulatedWorld::execute_sensing(const std::string& name, sim::SoundAction action) {
  sim::ActionOutcome outcome = rig_->robot->execute(action, physics_rng_);
  if (listening_) hear(rig_->renderer->render(outcome.trace, outcome.duration_s, sound_rng_));
  sim::add_sensor_noise(outcome.readings, config_.sensors, sensor_rng_);
  ActionReport report{name, outcome.status, outcome.reason, outcome.duration_s, false, named_};
  last_outcome_ = std::move(outcome);
  return report;
}

void SimulatedWorld::hear(const audio::AudioClip& clip) {
  if (heard_.samples.empty()) {
    heard_ = clip;
    return;
  }
  // The same microphone rendered both, so rate and channels agree; later sound follows earlier.
  heard_.samples.insert(heard_.samples.end(), clip.samples.begin(), clip.samples.end());
}

void SimulatedWorld::start_listening() {
  if (!rig_) throw std::logic_error("SimulatedWorld::start_listening before begin_trial()");
  listening_ = true;
  heard_ = {};
}

audio::AudioClip SimulatedWorld::stop_listening() {
  if (!listening_)
    throw std::logic_error("SimulatedWorld::stop_listening without start_listening()");
  listening_ = false;
  // Nothing happened while listening: the microphone hears the room alone, for the usual length.
  if (heard_.samples.empty()) {
    sim::ContactTrace quiet;
    quiet.object_position = rig_->robot->object_position();
    return rig_->renderer->render(quiet, 0.0, sound_rng_);
  }
  return std::move(heard_);
}

}  // namespace echoplan::robot
