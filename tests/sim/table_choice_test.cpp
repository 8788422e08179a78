#include "sim/table_choice.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "common/error.h"
#include "shipped_catalogue.h"

namespace echoplan::sim {
namespace {

TEST(TableChoice, WithoutTablesEveryRecordingAndTrialIsOnTheDefault) {
  const SimConfig config;
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(table_of_recording(shipped_catalogue(), config, i).name, "lab_laminate");
  EXPECT_EQ(table_of_trial(config, 42), "");
}

TEST(TableChoice, AListIsSpreadOverRecordingsByIndex) {
  SimConfig config;
  config.tables = {"oak_top", "rubber_mat", "glass_top"};
  const char* expected[] = {"oak_top", "rubber_mat", "glass_top", "oak_top", "rubber_mat"};
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(table_of_recording(shipped_catalogue(), config, i).name, expected[i]) << i;
}

TEST(TableChoice, ATrialsTableFollowsItsSeedAndCoversTheList) {
  SimConfig config;
  config.tables = {"oak_top", "steel_bench"};
  std::map<std::string, int> drawn;
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    const std::string table = table_of_trial(config, seed);
    EXPECT_EQ(table, table_of_trial(config, seed)) << seed;  // the seed alone decides it
    ++drawn[table];
  }
  ASSERT_EQ(drawn.size(), 2u);
  // Uniform: 200 +- 4 standard deviations (10) each.
  EXPECT_NEAR(drawn["oak_top"], 200, 40);
  config.tables = {"steel_bench"};
  EXPECT_EQ(table_of_trial(config, 7), "steel_bench");
}

TEST(TableChoice, AnUnknownTableIsRefusedNamingTheCatalogue) {
  SimConfig config;
  config.tables = {"oak_top", "marble"};
  try {
    check_tables(shipped_catalogue(), config);
    ADD_FAILURE() << "no error for an unknown table";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("marble"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("catalogue.yaml"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace echoplan::sim
