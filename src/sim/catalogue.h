// The object catalogue: materials, the table and the objects the simulator can handle, read from
// YAML (objects/catalogue.yaml; format in docs/simulator.md).
//
// Everything here is a plain value that never changes after loading. A modified object (an original
// plus an added mass) is resolved at load time into a full ObjectSpec whose mass, centre of mass
// and inertia include the added mass, so the rest of the simulator sees one kind of object.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

namespace echoplan::sim {

// A linear elastic material with Rayleigh damping (D = alpha*M + beta*K).
struct Material {
  std::string name;
  double density = 0;         // kg/m^3, > 0
  double youngs_modulus = 0;  // Pa, > 0
  double poisson_ratio = 0;   // in [0, 0.5)
  double alpha = 0;           // 1/s, >= 0 (mass-proportional damping)
  double beta = 0;            // s, >= 0 (stiffness-proportional damping)

  // Decay rate (1/s) of a mode at `frequency_hz`: alpha/2 + beta*omega^2/2.
  double decay_rate(double frequency_hz) const;
};

// One vibration mode as listed in the catalogue: frequency and relative gain. Its decay comes from
// the material unless `decay` is given (> 0, 1/s).
struct ListedMode {
  double frequency = 0;  // Hz, > 0
  double gain = 1;       // relative amplitude, >= 0
  double decay = 0;      // 1/s; 0 = from the material's Rayleigh damping
};

// A point mass added to an object (the "weighted" variants), in the object's frame: origin at the
// centre of its base, z along its axis.
struct AddedMass {
  double mass = 0;                   // kg, > 0
  std::array<double, 3> position{};  // m
};

// A rigid object the robot can slide or strike: a thin-walled cylinder with a base.
struct ObjectSpec {
  std::string name;
  std::string shape = "cylinder_shell";  // the only shape so far
  double radius = 0;                     // m, outer radius, > 0
  double height = 0;                     // m, > 0
  double wall_thickness = 0;             // m, in (0, radius)
  double base_thickness = 0;             // m, > 0
  double shell_mass = 0;                 // kg, the object itself without added mass, > 0
  Material material;
  bool closed = false;                   // a closed tube: its air column rings at c/2L
  double contact_radius = 0;             // m, radius of curvature of the rim meeting the table, > 0
  double friction = 0.4;                 // Coulomb coefficient against the table, > 0
  int ring_modes = 4;                    // shell ring modes n = 2..ring_modes derived from geometry
  std::vector<ListedMode> listed_modes;  // if non-empty, used instead of derived modes
  std::vector<AddedMass> added_masses;   // empty for an original object
  std::string base_object;               // the original this one modifies; empty for an original

  // Rigid-body properties including added masses: total mass (kg), centre of mass (m, object frame)
  // and the diagonal of the inertia tensor about the centre of mass (kg m^2, object axes).
  double total_mass() const;
  std::array<double, 3> centre_of_mass() const;
  std::array<double, 3> inertia_diagonal() const;
};

// The table: its material (for contact stiffness), friction and its own listed modes.
struct TableSpec {
  Material material;
  double friction = 0.45;
  std::vector<ListedMode> modes;
};

struct Catalogue {
  std::string source;  // the file it was read from (for messages)
  std::map<std::string, Material> materials;
  TableSpec table;
  std::map<std::string, ObjectSpec> objects;

  // The object called `name`; throws InputError listing the known names if there is none.
  const ObjectSpec& object(const std::string& name) const;
  std::vector<std::string> object_names() const;  // sorted
};

// Reads a catalogue file. Throws echoplan::InputError naming the file, the line and the entry for a
// missing field, a value out of range (e.g. a negative mass), an unknown material or base object.
Catalogue load_catalogue(const std::string& path);

// As load_catalogue, from YAML text; `source` names it in error messages.
Catalogue parse_catalogue(const std::string& yaml_text, const std::string& source);

// The catalogue shipped with echoplan: objects/catalogue.yaml in the working directory if it
// exists, else the one shipped with echoplan (common/data_dir.h says where that is found).
std::string default_catalogue_path();

}  // namespace echoplan::sim
