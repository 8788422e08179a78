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
  double loss_factor = 0;  // damping it adds to the object's modes (putty, glued coins), >= 0
  // Hz; 0 fixes it rigidly. The natural frequency of the mass on its fixing (tape, a rubber band):
  // the arm carries its weight, but far above this frequency (an impact, a mode) it stays still.
  double mount_hz = 0;

  // The share of the mass that moves with the object at `frequency_hz`: 1 when rigid, else a
  // heavily damped mount's transmissibility 1 / (1 + (f / mount_hz)^2) (critical damping: tape and
  // putty).
  double share_at(double frequency_hz) const;
};

// A rigid object the robot can slide or strike: a thin-walled cylinder with a base.
struct ObjectSpec {
  std::string name;
  std::string shape = "cylinder_shell";  // the only shape so far
  double radius = 0;                     // m, outer radius, > 0
  double height = 0;                     // m, > 0
  double wall_thickness = 0;             // m, in (0, radius)
  double base_thickness = 0;             // m, > 0
  double base_radius =
      0;  // m, of the base plate (a tapered cup\'s is smaller than its rim); 0 = radius
  double shell_mass = 0;  // kg, the object itself without added mass, > 0
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
  // The mass a force at `frequency_hz` moves: the shell and each added mass's share at it.
  double mass_at(double frequency_hz) const;
  std::array<double, 3> centre_of_mass() const;
  std::array<double, 3> inertia_diagonal() const;

  // What a force at `frequency_hz` moves, as a rigid body: this object with each added mass cut to
  // the share of it that follows (AddedMass::share_at).
  ObjectSpec moving_at(double frequency_hz) const;
  // The effective mass (kg) of this object, free, pushed up along its axis at the rim of its base
  // at `azimuth_rad`: 1 / (1/m + (r x n)^T I^-1 (r x n)), r from the centre of mass to that point.
  double rim_effective_mass(double azimuth_rad) const;
};

// The table's top as a plate whose modes above a few hundred hertz are too dense to list: `count`
// modes spread evenly in log frequency over [from_hz, to_hz], at equal gain (a plate's point
// mobility does not depend on frequency), each decaying with the table material's damping.
struct DenseModes {
  double from_hz = 0, to_hz = 0;
  int count = 0;
};

// The table: its material (for contact stiffness and its modes' damping), friction, its own listed
// modes and its dense modal field, and the damping of an object held against it.
struct TableSpec {
  std::string name;  // the catalogue's name for it (a world or a training set chooses by name)
  Material material;
  // The top's surface layer that a contact presses on (a laminate on an MDF core): a Hertz contact
  // a fraction of a millimetre wide stresses the top millimetre, so its modulus sets the contact's
  // stiffness and its loss the contact ring's. The same as `material` unless the catalogue names
  // one.
  Material surface;
  double friction = 0.45;
  double thickness = 0.025;  // m, of the top: sets its coincidence frequency (how well it radiates)
  std::vector<ListedMode> modes;
  DenseModes dense;
  // Loss factor added to every mode of an object that rings while pressed onto the table (energy
  // flows into it). The holding finger pads add their own c / (2 m) (kFingerPadDamping).
  double contact_loss_factor = 0.0;
};

struct Catalogue {
  std::string source;  // the file it was read from (for messages)
  std::map<std::string, Material> materials;
  TableSpec table;                          // the default: the lab's (`table:`)
  std::map<std::string, TableSpec> tables;  // every table by name, the default's too (`tables:`)
  std::map<std::string, ObjectSpec> objects;

  // The object called `name`; throws InputError listing the known names if there is none.
  const ObjectSpec& object(const std::string& name) const;
  std::vector<std::string> object_names() const;  // sorted
  // The table called `name` (empty: the default); throws InputError listing the known names.
  const TableSpec& table_named(const std::string& name) const;
  std::vector<std::string> table_names() const;  // sorted
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
