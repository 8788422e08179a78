// A campaign's certificate states the share of V* only where its bounds are within 1% of V*, and
// how loose they are elsewhere; the numbers here are worked out by hand.
#include "experiment/campaign_certificate.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "common/error.h"

namespace echoplan::experiment {
namespace {

Certificate certificate(double vstar_lower, double vstar_upper, double regret, double regret_lower,
                        double bound_gap) {
  Certificate c;
  c.vstar = {vstar_lower, vstar_upper};
  c.regret.mean = regret;
  c.regret.half_width = 0.2;
  c.regret.n = 12;
  c.regret_lower_mean = regret_lower;
  c.bound_gap_mean = bound_gap;
  c.decisions = 30;
  return c;
}

TEST(CampaignCertificate, StatesTheShareOnlyWhereTheBoundsAreTight) {
  // Fold 1: V* in [9.99, 10.01] (gap 0.02) and 0.05 looseness per trial: 0.5% of V* = 10, tight;
  // share 1 - 0.5 / 10 = 0.95, CI 1 - 0.7 / 10 to 1 - 0.3 / 10.
  // Fold 2: V* in [9, 11]: a gap of 2 is 20% of V*, too loose; the share lies between the bounds'
  // ends, 1 - 0.5 / 10 and 1 - 0.1 / 10.
  const nlohmann::ordered_json j = campaign_certificate_json(
      {{"1", "plan", "folds/1/problem.yaml", certificate(9.99, 10.01, 0.5, 0.45, 0.05)},
       {"2", "plan", "folds/2/problem.yaml", certificate(9.0, 11.0, 0.5, 0.1, 0.4)}});
  EXPECT_EQ(j["tight_within"], 0.01);
  ASSERT_EQ(j["folds"].size(), 2u);
  const auto& tight = j["folds"][0];
  EXPECT_EQ(tight["fold"], "1");
  EXPECT_EQ(tight["problem"], "folds/1/problem.yaml");
  EXPECT_EQ(tight["trials"], 12);
  EXPECT_TRUE(tight["tight"]);
  EXPECT_NEAR(tight["looseness_share"].get<double>(), 0.005, 1e-12);
  EXPECT_NEAR(tight["share_of_vstar"].get<double>(), 0.95, 1e-12);
  EXPECT_NEAR(tight["share_ci95"][0].get<double>(), 0.93, 1e-12);
  EXPECT_NEAR(tight["share_ci95"][1].get<double>(), 0.97, 1e-12);
  EXPECT_FALSE(tight.contains("share_range"));
  const auto& loose = j["folds"][1];
  EXPECT_FALSE(loose["tight"]);
  EXPECT_NEAR(loose["looseness_share"].get<double>(), 0.2, 1e-12);
  EXPECT_TRUE(loose["share_of_vstar"].is_null());
  EXPECT_NEAR(loose["share_range"][0].get<double>(), 0.95, 1e-12);
  EXPECT_NEAR(loose["share_range"][1].get<double>(), 0.99, 1e-12);
  // The text says the same.
  const std::string text = campaign_certificate_text(
      {{"1", "plan", "folds/1/problem.yaml", certificate(9.99, 10.01, 0.5, 0.45, 0.05)},
       {"2", "plan", "folds/2/problem.yaml", certificate(9.0, 11.0, 0.5, 0.1, 0.4)}});
  EXPECT_NE(text.find("95.00% (93.00% to 97.00%)"), std::string::npos) << text;
  EXPECT_NE(text.find("bounds too loose to say (20.00% of V*): 95.00% to 99.00%"),
            std::string::npos)
      << text;
}

TEST(CampaignCertificate, AFolderWithoutFoldsIsNotADatasetCampaign) {
  const auto dir = std::filesystem::temp_directory_path() / "echoplan_campaign_without_folds";
  std::filesystem::create_directories(dir);
  EXPECT_THROW(certify_campaign(dir, {}), InputError);
}

}  // namespace
}  // namespace echoplan::experiment
