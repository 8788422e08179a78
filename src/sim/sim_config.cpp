#include "sim/sim_config.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <sstream>

#include "common/error.h"
#include "sim/yaml_file.h"

namespace echoplan::sim {

namespace {

[[noreturn]] void fail(const std::string& source, const YAML::Node& at,
                       const std::string& problem) {
  throw InputError(source, at.Mark().line + 1, problem);
}

double read_number(const std::string& source, const YAML::Node& v, const std::string& field,
                   double low, double high) {
  double x = 0;
  try {
    x = v.as<double>();
  } catch (const YAML::Exception&) {
    fail(source, v, "'" + field + "' must be a number");
  }
  if (!std::isfinite(x) || x < low || x > high) {
    std::ostringstream msg;
    msg << "'" << field << "' = " << x << " is out of range [" << low << ", " << high << "]";
    fail(source, v, msg.str());
  }
  return x;
}

// One section of the config: a table of field name -> setter, so unknown fields are reported
// instead of silently ignored (a misspelt spread would otherwise keep its default).
using FieldSetters =
    std::map<std::string, std::function<void(const YAML::Node&, const std::string&)>>;

void read_section(const std::string& source, const YAML::Node& root, const std::string& name,
                  const FieldSetters& fields) {
  const YAML::Node section = root[name];
  if (!section) return;
  if (!section.IsMap()) fail(source, section, "'" + name + "' must be a mapping");
  for (const auto& kv : section) {
    const auto key = kv.first.as<std::string>();
    auto it = fields.find(key);
    if (it == fields.end()) {
      std::string known;
      for (const auto& [k, f] : fields) known += (known.empty() ? "" : ", ") + k;
      fail(source, kv.first, "unknown field '" + name + "." + key + "' (known: " + known + ")");
    }
    it->second(kv.second, name + "." + key);
  }
}

std::function<void(const YAML::Node&, const std::string&)> number_into(const std::string& source,
                                                                       double& target, double low,
                                                                       double high) {
  return [&source, &target, low, high](const YAML::Node& v, const std::string& field) {
    target = read_number(source, v, field, low, high);
  };
}

std::function<void(const YAML::Node&, const std::string&)> spread_into(const std::string& source,
                                                                       Spread& target, double low,
                                                                       double high) {
  return [&source, &target, low, high](const YAML::Node& v, const std::string& field) {
    if (!v.IsMap() || !v["mean"] || !v["spread"] || v.size() != 2)
      fail(source, v, "'" + field + "' must be {mean: ..., spread: ...}");
    target.mean = read_number(source, v["mean"], field + ".mean", low, high);
    target.spread = read_number(source, v["spread"], field + ".spread", 0.0, high - low);
  };
}

}  // namespace

SimConfig parse_sim_config(const std::string& yaml_text, const std::string& source) {
  const YAML::Node root = parse_yaml(yaml_text, source);
  SimConfig c;
  if (root.IsNull()) return c;
  if (!root.IsMap()) fail(source, root, "a sim config must be a mapping of sections");
  const std::vector<std::string> sections{"variability", "microphone", "room", "recording",
                                          "physics"};
  for (const auto& kv : root) {
    const auto key = kv.first.as<std::string>();
    if (std::find(sections.begin(), sections.end(), key) == sections.end())
      fail(source, kv.first,
           "unknown section '" + key +
               "' (known: variability, microphone, room, recording, physics)");
  }
  auto& v = c.variability;
  read_section(source, root, "variability",
               {{"impact_speed", spread_into(source, v.impact_speed, 0.005, 1.0)},
                {"impact_tilt_deg", spread_into(source, v.impact_tilt_deg, 0.0, 30.0)},
                {"grasp_height", spread_into(source, v.grasp_height, -0.05, 0.20)},
                {"grasp_offset", spread_into(source, v.grasp_offset, -0.02, 0.02)},
                {"push_speed", spread_into(source, v.push_speed, 0.005, 0.5)},
                {"push_offset", spread_into(source, v.push_offset, -0.02, 0.02)},
                {"placement_x", spread_into(source, v.placement_x, -0.05, 0.05)},
                {"placement_y", spread_into(source, v.placement_y, -0.05, 0.05)},
                {"microphone_distance", spread_into(source, v.microphone_distance, -0.3, 0.3)},
                {"background_db", spread_into(source, v.background_db, -20.0, 20.0)}});
  auto& mic = c.microphone;
  read_section(source, root, "microphone",
               {{"position",
                 [&](const YAML::Node& n, const std::string& field) {
                   if (!n.IsSequence() || n.size() != 3)
                     fail(source, n, "'" + field + "' must be [x, y, z] in metres");
                   for (int k = 0; k < 3; ++k)
                     mic.position[k] = read_number(source, n[k], field, -10.0, 10.0);
                 }},
                {"capsule_spacing", number_into(source, mic.capsule_spacing, 0.0, 1.0)}});
  auto& room = c.room;
  read_section(source, root, "room",
               {{"rt60_s", number_into(source, room.rt60_s, 0.01, 5.0)},
                {"length_s", number_into(source, room.length_s, 0.001, 0.5)},
                {"taps_per_s", number_into(source, room.taps_per_s, 10.0, 20000.0)},
                {"reverb_level", number_into(source, room.reverb_level, 0.0, 2.0)}});
  auto& rec = c.recording;
  double sample_rate = rec.sample_rate;
  read_section(source, root, "recording",
               {{"sample_rate", number_into(source, sample_rate, 8000.0, 192000.0)},
                {"duration_s", number_into(source, rec.duration_s, 0.1, 60.0)},
                {"noise_dbfs", number_into(source, rec.noise_dbfs, -200.0, 0.0)},
                {"output_gain", number_into(source, rec.output_gain, 0.0, 1000.0)},
                {"friction_gain", number_into(source, rec.friction_gain, 0.0, 1000.0)}});
  rec.sample_rate = static_cast<int>(std::lround(sample_rate));
  read_section(source, root, "physics",
               {{"timestep_s", number_into(source, c.physics.timestep_s, 0.0005, 0.005)}});
  return c;
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

namespace {

double draw(const Spread& s, Rng& rng) {
  return s.mean + s.spread * std::clamp(standard_normal(rng), -3.0, 3.0);
}

}  // namespace

ActionVariation sample_action(const VariabilityConfig& v, Rng& rng) {
  ActionVariation p;
  p.impact_speed = std::max(draw(v.impact_speed, rng), 0.001);
  // A tilt is an angle from vertical, so its sign is folded into the azimuth.
  p.impact_tilt_deg = std::abs(draw(v.impact_tilt_deg, rng));
  p.tilt_azimuth_deg = 360.0 * uniform01(rng);
  p.grasp_height = draw(v.grasp_height, rng);
  p.grasp_offset_x = draw(v.grasp_offset, rng);
  p.grasp_offset_y = draw(v.grasp_offset, rng);
  p.push_speed = std::max(draw(v.push_speed, rng), 0.001);
  p.push_offset = draw(v.push_offset, rng);
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

TrialSetup sample_setup(const VariabilityConfig& v, Rng& rng) {
  TrialSetup s;
  s.placement_x = draw(v.placement_x, rng);
  s.placement_y = draw(v.placement_y, rng);
  s.orientation_deg = 360.0 * uniform01(rng);
  return s;
}

std::vector<std::pair<std::string, double>> TrialSetup::named() const {
  return {{"placement_x", placement_x},
          {"placement_y", placement_y},
          {"orientation_deg", orientation_deg}};
}

}  // namespace echoplan::sim
