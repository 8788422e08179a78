#include "sim/catalogue.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <sstream>

#include "common/data_dir.h"
#include "common/error.h"
#include "sim/yaml_file.h"

namespace echoplan::sim {

double Material::decay_rate(double frequency_hz) const {
  const double omega = 2.0 * std::numbers::pi * frequency_hz;
  return alpha / 2.0 + beta * omega * omega / 2.0;
}

namespace {

// The wall (a tube) and the base (a disc) share the object's own mass in proportion to their
// volumes.
struct ShellParts {
  double wall_mass, base_mass;
};

ShellParts split_shell_mass(const ObjectSpec& o) {
  const double wall_volume = 2.0 * std::numbers::pi * o.radius * o.wall_thickness * o.height;
  const double base_volume = std::numbers::pi * o.radius * o.radius * o.base_thickness;
  const double wall_share = wall_volume / (wall_volume + base_volume);
  return {o.shell_mass * wall_share, o.shell_mass * (1.0 - wall_share)};
}

}  // namespace

double ObjectSpec::total_mass() const {
  double m = shell_mass;
  for (const auto& a : added_masses) m += a.mass;
  return m;
}

std::array<double, 3> ObjectSpec::centre_of_mass() const {
  const auto parts = split_shell_mass(*this);
  std::array<double, 3> moment{
      0.0, 0.0, parts.wall_mass * height / 2.0 + parts.base_mass * base_thickness / 2.0};
  for (const auto& a : added_masses)
    for (int k = 0; k < 3; ++k) moment[k] += a.mass * a.position[k];
  const double m = total_mass();
  return {moment[0] / m, moment[1] / m, moment[2] / m};
}

std::array<double, 3> ObjectSpec::inertia_diagonal() const {
  // Tube and disc about their own centres, then the parallel-axis theorem to the common centre of
  // mass; added masses are points. Products of inertia from off-axis added masses are neglected.
  const auto parts = split_shell_mass(*this);
  const auto com = centre_of_mass();
  const double r_in = radius - wall_thickness;
  const double r2 = radius * radius + r_in * r_in;
  std::array<double, 3> inertia{};
  auto add_body = [&](double m, double ixx, double izz, std::array<double, 3> at) {
    const double dx = at[0] - com[0], dy = at[1] - com[1], dz = at[2] - com[2];
    inertia[0] += ixx + m * (dy * dy + dz * dz);
    inertia[1] += ixx + m * (dx * dx + dz * dz);
    inertia[2] += izz + m * (dx * dx + dy * dy);
  };
  add_body(parts.wall_mass, parts.wall_mass * (r2 / 4.0 + height * height / 12.0),
           parts.wall_mass * r2 / 2.0, {0.0, 0.0, height / 2.0});
  add_body(parts.base_mass,
           parts.base_mass * (radius * radius / 4.0 + base_thickness * base_thickness / 12.0),
           parts.base_mass * radius * radius / 2.0, {0.0, 0.0, base_thickness / 2.0});
  for (const auto& a : added_masses) add_body(a.mass, 0.0, 0.0, a.position);
  return inertia;
}

const ObjectSpec& Catalogue::object(const std::string& name) const {
  auto it = objects.find(name);
  if (it != objects.end()) return it->second;
  std::string known;
  for (const auto& n : object_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError(source, 0, "unknown object '" + name + "' (the catalogue has: " + known + ")");
}

std::vector<std::string> Catalogue::object_names() const {
  std::vector<std::string> names;
  for (const auto& [name, spec] : objects) names.push_back(name);
  return names;
}

namespace {

// Reads fields of one YAML mapping, turning every problem into an InputError that names the file,
// the line of the offending node and the entry ("objects.coffee_mug") it belongs to.
class EntryReader {
 public:
  EntryReader(const std::string& source, std::string entry, const YAML::Node& node)
      : source_(source), entry_(std::move(entry)), node_(node) {
    if (!node_.IsMap()) fail(node_, "must be a mapping of fields");
  }

  [[noreturn]] void fail(const YAML::Node& at, const std::string& problem) const {
    const int line = at.IsDefined() ? at.Mark().line + 1 : node_.Mark().line + 1;
    throw InputError(source_, line, entry_ + ": " + problem);
  }

  bool has(const std::string& key) const { return static_cast<bool>(node_[key]); }
  YAML::Node child(const std::string& key) const { return node_[key]; }

  YAML::Node required(const std::string& key) const {
    YAML::Node v = node_[key];
    if (!v) fail(node_, "missing field '" + key + "'");
    return v;
  }

  double number(const YAML::Node& v, const std::string& key) const {
    try {
      return v.as<double>();
    } catch (const YAML::Exception&) {
      fail(v, "field '" + key + "' must be a number");
    }
  }

  // A required number with lower bound `low` (strict if `strict`) and optional upper bound.
  double number(const std::string& key, double low, bool strict, double high = INFINITY) const {
    return checked(required(key), key, low, strict, high);
  }
  double number_or(const std::string& key, double fallback, double low, bool strict,
                   double high = INFINITY) const {
    return has(key) ? checked(node_[key], key, low, strict, high) : fallback;
  }

  double checked(const YAML::Node& v, const std::string& key, double low, bool strict,
                 double high) const {
    const double x = number(v, key);
    if (!std::isfinite(x) || (strict ? x <= low : x < low) || x >= high) {
      std::ostringstream msg;
      msg << "field '" << key << "' = " << x << " must be " << (strict ? "> " : ">= ") << low;
      if (std::isfinite(high)) msg << " and < " << high;
      fail(v, msg.str());
    }
    return x;
  }

  std::string text(const std::string& key) const {
    YAML::Node v = required(key);
    if (!v.IsScalar()) fail(v, "field '" + key + "' must be a name");
    return v.as<std::string>();
  }

  bool flag_or(const std::string& key, bool fallback) const {
    if (!has(key)) return fallback;
    try {
      return node_[key].as<bool>();
    } catch (const YAML::Exception&) {
      fail(node_[key], "field '" + key + "' must be true or false");
    }
  }

  const std::string& entry() const { return entry_; }

 private:
  const std::string& source_;
  std::string entry_;
  YAML::Node node_;
};

Material read_material(const std::string& source, const std::string& name, const YAML::Node& node) {
  EntryReader r(source, "materials." + name, node);
  Material m;
  m.name = name;
  m.density = r.number("density", 0, true);
  m.youngs_modulus = r.number("youngs_modulus", 0, true);
  m.poisson_ratio = r.number("poisson_ratio", 0, false, 0.5);
  m.alpha = r.number("alpha", 0, false);
  m.beta = r.number("beta", 0, false);
  return m;
}

std::vector<ListedMode> read_modes(const std::string& source, const std::string& entry,
                                   const YAML::Node& node) {
  if (!node.IsSequence())
    throw InputError(source, node.Mark().line + 1, entry + ": 'modes' must be a list");
  std::vector<ListedMode> modes;
  for (std::size_t i = 0; i < node.size(); ++i) {
    EntryReader r(source, entry + ".modes[" + std::to_string(i) + "]", node[i]);
    ListedMode mode;
    mode.frequency = r.number("frequency", 0, true);
    mode.gain = r.number_or("gain", 1.0, 0, false);
    mode.decay = r.number_or("decay", 0.0, 0, false);
    modes.push_back(mode);
  }
  return modes;
}

const Material& find_material(const Catalogue& c, const EntryReader& r) {
  const std::string name = r.text("material");
  auto it = c.materials.find(name);
  if (it == c.materials.end()) r.fail(r.child("material"), "unknown material '" + name + "'");
  return it->second;
}

ObjectSpec read_original(const Catalogue& c, const std::string& name, const EntryReader& r) {
  ObjectSpec o;
  o.name = name;
  o.shape = r.text("shape");
  if (o.shape != "cylinder_shell")
    r.fail(r.child("shape"), "unknown shape '" + o.shape + "' (known: cylinder_shell)");
  o.radius = r.number("radius", 0, true);
  o.height = r.number("height", 0, true);
  o.wall_thickness = r.number("wall_thickness", 0, true, o.radius);
  o.base_thickness = r.number("base_thickness", 0, true, o.height);
  o.shell_mass = r.number("mass", 0, true);
  o.material = find_material(c, r);
  o.closed = r.flag_or("closed", false);
  o.contact_radius = r.number("contact_radius", 0, true);
  o.friction = r.number_or("friction", 0.4, 0, true);
  o.ring_modes = static_cast<int>(r.number_or("ring_modes", 4, 2, false, 13));
  if (r.has("modes")) o.listed_modes = read_modes(c.source, r.entry(), r.child("modes"));
  return o;
}

ObjectSpec read_modified(const Catalogue& c, const std::string& name, const EntryReader& r) {
  const std::string base = r.text("base");
  auto it = c.objects.find(base);
  if (it == c.objects.end() || !it->second.base_object.empty())
    r.fail(r.child("base"),
           "unknown base object '" + base + "' (it must be an original object listed above)");
  ObjectSpec o = it->second;
  o.name = name;
  o.base_object = base;
  EntryReader added(c.source, r.entry() + ".added_mass", r.required("added_mass"));
  AddedMass a;
  a.mass = added.number("mass", 0, true);
  YAML::Node pos = added.required("position");
  if (!pos.IsSequence() || pos.size() != 3)
    added.fail(pos, "field 'position' must be [x, y, z] in metres");
  for (int k = 0; k < 3; ++k) a.position[k] = added.number(pos[k], "position");
  o.added_masses.push_back(a);
  return o;
}

}  // namespace

Catalogue parse_catalogue(const std::string& yaml_text, const std::string& source) {
  const YAML::Node root = parse_yaml(yaml_text, source);
  Catalogue c;
  c.source = source;
  EntryReader top(source, "catalogue", root);

  const YAML::Node materials = top.required("materials");
  if (!materials.IsMap()) top.fail(materials, "'materials' must map names to materials");
  for (const auto& kv : materials) {
    const auto name = kv.first.as<std::string>();
    c.materials[name] = read_material(source, name, kv.second);
  }

  EntryReader table(source, "table", top.required("table"));
  c.table.material = find_material(c, table);
  c.table.friction = table.number_or("friction", 0.45, 0, true);
  c.table.modes = read_modes(source, "table", table.required("modes"));

  // Originals first, so a modified object can name any original regardless of order in the file.
  const YAML::Node objects = top.required("objects");
  if (!objects.IsMap() || objects.size() == 0)
    top.fail(objects, "'objects' must map names to objects");
  for (const auto& kv : objects) {
    const auto name = kv.first.as<std::string>();
    EntryReader r(source, "objects." + name, kv.second);
    if (!r.has("base")) c.objects[name] = read_original(c, name, r);
  }
  for (const auto& kv : objects) {
    const auto name = kv.first.as<std::string>();
    EntryReader r(source, "objects." + name, kv.second);
    if (r.has("base")) c.objects[name] = read_modified(c, name, r);
  }
  return c;
}

Catalogue load_catalogue(const std::string& path) {
  return parse_catalogue(read_text_file(path, "object catalogue"), path);
}

std::string default_catalogue_path() {
  const std::string local = "objects/catalogue.yaml";
  if (std::filesystem::exists(local)) return local;
  return shipped_file("objects/catalogue.yaml");
}

}  // namespace echoplan::sim
