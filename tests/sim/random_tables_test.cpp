// Random tables (sim/random_tables.h): the `random:N` entry expanded into N tables drawn from the
// seed and added to the catalogue, each within the ranges the header documents, reproducible, apart
// under another tag or seed; the contact loss scaled by the top's point impedance as the
// catalogue's own tables are (checked against the catalogue's steel bench, glass and oak tops, and
// an impedance worked out here); malformed counts refused naming the entry.
#include "sim/random_tables.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/error.h"
#include "shipped_catalogue.h"

namespace echoplan::sim {
namespace {

// 8 sqrt(B m''), B = E h^3 / (12 (1 - nu^2)), m'' = rho h, written out here.
double impedance_by_hand(const Material& m, double h) {
  const double bending =
      m.youngs_modulus * h * h * h / (12.0 * (1.0 - m.poisson_ratio * m.poisson_ratio));
  return 8.0 * std::sqrt(bending * m.density * h);
}

// The loss factor at 1 kHz of a material: alpha / omega + beta * omega.
double loss_factor_at_1khz(const Material& m) {
  const double omega = 2.0 * 3.14159265358979323846 * 1000.0;
  return m.alpha / omega + m.beta * omega;
}

TEST(RandomTables, RandomNBecomesNTablesAddedToTheCatalogueAmongTheOthers) {
  Catalogue catalogue = shipped_catalogue();
  const std::size_t before = catalogue.tables.size();
  const auto names = expand_random_tables(catalogue, {"oak_top", "random:3", "steel_bench"}, 7, "");
  EXPECT_EQ(names, (std::vector<std::string>{"oak_top", "random_1", "random_2", "random_3",
                                             "steel_bench"}));
  EXPECT_EQ(catalogue.tables.size(), before + 3);
  EXPECT_EQ(catalogue.table_named("random_2").name, "random_2");
  Catalogue tagged = shipped_catalogue();
  EXPECT_EQ(expand_random_tables(tagged, {"random:2"}, 7, "training"),
            (std::vector<std::string>{"training_random_1", "training_random_2"}));
  Catalogue plain = shipped_catalogue();
  EXPECT_EQ(expand_random_tables(plain, {"glass_top"}, 7, ""),
            (std::vector<std::string>{"glass_top"}));
  EXPECT_EQ(plain.tables.size(), before);
}

TEST(RandomTables, TheSameSeedAndTagDrawTheSameTablesAnotherSeedOrTagOthers) {
  const TableSpec& lab = shipped_catalogue().table;
  const TableSpec a = random_table(7, "training", 1, "t", lab);
  const TableSpec b = random_table(7, "training", 1, "t", lab);
  EXPECT_EQ(a.material.youngs_modulus, b.material.youngs_modulus);
  EXPECT_EQ(a.thickness, b.thickness);
  EXPECT_EQ(a.contact_loss_factor, b.contact_loss_factor);
  EXPECT_NE(random_table(8, "training", 1, "t", lab).material.youngs_modulus,
            a.material.youngs_modulus);
  EXPECT_NE(random_table(7, "world", 1, "t", lab).material.youngs_modulus,
            a.material.youngs_modulus);
  EXPECT_NE(random_table(7, "training", 2, "t", lab).material.youngs_modulus,
            a.material.youngs_modulus);
}

TEST(RandomTables, EachDrawLiesInTheDocumentedRangesWhichTheyCover) {
  const TableSpec& lab = shipped_catalogue().table;
  double lowest_modulus = 1e300, highest_modulus = 0;
  int soft = 0;
  const int n = 2000;
  for (int i = 1; i <= n; ++i) {
    const TableSpec t = random_table(1, "", i, "t", lab);
    const Material& top = t.material;
    EXPECT_GE(top.youngs_modulus, 2e9);
    EXPECT_LE(top.youngs_modulus, 2.2e11);
    lowest_modulus = std::min(lowest_modulus, top.youngs_modulus);
    highest_modulus = std::max(highest_modulus, top.youngs_modulus);
    EXPECT_GE(top.density, 500.0);
    EXPECT_LE(top.density, 8000.0);
    EXPECT_GE(top.poisson_ratio, 0.20);
    EXPECT_LE(top.poisson_ratio, 0.35);
    EXPECT_GE(loss_factor_at_1khz(top), 4e-4 * (1 - 1e-9));
    EXPECT_LE(loss_factor_at_1khz(top), 0.05 * (1 + 1e-9));
    EXPECT_GE(t.thickness, 0.005);
    EXPECT_LE(t.thickness, 0.040);
    EXPECT_GE(t.friction, 0.4);
    EXPECT_LE(t.friction, 0.9);
    EXPECT_EQ(t.dense.count, lab.dense.count);
    if (t.surface.youngs_modulus != top.youngs_modulus) {
      ++soft;
      EXPECT_GE(t.surface.youngs_modulus, 2e6);
      EXPECT_LE(t.surface.youngs_modulus, 2e9);
      EXPECT_GE(loss_factor_at_1khz(t.surface), 0.05 * (1 - 1e-9));
      EXPECT_LE(loss_factor_at_1khz(t.surface), 0.4 * (1 + 1e-9));
    }
  }
  // The range spans the catalogue's tops, MDF (3.5 GPa) to steel (200 GPa).
  EXPECT_LT(lowest_modulus, 3.5e9);
  EXPECT_GT(highest_modulus, 2.0e11);
  // 3 in 10 with a soft layer: 600 +- 4 standard deviations (20.5).
  EXPECT_NEAR(soft, 600, 82);
}

TEST(RandomTables, ContactLossScalesWithTheTopsMobilityAsTheCatalogues) {
  // The catalogue's own tables follow the rule (its comments round to two figures) ...
  const Catalogue& c = shipped_catalogue();
  const double lab = impedance_by_hand(c.table.material, c.table.thickness);
  for (const char* name : {"steel_bench", "glass_top", "oak_top"}) {
    const TableSpec& t = c.table_named(name);
    EXPECT_NEAR(t.contact_loss_factor,
                c.table.contact_loss_factor * lab / impedance_by_hand(t.material, t.thickness),
                0.06 * t.contact_loss_factor)
        << name;
  }
  // ... and so does every drawn table, exactly.
  for (int i = 1; i <= 20; ++i) {
    const TableSpec t = random_table(3, "", i, "t", c.table);
    EXPECT_NEAR(t.contact_loss_factor,
                c.table.contact_loss_factor * lab / impedance_by_hand(t.material, t.thickness),
                1e-9 * t.contact_loss_factor)
        << i;
  }
}

TEST(RandomTables, AMalformedCountIsRefusedNamingTheEntry) {
  for (const char* bad :
       {"random:0", "random:", "random:x", "random:1001", "random:3.5", "random:-2"}) {
    Catalogue catalogue = shipped_catalogue();
    try {
      expand_random_tables(catalogue, {bad}, 1, "");
      ADD_FAILURE() << "no error for " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("'") + bad + "'"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace echoplan::sim
