// How the simulated lab varies from trial to trial, where the microphone is, the room, and the
// recording format, how the arm moves: everything about a simulation run that is not the object.
// Read from an optional YAML file (format in docs/simulator.md); every field has a default.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "common/rng.h"

namespace echoplan::sim {

// A quantity that varies from action to action (or trial, or recording): a Gaussian around `mean`
// with standard deviation `stddev`, truncated at mean +- 3 standard deviations so that no draw is
// absurd (a negative speed, a grasp below the table).
struct TruncatedGaussian {
  double mean = 0;
  double stddev = 0;  // >= 0

  // One draw: always consumes the same number of values from `rng` (standard_normal's two).
  double draw(Rng& rng) const;
};

// The ranges and their physical reasons are in docs/simulator.md ("Variability").
struct VariabilityConfig {
  // Per action (ActionVariation):
  TruncatedGaussian impact_speed{
      0.10, 0.01};  // m/s, the strike's descent speed (servo tracking of a 0.1 m/s command)
  TruncatedGaussian impact_tilt_deg{
      0.0, 0.5};  // degrees between the object's axis and vertical at impact: rim or base first
                  // (the arm repeats one scripted grasp; fitted to the lab's 43 of 46 strikes)
  TruncatedGaussian grasp_height{
      0.085, 0.003};  // m, end-effector height above the table when at the object
  TruncatedGaussian grasp_offset{
      0.0, 0.003};  // m, hand off the object's axis when it closes (each horizontal axis)
  // m/s, the slide's mean speed: 5 cm over the push's duration (its profile is ArmConfig's). The
  // report gives only the distance. The lab's four slides lasted 0.95-2.0 s above -20 dB (mean 1.5
  // s, about 30% around it); 3.4 cm/s pushes for 1.5 s, and the spread, 24%, spans the lab's
  // durations within two stddev (docs/simulator.md, "The push: speed and profile").
  TruncatedGaussian push_speed{0.034, 0.008};
  TruncatedGaussian push_offset{0.0,
                                0.005};  // m, the pad off the object's centre line across the push
  // Per trial (ObjectPlacement): where the operator put the object.
  TruncatedGaussian placement_x{0.0, 0.003};  // m, object offset from its nominal place
  TruncatedGaussian placement_y{0.0, 0.003};  // m
  // Per recording (drawn by the recorder):
  TruncatedGaussian microphone_distance{
      0.0, 0.05};  // m added to the microphone-object distance (mic stand not fixed)
  TruncatedGaussian background_db{
      0.0, 0.5};  // dB added to recording.noise_dbfs (one session's room; fitted to the lab's
                  // 43 of 46 strikes: 3 dB made the strike window's quiet frames decide)
};

struct MicrophoneConfig {
  std::array<double, 3> position{-0.30, 0.40,
                                 0.40};  // m, world frame (the arm's base at the origin)
  double capsule_spacing =
      0.10;  // m between the two capsules, along world y; sets the delay between channels
};

struct RoomConfig {
  double rt60_s = 0.25;        // s, reverberation time of the decaying-noise tail, > 0
  double length_s = 0.08;      // s, impulse response length kept, > 0
  double taps_per_s = 500;     // sparse noise taps per second of impulse response, > 0
  double reverb_level = 0.06;  // tail amplitude relative to the direct sound (microphone close:
                               // strikes fall 20 dB in 15-45 ms)
  // s, in [0, 0.05]: the first reflection after the direct sound (2.5 ms: a path 0.86 m longer,
  // the table's edge or a nearby wall); the tail's taps lie between it and length_s.
  double first_reflection_s = 0.0025;
};

struct RecordingConfig {
  int sample_rate = 44100;  // Hz
  double duration_s =
      3.0;  // s, minimum recording length after the lead-in (longer if the action is)
  double lead_in_s = 0.355;  // s of exact digital zeros at the start (the lab's recorder opening)
  double noise_dbfs =
      -69;  // background noise, dB re full scale (RMS): the lab's strikes sit 51-58 dB above it
  double noise_corner_hz = 0;  // > 0: the room's noise is flat below this and falls 6 dB per
                               // octave above; 0: white (docs/simulator.md); its RMS is noise_dbfs
  double output_gain = 1400;   // full scale per unit of synthesized pressure before the limiter
                               // (every strike reaches it)
  double friction_gain =
      7.2e-7;  // scale of sliding excitation relative to impacts (slides 17 dB below strikes)
  double motor_noise_gain =
      1.8e-5;  // motor noise per rad/s of summed joint speed (about 20 dB below a slide)
  double limiter_ceiling_dbfs = -3;    // the recorder's limiter: no sample above this
  double limiter_hold_s = 0.5;         // s the limiter holds its gain after a peak
  double limiter_release_s = 0.5;      // s time constant of its recovery
  double limiter_lookahead_s = 0.001;  // s, in [0, 0.1]: how far ahead the limiter sees a peak
  // The arm's motor and gear noise (docs/simulator.md, "What is modelled", motor noise): a band
  // around motor_noise_hz (Q motor_noise_q: 0.7 is about two octaves) whose level follows the
  // summed joint speed, rising with time constant motor_attack_s and dying with motor_release_s
  // (the lab's tail after a slide: docs/simulator.md, "The mug slide"). Not measured on the lab's
  // arm: set yours.
  double motor_noise_hz = 1200;  // Hz, in [20, 20000]
  double motor_noise_q = 0.7;    // in [0.1, 20]
  double motor_attack_s = 0.15;  // s, in [0.001, 10]
  double motor_release_s = 0.4;  // s, in [0.001, 10]
  // The balance of an impact's parts and of a slide's, set with output_gain and friction_gain
  // against the lab's recordings (their peak frequencies, decays and strike-to-slide ratios:
  // ../shared/reference/real-robot-recordings.md, "Measures per file"); no measurement of their
  // own. contact_ring_gain: the contact's direct radiation (the thud at 1 / (2 tau)) relative to
  // the object's modes, in [0, 100]; table_impact_gain: the share of an impact that rings the
  // table's modes, in [0, 10]; ring_mode_floor: how strongly a contact spread evenly round the rim
  // still drives a ring mode (real objects are not perfectly round), in [0, 1];
  // friction_direct_gain: the rubbing contact's own broadband radiation relative to the modes', in
  // [0, 100].
  double contact_ring_gain = 3.0;
  double table_impact_gain = 0.25;
  double ring_mode_floor = 0.15;
  double friction_direct_gain = 0.5;
  // How a slide's friction sound follows the load (sound_friction.h, FrictionLoad): its amplitude
  // scales as (mu N / friction_reference_force_n)^friction_load_exponent, mu N the object's
  // friction force on the table. Exponent in [0, 1]: 0 load-independent roughness noise, 0.5 sound
  // power a fixed share of the frictional power. Fitted to the lab's slides heard right
  // (docs/simulator.md, "Slides as the lab heard them"). Reference force in [0.001, 100] N: the
  // four objects' geometric mean friction force, so friction_gain keeps its calibration.
  double friction_load_exponent = 0.45;
  double friction_reference_force_n = 0.2;
};

// How the simulated arm moves: its controller's profiles, the same in every action.
struct ArmConfig {
  // The slide's push is one trapezoidal speed profile scaled to the push's duration: it accelerates
  // from rest over this share of the duration and decelerates to rest over the second share (each
  // in [0, 1], together at most 1). The lab's slides build up over about a second and peak in their
  // second half; a push that reaches its speed at once is as loud from its first tenth of a second
  // (docs/simulator.md, "The push: speed and profile").
  double push_accelerate_share = 0.4;
  double push_decelerate_share = 0.2;
  // The strike's timings (s, each in [0.01, 2]). The report gives its distance and speed only
  // (5 cm at 10 cm/s, the report's section 3.2.1); these are the simulated arm's, not measured on
  // the lab's: the hand closes over grasp_time_s, the lift and the descent reach their speed over
  // strike_ease_s (docs/simulator.md, "What is modelled", actions), it pauses lift_pause_s at the
  // top, turns a tilted object upright on the table over level_time_s (slowly: a faster levelling
  // can make a second hit; docs/simulator.md, "The mug strike", the tilted landing), holds it
  // hold_time_s and opens over release_time_s.
  double grasp_time_s = 0.1;
  double strike_ease_s = 0.15;
  double lift_pause_s = 0.1;
  double level_time_s = 0.3;
  double hold_time_s = 0.1;
  double release_time_s = 0.05;
};

struct PhysicsConfig {
  double timestep_s = 0.002;  // s, in [0.0005, 0.005]: every action but the slide
  // s, in [0.0005, 0.005]: the slide, a steady push whose contacts change slowly; its sound is
  // interpolated between steps. The strike needs the finer step for its impact (a stop on contact
  // within 1 mm); the slide's coarser one pays for its length (git history).
  double slide_timestep_s = 0.003;
};

// The arm's own sensors beside the microphone (sim/arm_sensors.h): how often they are read and how
// noisy each reading is. The noise is an assumption of this simulator, not a measurement: the order
// of a strain-gauge joint torque sensor's and of a wrist force sensor's noise at 100 Hz.
struct SensorConfig {
  double rate_hz = 100;           // Hz, in [10, 1000]: the arm controller's feedback rate
  double effort_noise_nm = 0.05;  // N m, in [0, 10]: standard deviation per joint torque reading
  double force_noise_n = 0.2;     // N, in [0, 100]: standard deviation per force axis reading
};

struct SimConfig {
  // The catalogue's tables the recordings and trials are made on (`table:`, a name or a list;
  // sim/table_choice.h says which gets which); empty: the catalogue's default table.
  std::vector<std::string> tables;
  VariabilityConfig variability;
  MicrophoneConfig microphone;
  RoomConfig room;
  RecordingConfig recording;
  ArmConfig arm;
  PhysicsConfig physics;
  SensorConfig sensors;
};

// Reads a sim config file; missing fields keep their defaults. Throws InputError naming the file,
// the line and the field for a wrong type or out-of-range value or an unknown field.
SimConfig load_sim_config(const std::string& path);
SimConfig parse_sim_config(const std::string& yaml_text, const std::string& source);

// How one action varies (drawn per action): what the manifest records with the ObjectPlacement.
struct ActionVariation {
  double impact_speed = 0;     // m/s
  double impact_tilt_deg = 0;  // degrees
  double tilt_azimuth_deg =
      0;  // degrees, direction of the tilt around the vertical, uniform: which rim point lands
  double grasp_height = 0;    // m
  double grasp_offset_x = 0;  // m, world frame
  double grasp_offset_y = 0;  // m
  double push_speed = 0;      // m/s
  double push_offset = 0;     // m, along world y

  // (name, value) pairs in a fixed order, for manifests and logs.
  std::vector<std::pair<std::string, double>> named() const;
};

// Draws one action's variation. Always consumes the same number of draws from `rng`.
ActionVariation sample_action(const VariabilityConfig& variability, Rng& rng);

// Where the object stands when a trial begins (drawn per trial).
struct ObjectPlacement {
  double placement_x = 0;      // m, from the nominal place (0.1 m ahead of the end effector)
  double placement_y = 0;      // m
  double orientation_deg = 0;  // rotation of the object about its own axis, uniform in [0, 360)

  std::vector<std::pair<std::string, double>> named() const;
};

// Draws one trial's placement. Always consumes the same number of draws from `rng`.
ObjectPlacement sample_placement(const VariabilityConfig& variability, Rng& rng);

// A standard normal variate from `rng` (Box-Muller on uniform01, identical on every platform).
double standard_normal(Rng& rng);

}  // namespace echoplan::sim
