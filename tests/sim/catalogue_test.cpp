#include "sim/catalogue.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../common/source_dir.h"
#include "common/error.h"

namespace echoplan::sim {
namespace {

const std::string kCatalogue = echoplan::testing::source_dir() + "/objects/catalogue.yaml";

// A small valid catalogue; tests break one thing at a time.
const std::string kValid = R"(materials:
  ceramic: {density: 2700, youngs_modulus: 7.2e10, poisson_ratio: 0.19, alpha: 6, beta: 1.0e-7}
  wood: {density: 750, youngs_modulus: 1.1e10, poisson_ratio: 0.25, alpha: 60, beta: 2.0e-6}
table:
  material: wood
  modes:
    - {frequency: 150, gain: 0.5}
objects:
  mug:
    shape: cylinder_shell
    radius: 0.04
    height: 0.1
    wall_thickness: 0.005
    base_thickness: 0.006
    mass: 0.3
    material: ceramic
    contact_radius: 0.004
  heavy_mug:
    base: mug
    added_mass: {mass: 0.2, position: [0, 0, 0.01]}
)";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// Parses `text` expecting an InputError; returns it so the caller can check where it points.
InputError parse_error(const std::string& text) {
  try {
    parse_catalogue(text, "test.yaml");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError("", 0, "");
}

TEST(Catalogue, ShippedCatalogueHasTheProjectsObjects) {
  const Catalogue c = load_catalogue(kCatalogue);
  for (const char* name : {"pringles_can", "coffee_mug", "plastic_cup", "paper_base",
                           "pringles_can_weighted", "coffee_mug_weighted"})
    EXPECT_TRUE(c.objects.count(name)) << name;
  for (const char* name :
       {"ceramic", "glass", "wood", "plastic", "polycarbonate", "steel", "paper", "cardboard"})
    EXPECT_TRUE(c.materials.count(name)) << name;
  EXPECT_DOUBLE_EQ(c.materials.at("ceramic").youngs_modulus, 7.2e10);
  EXPECT_DOUBLE_EQ(c.materials.at("steel").beta, 8e-8);
}

TEST(Catalogue, ModifiedObjectIsTheOriginalPlusItsAddedMass) {
  const Catalogue c = parse_catalogue(kValid, "test.yaml");
  const ObjectSpec& mug = c.object("mug");
  const ObjectSpec& heavy = c.object("heavy_mug");
  EXPECT_EQ(heavy.base_object, "mug");
  EXPECT_DOUBLE_EQ(heavy.total_mass(), 0.5);
  EXPECT_DOUBLE_EQ(heavy.radius, mug.radius);
  EXPECT_EQ(heavy.material.name, "ceramic");
  // The added mass sits low, so the centre of mass drops: mass-weighted mean of the two.
  const double expected_z = (0.3 * mug.centre_of_mass()[2] + 0.2 * 0.01) / 0.5;
  EXPECT_NEAR(heavy.centre_of_mass()[2], expected_z, 1e-12);
  EXPECT_GT(heavy.inertia_diagonal()[0], mug.inertia_diagonal()[0]);
}

// A mass on a loose mount (tape) is carried by the arm but stays still at audio frequencies: the
// share that follows is a critically damped mount's transmissibility, 1 / (1 + (f / f_mount)^2).
TEST(Catalogue, ALooseMountsMassFollowsTheObjectOnlyBelowItsFrequency) {
  const Catalogue rigid = parse_catalogue(kValid, "test.yaml");
  EXPECT_EQ(rigid.object("heavy_mug").added_masses.at(0).mount_hz, 0.0);
  EXPECT_DOUBLE_EQ(rigid.object("heavy_mug").mass_at(5000), 0.5);
  const Catalogue loose = parse_catalogue(
      replace(kValid, "position: [0, 0, 0.01]}", "position: [0, 0, 0.01], mount_hz: 50}"),
      "test.yaml");
  const ObjectSpec& heavy = loose.object("heavy_mug");
  EXPECT_EQ(heavy.added_masses.at(0).mount_hz, 50.0);
  EXPECT_DOUBLE_EQ(heavy.total_mass(), 0.5);  // the arm carries it all
  EXPECT_DOUBLE_EQ(heavy.mass_at(50), 0.3 + 0.2 / 2);
  EXPECT_DOUBLE_EQ(heavy.mass_at(500), 0.3 + 0.2 / 101);
  EXPECT_NEAR(heavy.mass_at(0.001), 0.5, 1e-9);
  const InputError e = parse_error(
      replace(kValid, "position: [0, 0, 0.01]}", "position: [0, 0, 0.01], mount_hz: -5}"));
  EXPECT_EQ(e.line(), 20);
  EXPECT_NE(e.problem().find("mount_hz"), std::string::npos) << e.problem();
}

TEST(Catalogue, InertiaOfAThinTubeMatchesTheTextbookFormula) {
  // A tube with a negligible base: I_zz -> m (R^2 + r^2) / 2, I_xx -> m ((R^2 + r^2)/4 + H^2/12).
  ObjectSpec tube;
  tube.radius = 0.05;
  tube.height = 0.2;
  tube.wall_thickness = 0.001;
  tube.base_thickness = 1e-9;
  tube.shell_mass = 0.1;
  const double r2 = 0.05 * 0.05 + 0.049 * 0.049;
  const auto inertia = tube.inertia_diagonal();
  // The vanishing base shifts the centre of mass by ~1e-9 m: far below these tolerances.
  EXPECT_NEAR(inertia[2], 0.1 * r2 / 2, 1e-9);
  EXPECT_NEAR(inertia[0], 0.1 * (r2 / 4 + 0.2 * 0.2 / 12), 1e-9);
}

TEST(Catalogue, NegativeMassNamesFileLineAndEntry) {
  const InputError e = parse_error(replace(kValid, "mass: 0.3", "mass: -0.3"));
  EXPECT_EQ(e.file(), "test.yaml");
  EXPECT_EQ(e.line(), 15);
  EXPECT_NE(e.problem().find("objects.mug"), std::string::npos) << e.what();
  EXPECT_NE(e.problem().find("mass"), std::string::npos) << e.what();
}

TEST(Catalogue, UnknownMaterialNamesTheEntry) {
  const InputError e = parse_error(replace(kValid, "material: ceramic", "material: unobtainium"));
  EXPECT_EQ(e.line(), 16);
  EXPECT_NE(e.problem().find("objects.mug"), std::string::npos) << e.what();
  EXPECT_NE(e.problem().find("unknown material 'unobtainium'"), std::string::npos) << e.what();
}

TEST(Catalogue, TableSurfaceIsTheTopMaterialUnlessNamed) {
  const Catalogue plain = parse_catalogue(kValid, "test.yaml");
  EXPECT_EQ(plain.table.surface.name, "wood");
  const Catalogue laminated = parse_catalogue(
      replace(kValid, "  material: wood\n", "  material: wood\n  surface: ceramic\n"), "test.yaml");
  EXPECT_EQ(laminated.table.material.name, "wood");
  EXPECT_EQ(laminated.table.surface.name, "ceramic");
  EXPECT_DOUBLE_EQ(laminated.table.surface.youngs_modulus, 7.2e10);
  const InputError e =
      parse_error(replace(kValid, "  material: wood\n", "  material: wood\n  surface: formica\n"));
  EXPECT_EQ(e.line(), 6);
  EXPECT_NE(e.problem().find("unknown material 'formica'"), std::string::npos) << e.what();
}

TEST(Catalogue, MissingFieldNamesTheEntryAndField) {
  const InputError e = parse_error(replace(kValid, "    contact_radius: 0.004\n", ""));
  EXPECT_EQ(e.line(), 10);  // the entry's mapping starts on the line after "mug:"
  EXPECT_NE(e.problem().find("objects.mug"), std::string::npos) << e.what();
  EXPECT_NE(e.problem().find("missing key 'contact_radius' in objects.mug"), std::string::npos)
      << e.what();
}

// A key that is not a name (a YAML list used as a key) is bad input, not an internal error: found
// by fuzz/sim_files_fuzz.cpp.
TEST(Catalogue, KeysThatAreNotNamesAreInputErrors) {
  const InputError material = parse_error("materials:\n  ? [a, b]\n  : {density: 1}\n");
  EXPECT_EQ(material.line(), 2);
  EXPECT_NE(material.problem().find("each key of 'materials' must be a non-empty name"),
            std::string::npos)
      << material.what();
  const InputError object = parse_error(replace(kValid, "  mug:\n", "  ? [mug]\n  :\n"));
  EXPECT_NE(object.problem().find("each key of 'objects' must be a non-empty name"),
            std::string::npos)
      << object.what();
}

TEST(Catalogue, OtherErrorsAreReportedWithTheirEntry) {
  EXPECT_NE(parse_error(replace(kValid, "base: mug", "base: cup"))
                .problem()
                .find("unknown base object 'cup'"),
            std::string::npos);
  EXPECT_NE(parse_error(replace(kValid, "poisson_ratio: 0.19", "poisson_ratio: 0.7"))
                .problem()
                .find("materials.ceramic"),
            std::string::npos);
  EXPECT_NE(parse_error(replace(kValid, "radius: 0.04", "radius: big"))
                .problem()
                .find("must be a number"),
            std::string::npos);
  EXPECT_NE(
      parse_error(replace(kValid, "mass: 0.2,", "mass: 0,")).problem().find("heavy_mug.added_mass"),
      std::string::npos);
  EXPECT_NE(parse_error(replace(kValid, "wall_thickness: 0.005", "wall_thickness: 0.05"))
                .problem()
                .find("wall_thickness"),
            std::string::npos);
  EXPECT_EQ(parse_error("materials: [unclosed").line(), 1);
}

// A misspelt or misplaced key would otherwise keep a default silently (a "frction" leaves the
// object at friction 0.4): every level of the catalogue names the key, its entry and its line.
TEST(Catalogue, UnknownKeysAreRejectedWithFileLineAndEntry) {
  struct Case {
    std::string from, to;
    int line;
    std::string key, entry;
  };
  const std::vector<Case> cases{
      {"    contact_radius: 0.004\n", "    contact_radius: 0.004\n    frction: 0.3\n", 18,
       "frction", "objects.mug"},
      {"alpha: 6,", "alpha: 6, gamma: 1,", 2, "gamma", "materials.ceramic"},
      {"  material: wood\n", "  material: wood\n  colour: brown\n", 6, "colour", "table"},
      {"{frequency: 150, gain: 0.5}", "{frequency: 150, gain: 0.5, q: 3}", 7, "q",
       "table.modes[0]"},
      {"    base: mug\n", "    base: mug\n    radius: 0.05\n", 20, "radius", "objects.heavy_mug"},
      {"position: [0, 0, 0.01]}", "position: [0, 0, 0.01], colour: red}", 20, "colour",
       "objects.heavy_mug.added_mass"},
      {"objects:\n", "lights: on\nobjects:\n", 8, "lights", "the catalogue"},
  };
  for (const Case& c : cases) {
    const InputError e = parse_error(replace(kValid, c.from, c.to));
    EXPECT_EQ(e.file(), "test.yaml");
    EXPECT_EQ(e.line(), c.line) << e.what();
    EXPECT_NE(e.problem().find("unknown key '" + c.key + "' in " + c.entry), std::string::npos)
        << e.what();
  }
  const InputError dense =
      parse_error(replace(kValid, "  material: wood\n",
                          "  material: wood\n  dense_modes: {from: 150, to: 8000, n: 3}\n"));
  EXPECT_NE(dense.problem().find("unknown key 'n' in table.dense_modes"), std::string::npos)
      << dense.what();
}

TEST(Catalogue, UnknownObjectListsTheKnownOnes) {
  const Catalogue c = parse_catalogue(kValid, "test.yaml");
  try {
    c.object("teapot");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("heavy_mug, mug"), std::string::npos) << e.what();
  }
}

TEST(Catalogue, MissingFileIsAnInputError) {
  EXPECT_THROW(load_catalogue("/nonexistent/catalogue.yaml"), InputError);
}

// kValid with a named table under `tables:` (its key on line 22, its fields from line 23).
std::string with_named_table(const std::string& table_body) {
  return kValid + "tables:\n  steel_top:\n" + table_body;
}

const std::string kSteelTop =
    "    material: wood\n    friction: 0.5\n    thickness: 0.006\n    contact_loss_factor: 0.02\n";

TEST(Catalogue, ShippedTablesAreTheLabsDefaultAndFourOthers) {
  const Catalogue c = load_catalogue(kCatalogue);
  EXPECT_EQ(c.table.name, "lab_laminate");
  EXPECT_EQ(c.table_names(), (std::vector<std::string>{"glass_top", "lab_laminate", "oak_top",
                                                       "rubber_mat", "steel_bench"}));
  EXPECT_EQ(c.table_named("").name, "lab_laminate");
  EXPECT_EQ(c.table_named("steel_bench").material.name, "steel");
  EXPECT_EQ(c.table_named("glass_top").material.name, "float_glass");
  EXPECT_EQ(c.table_named("oak_top").material.name, "oak");
  // The mat lies on the lab's top: the MDF rings, the contact presses on rubber (E ~1-10 MPa, a
  // loss factor of 0.1-0.5 near 1 kHz).
  const TableSpec& mat = c.table_named("rubber_mat");
  EXPECT_EQ(mat.material.name, "mdf");
  EXPECT_EQ(mat.surface.name, "rubber");
  EXPECT_GE(mat.surface.youngs_modulus, 1e6);
  EXPECT_LE(mat.surface.youngs_modulus, 1e7);
  const double omega = 2 * 3.141592653589793 * 1000;
  const double eta = mat.surface.alpha / omega + mat.surface.beta * omega;
  EXPECT_GE(eta, 0.1);
  EXPECT_LE(eta, 0.5);
}

TEST(Catalogue, TheDefaultTableIsNamedAndListedWithTheOthers) {
  const Catalogue c = parse_catalogue(with_named_table(kSteelTop), "test.yaml");
  EXPECT_EQ(c.table.name, "table");  // the default's name when `table:` gives none
  EXPECT_EQ(c.table_names(), (std::vector<std::string>{"steel_top", "table"}));
  const TableSpec& steel = c.table_named("steel_top");
  EXPECT_DOUBLE_EQ(steel.thickness, 0.006);
  EXPECT_DOUBLE_EQ(steel.contact_loss_factor, 0.02);
  EXPECT_EQ(steel.surface.name, "wood");  // no surface: the top's material
  EXPECT_TRUE(steel.modes.empty());       // nothing inherited from the default's modes
}

TEST(Catalogue, ANamedTableMissingAFieldNamesItsLine) {
  for (const char* field : {"friction", "thickness", "contact_loss_factor", "material"}) {
    std::string body = kSteelTop;
    const auto at = body.find(std::string("    ") + field);
    body.erase(at, body.find('\n', at) + 1 - at);
    const InputError e = parse_error(with_named_table(body));
    EXPECT_EQ(e.file(), "test.yaml");
    EXPECT_EQ(e.line(), 23) << e.what();
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("tables.steel_top"), std::string::npos) << e.what();
  }
}

