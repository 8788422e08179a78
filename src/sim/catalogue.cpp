#include "sim/catalogue.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <sstream>

#include "common/data_dir.h"
#include "common/error.h"
#include "common/file_io.h"
#include "common/yaml_reader.h"

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

double AddedMass::share_at(double frequency_hz) const {
  if (mount_hz <= 0) return 1.0;
  const double r = frequency_hz / mount_hz;
  return 1.0 / (1.0 + r * r);
}

double ObjectSpec::mass_at(double frequency_hz) const {
  double m = shell_mass;
  for (const auto& a : added_masses) m += a.mass * a.share_at(frequency_hz);
  return m;
}

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

ObjectSpec ObjectSpec::moving_at(double frequency_hz) const {
  ObjectSpec moving = *this;
  for (auto& a : moving.added_masses) {
    a.mass *= a.share_at(frequency_hz);
    a.mount_hz = 0;  // what is left of it moves with the object
  }
  return moving;
}

double ObjectSpec::rim_effective_mass(double azimuth_rad) const {
  const auto com = centre_of_mass();
  const auto inertia = inertia_diagonal();
  // r x n with n = z: (r_y, -r_x, 0).
  const double rx = radius * std::cos(azimuth_rad) - com[0];
  const double ry = radius * std::sin(azimuth_rad) - com[1];
  return 1.0 / (1.0 / total_mass() + ry * ry / inertia[0] + rx * rx / inertia[1]);
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

const TableSpec& Catalogue::table_named(const std::string& name) const {
  if (name.empty()) return table;
  auto it = tables.find(name);
  if (it != tables.end()) return it->second;
  std::string known;
  for (const auto& n : table_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError(source, 0, "unknown table '" + name + "' (the catalogue has: " + known + ")");
}

std::vector<std::string> Catalogue::table_names() const {
  std::vector<std::string> names;
  for (const auto& [name, spec] : tables) names.push_back(name);
  return names;
}

namespace {

Material read_material(const YamlReader& f, const std::string& name, const YAML::Node& node) {
  const YamlMapping r(f, "materials." + name, node);
  r.only_keys({"density", "youngs_modulus", "poisson_ratio", "alpha", "beta"});
  Material m;
  m.name = name;
  m.density = r.number("density", NumberRange::above(0));
  m.youngs_modulus = r.number("youngs_modulus", NumberRange::above(0));
  m.poisson_ratio = r.number("poisson_ratio", NumberRange::at_least(0).below(0.5));
  m.alpha = r.number("alpha", NumberRange::at_least(0));
  m.beta = r.number("beta", NumberRange::at_least(0));
  return m;
}

std::vector<ListedMode> read_modes(const YamlReader& f, const std::string& entry,
                                   const YAML::Node& node) {
  if (!node.IsSequence()) f.fail(node, entry + ".modes must be a list of {frequency, gain, decay}");
  std::vector<ListedMode> modes;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlMapping r(f, entry + ".modes[" + std::to_string(i) + "]", node[i]);
    r.only_keys({"frequency", "gain", "decay"});
    ListedMode mode;
    mode.frequency = r.number("frequency", NumberRange::above(0));
    mode.gain = r.number_or("gain", 1.0, NumberRange::at_least(0));
    mode.decay = r.number_or("decay", 0.0, NumberRange::at_least(0));
    modes.push_back(mode);
  }
  return modes;
}

const Material& find_material(const Catalogue& c, const YamlMapping& r) {
  const std::string name = r.name("material");
  auto it = c.materials.find(name);
  if (it == c.materials.end()) r.fail(r.node()["material"], "unknown material '" + name + "'");
  return it->second;
}

// The default table's name when `table:` gives none.
constexpr const char* kDefaultTableName = "table";

const Material& find_surface(const Catalogue& c, const YamlMapping& r) {
  const std::string name = r.name("surface");
  auto it = c.materials.find(name);
  if (it == c.materials.end()) r.fail(r.node()["surface"], "unknown material '" + name + "'");
  return it->second;
}

// A table's fields (the default's under `table:` or a named one under `tables:`); `name` unless
// the mapping gives its own.
TableSpec read_table(const Catalogue& c, const YamlMapping& r, const std::string& name) {
  r.only_keys({"name", "material", "surface", "friction", "modes", "dense_modes", "thickness",
               "contact_loss_factor"});
  TableSpec t;
  t.name = r.has("name") ? r.name("name") : name;
  t.material = find_material(c, r);
  t.surface = r.has("surface") ? find_surface(c, r) : t.material;
  t.friction = r.number_or("friction", 0.45, NumberRange::above(0));
  if (r.has("modes")) t.modes = read_modes(r.reader(), r.entry(), r.node()["modes"]);
  if (r.has("dense_modes")) {
    const YamlMapping dense(r.reader(), r.entry() + ".dense_modes", r.node()["dense_modes"]);
    dense.only_keys({"from", "to", "count"});
    t.dense.from_hz = dense.number("from", NumberRange::above(0));
    t.dense.to_hz = dense.number("to", NumberRange::above(t.dense.from_hz));
    t.dense.count = static_cast<int>(dense.number("count", NumberRange::at_least(1).below(1000)));
  }
  t.thickness = r.number_or("thickness", 0.025, NumberRange::above(0));
  t.contact_loss_factor =
      r.number_or("contact_loss_factor", 0.0, NumberRange::at_least(0).below(1.0));
  return t;
}

// `tables:`: the other tables by name, each with every field of its own (a named table is a
// whole table, not a change to the default, so nothing is inherited silently).
void read_named_tables(Catalogue& c, const YamlMapping& top) {
  const YAML::Node tables = top.node()["tables"];
  if (!tables.IsMap() || tables.size() == 0) top.fail(tables, "'tables' must map names to tables");
  for (const auto& kv : tables) {
    const std::string name = top.reader().name(kv.first, "each key of 'tables'");
    const YamlMapping r(top.reader(), "tables." + name, kv.second);
    if (r.has("name")) r.fail(r.node()["name"], "a named table's name is its key");
    for (const char* key : {"friction", "thickness", "contact_loss_factor"}) r.required(key);
    if (c.tables.count(name))
      top.reader().fail(
          kv.first, "table '" + name + "' is named twice (the default is '" + c.table.name + "')");
    c.tables[name] = read_table(c, r, name);
  }
}

ObjectSpec read_original(const Catalogue& c, const std::string& name, const YamlMapping& r) {
  r.only_keys({"shape", "radius", "height", "wall_thickness", "base_thickness", "mass",
               "base_radius", "material", "closed", "contact_radius", "friction", "ring_modes",
               "modes"});
  ObjectSpec o;
  o.name = name;
  o.shape = r.name("shape");
  if (o.shape != "cylinder_shell")
    r.fail(r.node()["shape"], "unknown shape '" + o.shape + "' (known: cylinder_shell)");
  o.radius = r.number("radius", NumberRange::above(0));
  o.height = r.number("height", NumberRange::above(0));
  o.wall_thickness = r.number("wall_thickness", NumberRange::above(0).below(o.radius));
  o.base_thickness = r.number("base_thickness", NumberRange::above(0).below(o.height));
  o.shell_mass = r.number("mass", NumberRange::above(0));
  o.base_radius = r.number_or("base_radius", 0.0, NumberRange::at_least(0).below(o.radius + 1e-12));
  o.material = find_material(c, r);
  o.closed = r.boolean_or("closed", false);
  o.contact_radius = r.number("contact_radius", NumberRange::above(0));
  o.friction = r.number_or("friction", 0.4, NumberRange::above(0));
  o.ring_modes = static_cast<int>(r.number_or("ring_modes", 4, NumberRange::at_least(2).below(13)));
  if (r.has("modes")) o.listed_modes = read_modes(r.reader(), r.entry(), r.node()["modes"]);
  return o;
}

// A modified object is its original plus an added mass, nothing else: a field of the original here
// (a new radius, say) would silently be ignored, so it is rejected like a misspelt one.
ObjectSpec read_modified(const Catalogue& c, const std::string& name, const YamlMapping& r) {
  r.only_keys({"base", "added_mass"});
  const std::string base = r.name("base");
  auto it = c.objects.find(base);
  if (it == c.objects.end() || !it->second.base_object.empty())
    r.fail(r.node()["base"],
           "unknown base object '" + base + "' (it must be an original object listed above)");
  ObjectSpec o = it->second;
  o.name = name;
  o.base_object = base;
  const YamlMapping added(r.reader(), r.entry() + ".added_mass", r.required("added_mass"));
  added.only_keys({"mass", "position", "loss_factor", "mount_hz"});
  AddedMass a;
  a.mass = added.number("mass", NumberRange::above(0));
  const std::vector<double> position = added.numbers("position", 3);  // [x, y, z] in metres
  std::copy(position.begin(), position.end(), a.position.begin());
  a.loss_factor = added.number_or("loss_factor", 0.0, NumberRange::at_least(0).below(1.0));
  a.mount_hz = added.number_or("mount_hz", 0.0, NumberRange::at_least(0));
  o.added_masses.push_back(a);
  return o;
}

}  // namespace

namespace {

Catalogue read_catalogue(const YamlReader& f, const YAML::Node& root) {
  Catalogue c;
  c.source = f.file();
  const YamlMapping top(f, "the catalogue", root);
  top.only_keys({"materials", "table", "tables", "objects"});

  const YAML::Node materials = top.required("materials");
  if (!materials.IsMap()) top.fail(materials, "'materials' must map names to materials");
  for (const auto& kv : materials) {
    const std::string name = f.name(kv.first, "each key of 'materials'");
    c.materials[name] = read_material(f, name, kv.second);
  }

  c.table = read_table(c, YamlMapping(f, "table", top.required("table")), kDefaultTableName);
  c.tables[c.table.name] = c.table;
  if (top.has("tables")) read_named_tables(c, top);

  // Originals first, so a modified object can name any original regardless of order in the file.
  const YAML::Node objects = top.required("objects");
  if (!objects.IsMap() || objects.size() == 0)
    top.fail(objects, "'objects' must map names to objects");
  for (const auto& kv : objects) {
    const std::string name = f.name(kv.first, "each key of 'objects'");
    const YamlMapping r(f, "objects." + name, kv.second);
    if (!r.has("base")) c.objects[name] = read_original(c, name, r);
  }
  for (const auto& kv : objects) {
    const std::string name = f.name(kv.first, "each key of 'objects'");
    const YamlMapping r(f, "objects." + name, kv.second);
    if (r.has("base")) c.objects[name] = read_modified(c, name, r);
  }
  return c;
}

}  // namespace

Catalogue parse_catalogue(const std::string& yaml_text, const std::string& source) {
  const YAML::Node root = parse_yaml(yaml_text, source);
  return read_yaml_guarded(source, [&] { return read_catalogue(YamlReader(source), root); });
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
