#include "sim/sim_config.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <sstream>

#include "common/error.h"
#include "common/file_io.h"
#include "common/yaml_reader.h"

namespace echoplan::sim {

namespace {

// One section of the config: a table of field name -> setter, so unknown fields are reported
// instead of silently ignored (a misspelt field would otherwise keep its default).
using FieldSetters =
    std::map<std::string, std::function<void(const YAML::Node&, const std::string&)>>;

void read_section(const YamlReader& f, const YAML::Node& root, const std::string& name,
                  const FieldSetters& fields) {
  const YAML::Node section = root[name];
  if (!section) return;
  std::vector<std::string> known;
  for (const auto& [key, setter] : fields) known.push_back(key);
  f.only_keys(section, known, name);
  for (const auto& kv : section)
    fields.at(kv.first.Scalar())(kv.second, name + "." + kv.first.Scalar());
}

std::function<void(const YAML::Node&, const std::string&)> number_into(const YamlReader& f,
                                                                       double& target, double low,
                                                                       double high) {
  return [&f, &target, low, high](const YAML::Node& v, const std::string& field) {
    target = f.number(v, field, NumberRange::closed(low, high));
  };
}

std::function<void(const YAML::Node&, const std::string&)> truncated_gaussian_into(
    const YamlReader& f, TruncatedGaussian& target, double low, double high) {
  return [&f, &target, low, high](const YAML::Node& v, const std::string& field) {
    if (!v.IsMap()) f.fail(v, field + " must be {mean: ..., stddev: ...}");
    f.only_keys(v, {"mean", "stddev"}, field);
    target.mean =
        f.number(f.require(v, "mean", field), field + ".mean", NumberRange::closed(low, high));
    target.stddev = f.number(f.require(v, "stddev", field), field + ".stddev",
                             NumberRange::closed(0.0, high - low));
  };
}

SimConfig read_sim_config(const YamlReader& f, const YAML::Node& root) {
  SimConfig c;
  if (root.IsNull()) return c;
  f.expect_map(root, "the sim config");
  const std::vector<std::string> sections{"table",     "variability", "microphone", "room",
                                          "recording", "arm",         "physics",    "sensors"};
  f.only_keys(root, sections, "the sim config");
  // Checked against the catalogue where both are known (sim/table_choice.h).
  if (const YAML::Node t = root["table"])
    c.tables = t.IsSequence() ? f.names(t, "table") : std::vector<std::string>{f.name(t, "table")};
  auto& v = c.variability;
  read_section(
      f, root, "variability",
      {{"impact_speed", truncated_gaussian_into(f, v.impact_speed, 0.005, 1.0)},
       {"impact_tilt_deg", truncated_gaussian_into(f, v.impact_tilt_deg, 0.0, 30.0)},
       {"grasp_height", truncated_gaussian_into(f, v.grasp_height, -0.05, 0.20)},
       {"grasp_offset", truncated_gaussian_into(f, v.grasp_offset, -0.02, 0.02)},
       {"push_speed", truncated_gaussian_into(f, v.push_speed, 0.005, 0.5)},
       {"push_offset", truncated_gaussian_into(f, v.push_offset, -0.02, 0.02)},
       {"placement_x", truncated_gaussian_into(f, v.placement_x, -0.05, 0.05)},
       {"placement_y", truncated_gaussian_into(f, v.placement_y, -0.05, 0.05)},
       {"microphone_distance", truncated_gaussian_into(f, v.microphone_distance, -0.3, 0.3)},
       {"background_db", truncated_gaussian_into(f, v.background_db, -20.0, 20.0)}});
  auto& mic = c.microphone;
  read_section(f, root, "microphone",
               {{"position",
                 [&](const YAML::Node& n, const std::string& field) {
                   if (!n.IsSequence() || n.size() != 3)
                     f.fail(n, field + " must be [x, y, z] in metres");
                   for (int k = 0; k < 3; ++k)
                     mic.position[k] = f.number(n[k], field, NumberRange::closed(-10.0, 10.0));
                 }},
                {"capsule_spacing", number_into(f, mic.capsule_spacing, 0.0, 1.0)}});
  auto& room = c.room;
  read_section(f, root, "room",
               {{"rt60_s", number_into(f, room.rt60_s, 0.01, 5.0)},
                {"length_s", number_into(f, room.length_s, 0.001, 0.5)},
                {"taps_per_s", number_into(f, room.taps_per_s, 10.0, 20000.0)},
                {"reverb_level", number_into(f, room.reverb_level, 0.0, 2.0)},
                {"first_reflection_s", number_into(f, room.first_reflection_s, 0.0, 0.05)}});
  auto& rec = c.recording;
  double sample_rate = rec.sample_rate;
  read_section(f, root, "recording",
               {{"sample_rate", number_into(f, sample_rate, 8000.0, 192000.0)},
                {"duration_s", number_into(f, rec.duration_s, 0.1, 60.0)},
                {"noise_dbfs", number_into(f, rec.noise_dbfs, -200.0, 0.0)},
                {"noise_corner_hz", number_into(f, rec.noise_corner_hz, 0.0, 20000.0)},
                {"output_gain", number_into(f, rec.output_gain, 0.0, 1.0e6)},
                {"friction_gain", number_into(f, rec.friction_gain, 0.0, 1000.0)},
                {"lead_in_s", number_into(f, rec.lead_in_s, 0.0, 10.0)},
                {"motor_noise_gain", number_into(f, rec.motor_noise_gain, 0.0, 1000.0)},
                {"limiter_ceiling_dbfs", number_into(f, rec.limiter_ceiling_dbfs, -60.0, 0.0)},
                {"limiter_hold_s", number_into(f, rec.limiter_hold_s, 0.0, 10.0)},
                {"limiter_release_s", number_into(f, rec.limiter_release_s, 0.001, 10.0)},
                {"limiter_lookahead_s", number_into(f, rec.limiter_lookahead_s, 0.0, 0.1)},
                {"motor_noise_hz", number_into(f, rec.motor_noise_hz, 20.0, 20000.0)},
                {"motor_noise_q", number_into(f, rec.motor_noise_q, 0.1, 20.0)},
                {"motor_attack_s", number_into(f, rec.motor_attack_s, 0.001, 10.0)},
                {"motor_release_s", number_into(f, rec.motor_release_s, 0.001, 10.0)},
                {"contact_ring_gain", number_into(f, rec.contact_ring_gain, 0.0, 100.0)},
                {"table_impact_gain", number_into(f, rec.table_impact_gain, 0.0, 10.0)},
                {"ring_mode_floor", number_into(f, rec.ring_mode_floor, 0.0, 1.0)},
                {"friction_direct_gain", number_into(f, rec.friction_direct_gain, 0.0, 100.0)},
                {"friction_load_exponent", number_into(f, rec.friction_load_exponent, 0.0, 1.0)},
                {"friction_reference_force_n",
                 number_into(f, rec.friction_reference_force_n, 0.001, 100.0)}});
  rec.sample_rate = static_cast<int>(std::lround(sample_rate));
  if (rec.motor_noise_hz >= 0.5 * rec.sample_rate)
    f.fail(root["recording"]["motor_noise_hz"],
           "recording.motor_noise_hz must be below half the sample rate");
  auto& arm = c.arm;
  read_section(f, root, "arm",
               {{"push_accelerate_share", number_into(f, arm.push_accelerate_share, 0.0, 1.0)},
                {"push_decelerate_share", number_into(f, arm.push_decelerate_share, 0.0, 1.0)},
                {"grasp_time_s", number_into(f, arm.grasp_time_s, 0.01, 2.0)},
                {"strike_ease_s", number_into(f, arm.strike_ease_s, 0.01, 2.0)},
                {"lift_pause_s", number_into(f, arm.lift_pause_s, 0.01, 2.0)},
                {"level_time_s", number_into(f, arm.level_time_s, 0.01, 2.0)},
                {"hold_time_s", number_into(f, arm.hold_time_s, 0.01, 2.0)},
                {"release_time_s", number_into(f, arm.release_time_s, 0.01, 2.0)}});
  if (arm.push_accelerate_share + arm.push_decelerate_share > 1.0)
    f.fail(root["arm"],
           "push_accelerate_share and push_decelerate_share add up to more than 1: they are shares "
           "of one push");
  read_section(f, root, "physics",
               {{"timestep_s", number_into(f, c.physics.timestep_s, 0.0005, 0.005)},
                {"slide_timestep_s", number_into(f, c.physics.slide_timestep_s, 0.0005, 0.005)}});
  read_section(f, root, "sensors",
               {{"rate_hz", number_into(f, c.sensors.rate_hz, 10.0, 1000.0)},
                {"effort_noise_nm", number_into(f, c.sensors.effort_noise_nm, 0.0, 10.0)},
                {"force_noise_n", number_into(f, c.sensors.force_noise_n, 0.0, 100.0)}});
  return c;
}

}  // namespace

SimConfig parse_sim_config(const std::string& yaml_text, const std::string& source) {
  const YAML::Node root = parse_yaml(yaml_text, source);
  return read_yaml_guarded(source, [&] { return read_sim_config(YamlReader(source), root); });
}

SimConfig load_sim_config(const std::string& path) {
  return parse_sim_config(read_text_file(path, "sim config"), path);
}

double standard_normal(Rng& rng) {
  // Box-Muller; 1 - u keeps the logarithm's argument in (0, 1].
  const double u1 = 1.0 - uniform01(rng);
  const double u2 = uniform01(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

double TruncatedGaussian::draw(Rng& rng) const {
  return mean + stddev * std::clamp(standard_normal(rng), -3.0, 3.0);
}

ActionVariation sample_action(const VariabilityConfig& v, Rng& rng) {
  ActionVariation p;
  p.impact_speed = std::max(v.impact_speed.draw(rng), 0.001);
  // A tilt is an angle from vertical, so its sign is folded into the azimuth.
  p.impact_tilt_deg = std::abs(v.impact_tilt_deg.draw(rng));
  p.tilt_azimuth_deg = 360.0 * uniform01(rng);
  p.grasp_height = v.grasp_height.draw(rng);
  p.grasp_offset_x = v.grasp_offset.draw(rng);
  p.grasp_offset_y = v.grasp_offset.draw(rng);
  p.push_speed = std::max(v.push_speed.draw(rng), 0.001);
  p.push_offset = v.push_offset.draw(rng);
  return p;
}

std::vector<std::pair<std::string, double>> ActionVariation::named() const {
  return {{"impact_speed", impact_speed},
          {"impact_tilt_deg", impact_tilt_deg},
          {"tilt_azimuth_deg", tilt_azimuth_deg},
          {"grasp_height", grasp_height},
          {"grasp_offset_x", grasp_offset_x},
          {"grasp_offset_y", grasp_offset_y},
          {"push_speed", push_speed},
          {"push_offset", push_offset}};
}

ObjectPlacement sample_placement(const VariabilityConfig& v, Rng& rng) {
  ObjectPlacement s;
  s.placement_x = v.placement_x.draw(rng);
  s.placement_y = v.placement_y.draw(rng);
  s.orientation_deg = 360.0 * uniform01(rng);
  return s;
}

std::vector<std::pair<std::string, double>> ObjectPlacement::named() const {
  return {{"placement_x", placement_x},
          {"placement_y", placement_y},
          {"orientation_deg", orientation_deg}};
}

}  // namespace echoplan::sim