TEST(Catalogue, ANamedTablesUnknownMaterialOrKeyNamesItsLine) {
  const InputError material =
      parse_error(with_named_table(replace(kSteelTop, "material: wood", "material: granite")));
  EXPECT_EQ(material.line(), 23);
  EXPECT_NE(std::string(material.what()).find("unknown material 'granite'"), std::string::npos);
  const InputError surface = parse_error(with_named_table(kSteelTop + "    surface: cork\n"));
  EXPECT_EQ(surface.line(), 27);
  EXPECT_NE(std::string(surface.what()).find("unknown material 'cork'"), std::string::npos);
  const InputError key = parse_error(with_named_table(kSteelTop + "    frction: 1\n"));
  EXPECT_EQ(key.line(), 27);
  EXPECT_NE(std::string(key.what()).find("frction"), std::string::npos);
}

TEST(Catalogue, ATableNamedTwiceOrAnUnknownTableIsAnInputError) {
  const std::string twice = replace(with_named_table(kSteelTop), "steel_top:", "table:");
  EXPECT_EQ(parse_error(twice).line(), 22);
  const Catalogue c = parse_catalogue(with_named_table(kSteelTop), "test.yaml");
  try {
    c.table_named("marble");
    ADD_FAILURE() << "no error for an unknown table";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("steel_top, table"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace echoplan::sim
