// Campaign files: the shipped default is the report's chapter 5, and mistakes are InputErrors
// naming the file and line.
#include "experiment/campaign_config.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../common/source_dir.h"
#include "../common/test_folder.h"
#include "common/error.h"
#include "experiment/campaign_arms.h"

namespace echoplan::experiment {
namespace {

const std::string kMinimal = R"(
arms:
  - {name: a, problem: p.yaml}
world: {type: model, problem: w.yaml}
trials:
  - {object: mug, trials: 3}
planner: {episodes: 100}
)";

// The InputError of parsing `text`, as "line: problem".
std::string error_of(const std::string& text) {
  try {
    parse_campaign_config(text, "/dir/c.yaml");
  } catch (const InputError& e) {
    return std::to_string(e.line()) + ": " + e.problem();
  }
  return "no error";
}

// The InputError of resolving the arms of `text` (campaign_arms.h), as "line: problem".
std::string arm_error_of(const std::string& text) {
  try {
    resolve_arms(parse_campaign_config(text, "/dir/c.yaml"));
  } catch (const InputError& e) {
    return std::to_string(e.line()) + ": " + e.problem();
  }
  return "no error";
}

TEST(CampaignConfig, ShippedDefaultIsTheReportsChapter5) {
  const CampaignConfig c =
      load_campaign_config(echoplan::testing::source_dir() + "/experiments/chapter5.yaml");
  ASSERT_EQ(c.groups.size(), 6u);
  for (int g = 0; g < 4; ++g) {
    EXPECT_EQ(c.groups[g].trials, 10);
    EXPECT_EQ(c.groups[g].object, c.groups[g].plays);
  }
  EXPECT_EQ(c.groups[4].object, "pringles_can_weighted");
  EXPECT_EQ(c.groups[4].plays, "pringles_can");
  EXPECT_EQ(c.groups[5].object, "coffee_mug_weighted");
  EXPECT_EQ(c.groups[5].plays, "coffee_mug");
  EXPECT_EQ(c.training.recordings_per_pair, 10);
  EXPECT_EQ(c.planner.solver, "abt");
  EXPECT_GT(c.planner.episodes, 0);  // reproducible budget by default
  EXPECT_EQ(c.planner.step_ms, 0);
  int trials = 0;
  for (const ObjectGroup& g : c.groups) trials += g.trials;
  EXPECT_EQ(trials, 60);
}

// The shipped noise campaign: its speech is where setup.sh installs it, and the arm trained in
// noise learns from words the trials never play.
TEST(CampaignConfig, ShippedNoiseCampaignTrainsOnSpeechItsTrialsNeverPlay) {
  const CampaignConfig c =
      load_campaign_config(echoplan::testing::source_dir() + "/experiments/noise.yaml");
  ASSERT_TRUE(c.world.noise.given());
  EXPECT_EQ(c.world.noise.ebr_db, "0");
  const std::vector<ResolvedArm> arms = resolve_arms(c);
  ASSERT_EQ(arms.size(), 2u);
  EXPECT_FALSE(arms[0].trained_in_noise());
  EXPECT_TRUE(arms[1].trained_in_noise());
  for (const std::string& heard : c.world.noise.sources)
    for (const std::string& trained : c.training.noise.sources)
      if (heard != "room") {
        EXPECT_NE(heard, trained);
      }
}

// The shipped campaign outside the lab: noise over a range of ratios and tables drawn per trial,
// the arm hearing levels trained in noise, and its speech words the trials never play.
TEST(CampaignConfig, ShippedOutsideCampaignDrawsNoiseLevelsAndTables) {
  const CampaignConfig c =
      load_campaign_config(echoplan::testing::source_dir() + "/experiments/outside.yaml");
  EXPECT_EQ(c.world.noise.ebr_db, "-6:24");
  EXPECT_EQ(c.world.surfaces, (std::vector<std::string>{"lab_laminate", "oak_top", "glass_top"}));
  const std::vector<ResolvedArm> arms = resolve_arms(c);
  ASSERT_EQ(arms.size(), 3u);
  EXPECT_FALSE(arms[0].trained_in_noise());
  EXPECT_EQ(arms[2].hearing(), perception::ObservationKind::levels);
  EXPECT_TRUE(arms[2].trained_in_noise());
  for (const std::string& heard : c.world.noise.sources)
    for (const std::string& trained : c.training.noise.sources)
      if (heard != "room") {
        EXPECT_NE(heard, trained);
      }
}

TEST(CampaignConfig, RelativePathsAreRelativeToTheFile) {
  const CampaignConfig c = parse_campaign_config(kMinimal, "/dir/c.yaml");
  EXPECT_EQ(c.arms.at(0).problem, "/dir/p.yaml");
  EXPECT_EQ(c.world.problem, "/dir/w.yaml");
  EXPECT_EQ(c.groups.at(0).plays, "mug");
}

TEST(CampaignConfig, JsonRoundTrip) {
  const CampaignConfig c = parse_campaign_config(kMinimal, "/dir/c.yaml");
  const CampaignConfig back = campaign_config_from_json(to_json(c), "campaign.json");
  EXPECT_EQ(to_json(back), to_json(c));
}

TEST(CampaignConfig, MistakesNameTheLine) {
  const std::string typo = error_of(kMinimal + "planer: {}\n");
  EXPECT_EQ(typo.substr(0, 2), "8:") << typo;
  EXPECT_NE(typo.find("unknown key 'planer'"), std::string::npos) << typo;
}

TEST(CampaignConfig, RejectsBadValues) {
  auto replaced = [](const std::string& from, const std::string& to) {
    std::string text = kMinimal;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  EXPECT_NE(error_of(replaced("{episodes: 100}", "{episodes: 100, step_ms: 5}"))
                .find("exactly one planning budget"),
            std::string::npos);
  EXPECT_NE(error_of(replaced("{episodes: 100}", "{}")).find("exactly one planning budget"),
            std::string::npos);
  EXPECT_NE(error_of(replaced("type: model", "type: robot")).find("world type 'robot'"),
            std::string::npos);
  EXPECT_NE(error_of(replaced("trials: 3", "trials: 0")).find("trials must be >= 1"),
            std::string::npos);
  EXPECT_NE(error_of(replaced("name: a", "name: a b")).find("name 'a b' may hold only"),
            std::string::npos);
  EXPECT_NE(error_of(replaced("{episodes: 100}", "{episodes: 100, solver: greedy}"))
                .find("solver 'greedy'"),
            std::string::npos);
  EXPECT_EQ(error_of(replaced("trials: 3", "trials: 3")).substr(0, 8), "no error");
  const std::string line = error_of(replaced("trials: 3", "trials: 0"));
  EXPECT_EQ(line.substr(0, 2), "6:") << line;
}

// kMinimal with its arm replaced by `arm`.
std::string with_arm(const std::string& arm) {
  std::string text = kMinimal;
  const std::string from = "{name: a, problem: p.yaml}";
  return text.replace(text.find(from), from.size(), arm);
}

// An arm that plans may choose its planner's leaf value; a fixed strategy has none to choose.
TEST(CampaignConfig, APlanningArmChoosesItsLeafValue) {
  const CampaignConfig c =
      parse_campaign_config(with_arm("{name: a, problem: p.yaml, leaf: exact}"), "/dir/c.yaml");
  EXPECT_EQ(c.arms[0].leaf, "exact");
  EXPECT_EQ(to_json(c)["arms"][0]["leaf"], "exact");
  EXPECT_EQ(to_json(campaign_config_from_json(to_json(c), "campaign.json")), to_json(c));
  const std::string unknown = error_of(with_arm("{name: a, problem: p.yaml, leaf: magic}"));
  EXPECT_EQ(unknown.substr(0, 2), "3:") << unknown;
  EXPECT_NE(unknown.find("policy, exact, exact-offline, lookahead, heuristic, rollout"),
            std::string::npos)
      << unknown;
  // Read as written; refused, at the arm's line, when the arms are resolved.
  const std::string fixed =
      arm_error_of(with_arm("{name: a, problem: p.yaml, strategy: all_actions, leaf: exact}"));
  EXPECT_EQ(fixed.substr(0, 3), "3: ") << fixed;
  EXPECT_NE(fixed.find("arm 'a': leaf: only an arm that plans"), std::string::npos) << fixed;
}

// How the planner counts unheard outcomes, likewise; left out of the identity at its default.
TEST(CampaignConfig, APlanningArmChoosesHowUnheardOutcomesCount) {
  // Campaigns written before the choice existed keep their identity (a resumed run continues).
  CampaignConfig shipped =
      load_campaign_config(echoplan::testing::source_dir() + "/experiments/chapter5.yaml");
  EXPECT_FALSE(shipped.identity()["arms"][0].contains("unheard"));
  shipped.arms[0].unheard = "commit";
  EXPECT_EQ(shipped.identity()["arms"][0]["unheard"], "commit");
  const CampaignConfig c =
      parse_campaign_config(with_arm("{name: a, problem: p.yaml, unheard: commit}"), "/dir/c.yaml");
  EXPECT_EQ(c.arms[0].unheard, "commit");
  EXPECT_EQ(to_json(campaign_config_from_json(to_json(c), "campaign.json")), to_json(c));
  const std::string unknown = error_of(with_arm("{name: a, problem: p.yaml, unheard: guess}"));
  EXPECT_EQ(unknown.substr(0, 2), "3:") << unknown;
  EXPECT_NE(unknown.find("share, commit"), std::string::npos) << unknown;
  const std::string fixed =
      arm_error_of(with_arm("{name: a, problem: p.yaml, strategy: random, unheard: commit}"));
  EXPECT_NE(fixed.find("arm 'a': unheard: only an arm that plans"), std::string::npos) << fixed;
}

TEST(CampaignConfig, TrainingTableEstimate) {
  EXPECT_EQ(parse_campaign_config(kMinimal, "/dir/c.yaml").training.table, "");  // the default
  const CampaignConfig soft =
      parse_campaign_config(kMinimal + "training_set: {table: soft}\n", "/dir/c.yaml");
  EXPECT_EQ(soft.training.table, "soft");
  EXPECT_EQ(campaign_config_from_json(to_json(soft), "campaign.json").training.table, "soft");
  const std::string bad = error_of(kMinimal + "training_set:\n  table: hard\n");
  EXPECT_EQ(bad, "9: table 'hard' is not one of: counts, soft");
  EXPECT_EQ(error_of(kMinimal + "training_set:\n  model: m.json\n  table: soft\n"),
            "10: table chooses how this campaign trains; with model: the model file has its own");
}

TEST(CampaignConfig, ClassifierWithModelIsAnError) {
  EXPECT_EQ(parse_campaign_config(kMinimal + "training_set: {classifier: report-template}\n",
                                  "/dir/c.yaml")
                .training.classifier,
            "report-template");
  EXPECT_EQ(error_of(kMinimal + "training_set:\n  model: m.json\n  classifier: report-template\n"),
            "10: classifier chooses how this campaign trains; with model: the model file has its "
            "own");
}

// A simulated world's noise: built-in sources stay names, files are relative to the campaign file,
// and the sections appear in the JSON (and so the identity) only when given.
class CampaignNoiseConfig : public TestFolder {};

TEST_F(CampaignNoiseConfig, ASimulatedWorldHearsThroughTheNoiseItNames) {
  std::string simulated = kMinimal;
  simulated.replace(simulated.find("type: model"), 11, "type: simulated");
  const CampaignConfig quiet = parse_campaign_config(simulated, "/dir/c.yaml");
  EXPECT_FALSE(quiet.world.noise.given());
  EXPECT_FALSE(to_json(quiet)["world"].contains("noise"));
  const std::string noisy =
      "world:\n  type: simulated\n  problem: w.yaml\n  noise: {sources: [room, speech], ebr_db: "
      "\"-6:12\"}\n" +
      simulated.substr(simulated.find("trials:"));
  const std::string arms = "arms:\n  - {name: a, problem: p.yaml}\n";
  std::filesystem::create_directories(dir_ / "speech");
  const std::string file = (dir_ / "c.yaml").string();
  const CampaignConfig c = parse_campaign_config(arms + noisy, file);
  EXPECT_EQ(c.world.noise.sources, (std::vector<std::string>{"room", (dir_ / "speech").string()}));
  EXPECT_EQ(c.world.noise.ebr_db, "-6:12");
  const CampaignConfig back = campaign_config_from_json(to_json(c), "campaign.json");
  EXPECT_EQ(back.world.noise.sources, c.world.noise.sources);
  EXPECT_EQ(to_json(back), to_json(c));
  EXPECT_EQ(to_json(c)["world"]["noise"]["ebr_db"], "-6:12");
}

TEST(CampaignConfig, NoiseMistakesNameTheLine) {
  const std::string head = "arms:\n  - {name: a, problem: p.yaml}\nworld:\n  type: ";
  const std::string tail = "\ntrials:\n  - {object: mug}\nplanner: {episodes: 100}\n";
  const auto world = [&](const std::string& type, const std::string& noise) {
    return error_of(head + type + "\n  problem: w.yaml\n  noise: " + noise + tail);
  };
  EXPECT_EQ(world("model", "{sources: [room], ebr_db: 0}"),
            "6: noise: a model world hears no recordings (a simulated world or a dataset world "
            "over a recordings tree does)");
  EXPECT_EQ(world("simulated", "{sources: [room], ebr_db: 70}"),
            "6: world.noise: EBR '70': give a number of dB in [-60, 60], or LO:HI");
  EXPECT_EQ(world("simulated", "{sources: [room]}"),
            "6: world.noise needs ebr_db: the ratio of each recording");
  EXPECT_EQ(world("simulated", "{sources: [nowhere.wav], ebr_db: 0}"),
            "6: world.noise: source '/dir/nowhere.wav' is neither built-in (white, room, motor, "
            "coloured) nor a file or folder");
  EXPECT_NE(world("simulated", "{ebr_db: 0}").find("sources"), std::string::npos);
  EXPECT_EQ(world("simulated", "{sources: [room], ebr_db: 0, talkers: 0}"),
            "6: world.noise: talkers must be 1 to 64 (people heard at once), not 0");
  // An arm trained in noise hears recordings; a model world hears none.
  EXPECT_NE(arm_error_of(with_arm("{name: a, problem: p.yaml, trained_in_noise: true}"))
                .find("trained_in_noise: the classifier trained in noise hears recordings; a "
                      "model world hears none"),
            std::string::npos);
}

// A dataset world hears its recordings through noise, and an arm may be trained in noise on each
// fold; with a frozen model nothing is trained and the data is replayed as it is.
TEST_F(CampaignNoiseConfig, ADatasetWorldTakesNoiseAndArmsTrainedInIt) {
  std::filesystem::create_directories(dir_ / "recordings");
  std::filesystem::create_directories(dir_ / "speech");
  std::ofstream(dir_ / "m.json") << "{}";
  const std::string source = (dir_ / "c.yaml").string();
  const auto error = [&](const std::string& text) {
    try {
      resolve_arms(parse_campaign_config(text, source));
    } catch (const InputError& e) {
      return std::to_string(e.line()) + ": " + e.problem();
    }
    return std::string("no error");
  };
  const std::string world = "world:\n  type: dataset\n  data: recordings\n";
  const std::string noise = "  noise: {sources: [room, speech], ebr_db: \"0\"}\n";
  const std::string task = "task: {rewards: {right: 10, wrong: -100, sense: -1}}\n";
  const std::string arms =
      "arms:\n  - {name: quiet, strategy: plan}\n  - {name: in_noise, strategy: plan, "
      "trained_in_noise: true}\nplanner: {episodes: 100}\n";
  const std::string training = "training_set: {noise: {sources: [white], ebr_db: \"-6:24\"}}\n";
  const CampaignConfig c = parse_campaign_config(world + noise + training + task + arms, source);
  EXPECT_EQ(c.world.noise.sources, (std::vector<std::string>{"room", (dir_ / "speech").string()}));
  EXPECT_EQ(c.training.noise.sources, std::vector<std::string>{"white"});
  const std::vector<ResolvedArm> resolved = resolve_arms(c);
  EXPECT_FALSE(resolved[0].trained_in_noise());
  EXPECT_TRUE(resolved[1].trained_in_noise());
  // Its fold problems are the noise-trained classifier's, in a file of their own.
  EXPECT_EQ(fold_problem_name(resolved[0].plans_with), "problem.yaml");
  EXPECT_EQ(fold_problem_name(resolved[1].plans_with), "problem-in-noise.yaml");
  const CampaignConfig back = campaign_config_from_json(to_json(c), "campaign.json");
  EXPECT_EQ(back.world.noise.sources, c.world.noise.sources);
  EXPECT_EQ(back.training.noise.ebr_db, "-6:24");

  const std::string frozen = world + "  model: m.json\n";
  EXPECT_EQ(error(frozen + noise + task + arms),
            "5: noise: a dataset world with a frozen model (world.model) replays its data as it "
            "is; write a noisy copy with `echoplan add-noise` and give that as world.data");
  EXPECT_NE(error(frozen + task + arms)
                .find("trained_in_noise: the world's model is frozen (world.model); nothing is "
                      "trained"),
            std::string::npos);
}

// A dataset world's series become rows as world.series says (presets spelled out, a bad spec at
// its line), and an arm may hear some modalities only; both round-trip and enter the identity
// only when given.
TEST_F(CampaignNoiseConfig, ADatasetWorldChoosesSeriesFeaturesAndArmsTheirModalities) {
  // Two objects, one lift each, felt by joint efforts and a wrist force.
  for (const char* object : {"mug", "cup"}) {
    std::filesystem::create_directories(dir_ / "recordings" / object / "lift");
    std::ofstream effort(dir_ / "recordings" / object / "lift" / "1.effort.csv");
    std::ofstream force(dir_ / "recordings" / object / "lift" / "1.force.csv");
    effort << "t,j1\n";
    force << "t,force_z\n";
    for (int i = 0; i < 10; ++i)
      effort << i * 0.01 << "," << i << "\n", force << i * 0.01 << ",1\n";
  }
  const std::string source = (dir_ / "c.yaml").string();
  const std::string world = "world:\n  type: dataset\n  data: recordings\n";
  const std::string arms =
      "arms:\n  - {name: both, strategy: plan}\n  - {name: torque, strategy: plan, "
      "modalities: [effort, force]}\nplanner: {episodes: 100}\n";
  const CampaignConfig c = parse_campaign_config(
      world + "  series: {effort: cy101-haptic, force: \"stats[force_z]\"}\n" + arms, source);
  EXPECT_EQ(c.world.series, (perception::SeriesChoices{{"effort", "bins(10,sum,time-major)"},
                                                       {"force", "stats[force_z]"}}));
  const std::vector<ResolvedArm> resolved = resolve_arms(c);
  EXPECT_TRUE(resolved[0].plans_with.modalities.empty());
  EXPECT_EQ(resolved[1].plans_with.modalities, (std::vector<std::string>{"effort", "force"}));
  EXPECT_EQ(fold_problem_name(resolved[1].plans_with), "problem-hears-effort-force.yaml");
  const CampaignConfig back = campaign_config_from_json(to_json(c), "campaign.json");
  EXPECT_EQ(back.world.series, c.world.series);
  EXPECT_EQ(back.arms[1].modalities, c.arms[1].modalities);
  const CampaignConfig plain = parse_campaign_config(world + arms, source);
  EXPECT_FALSE(plain.identity()["world"].contains("series"));
  EXPECT_EQ(c.identity()["world"]["series"]["effort"], "bins(10,sum,time-major)");
  try {
    parse_campaign_config(world + "  series: {effort: \"bins(0,sum)\"}\n" + arms, source);
    ADD_FAILURE() << "no error for a bad spec";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 4);
    EXPECT_NE(e.problem().find("series.effort: series features 'bins(0,sum)'"), std::string::npos)
        << e.problem();
  }
}

TEST(CampaignConfig, ShippedSurfacesCampaignHoldsItsTrialsTableOutOfTraining) {
  const CampaignConfig c =
      load_campaign_config(echoplan::testing::source_dir() + "/experiments/surfaces.yaml");
  ASSERT_EQ(c.world.surfaces.size(), 1u);
  ASSERT_FALSE(c.training.surfaces.empty());
  for (const std::string& heard : c.training.surfaces) EXPECT_NE(heard, c.world.surfaces[0]);
  ASSERT_EQ(c.arms.size(), 2u);
  EXPECT_FALSE(c.arms[0].trained_on_surfaces);
  EXPECT_TRUE(c.arms[1].trained_on_surfaces);
  ASSERT_EQ(c.groups.size(), 4u);  // the main job's four objects
}

TEST(CampaignConfig, ShippedRandomTablesCampaignTrainsOnDrawnTablesAndTestsOnEveryCatalogueOne) {
  const CampaignConfig c =
      load_campaign_config(echoplan::testing::source_dir() + "/experiments/random_tables.yaml");
  EXPECT_EQ(c.world.surfaces, (std::vector<std::string>{"lab_laminate", "oak_top", "steel_bench",
                                                        "glass_top", "rubber_mat"}));
  EXPECT_EQ(c.training.surfaces, (std::vector<std::string>{"random:40"}));
  EXPECT_EQ(c.training.recordings_per_pair, 40);  // each recording on a table of its own
  ASSERT_EQ(c.arms.size(), 2u);
  EXPECT_FALSE(c.arms[0].trained_on_surfaces);
  EXPECT_TRUE(c.arms[1].trained_on_surfaces);
}

TEST(CampaignConfig, SurfacesAreANameOrAListAndRoundTrip) {
  const std::string head = "arms:\n  - {name: a, problem: p.yaml, trained_on_surfaces: true}\n";
  const std::string tail = "trials:\n  - {object: mug}\nplanner: {episodes: 100}\n";
  const CampaignConfig one = parse_campaign_config(
      head + "world: {type: simulated, problem: w.yaml, surface: steel_bench}\n" + tail,
      "/dir/c.yaml");
  EXPECT_EQ(one.world.surfaces, (std::vector<std::string>{"steel_bench"}));
  EXPECT_EQ(one.world.surface_line, 3);
  const CampaignConfig list = parse_campaign_config(
      head + "world: {type: simulated, problem: w.yaml, surface: [oak_top, glass_top]}\n" +
          "training_set: {surfaces: [lab_laminate, rubber_mat]}\n" + tail,
      "/dir/c.yaml");
  EXPECT_EQ(list.world.surfaces, (std::vector<std::string>{"oak_top", "glass_top"}));
  EXPECT_EQ(list.training.surfaces, (std::vector<std::string>{"lab_laminate", "rubber_mat"}));
  EXPECT_EQ(list.training.surfaces_line, 4);
  const CampaignConfig back = campaign_config_from_json(to_json(list), "campaign.json");
  EXPECT_EQ(back.world.surfaces, list.world.surfaces);
  EXPECT_EQ(back.training.surfaces, list.training.surfaces);
  EXPECT_TRUE(back.arms[0].trained_on_surfaces);
  EXPECT_EQ(to_json(back), to_json(list));
}

TEST(CampaignConfig, SurfacesEnterTheIdentityOnlyWhenGiven) {
  // Campaigns written before surfaces existed keep their identities: no key at all without them.
  const CampaignConfig c =
      load_campaign_config(echoplan::testing::source_dir() + "/experiments/surfaces.yaml");
  CampaignConfig without = c;
  without.world.surfaces.clear();
  without.training.surfaces.clear();
  for (CampaignArm& arm : without.arms) arm.trained_on_surfaces = false;
  without.arms[1].name = "other";
  // campaign.json lists every arm key (as it does trained_in_noise); the identity only those given.
  const std::string plain = without.identity().dump();
  for (const char* key : {"\"surface\"", "\"surfaces\"", "\"trained_on_surfaces\""})
    EXPECT_EQ(plain.find(key), std::string::npos) << key;
  const nlohmann::json json = to_json(without);
  EXPECT_FALSE(json["world"].contains("surface"));
  EXPECT_FALSE(json["training_set"].contains("surfaces"));
  const std::string given = c.identity().dump();
  EXPECT_NE(given.find("\"surface\":[\"steel_bench\"]"), std::string::npos) << given;
  EXPECT_NE(given.find("\"trained_on_surfaces\":true"), std::string::npos) << given;
  CampaignConfig other = c;
  other.world.surfaces = {"glass_top"};
  EXPECT_NE(other.identity(), c.identity());
}

TEST(CampaignConfig, SurfaceMistakesNameTheLine) {
  const std::string head = "arms:\n  - {name: a, problem: p.yaml}\nworld:\n  type: ";
  const std::string tail = "\ntrials:\n  - {object: mug}\nplanner: {episodes: 100}\n";
  EXPECT_EQ(error_of(head + "model\n  problem: w.yaml\n  surface: steel_bench" + tail),
            "6: surface: the table a simulated world's robot acts on");
  EXPECT_EQ(error_of(head + "simulated\n  problem: w.yaml\n  surface: [oak_top, oak_top]" + tail)
                .substr(0, 2),
            "6:");
  EXPECT_EQ(error_of(head + "simulated\n  problem: w.yaml\n  surface: []" + tail),
            "6: world.surface must not be empty");
  EXPECT_NE(arm_error_of(with_arm("{name: a, problem: p.yaml, trained_on_surfaces: true}"))
                .find("trained_on_surfaces: the classifier trained on other tables hears a "
                      "simulated"),
            std::string::npos);
}

TEST(CampaignConfig, ShippedDefaultNamesTheReportsNumbers) {
  const CampaignConfig c =
      load_campaign_config(echoplan::testing::source_dir() + "/experiments/chapter5.yaml");
  ASSERT_TRUE(c.reference);
  EXPECT_EQ(c.reference->source,
            echoplan::testing::source_dir() + "/experiments/chapter5_reference.yaml");
  EXPECT_EQ(c.reference->label, "report");
  // A reference changes the report's comparison, not the trials: not part of the identity.
  CampaignConfig without = c;
  without.reference.reset();
  EXPECT_EQ(without.identity(), c.identity());
  const CampaignConfig back = campaign_config_from_json(to_json(c), "campaign.json");
  ASSERT_TRUE(back.reference);
  EXPECT_EQ(to_json(*back.reference), to_json(*c.reference));
}

TEST(CampaignConfig, WithoutReferenceHasNone) {
  const CampaignConfig c = parse_campaign_config(kMinimal, "/dir/c.yaml");
  EXPECT_FALSE(c.reference);
  EXPECT_FALSE(to_json(c).contains("reference"));
  EXPECT_FALSE(campaign_config_from_json(to_json(c), "campaign.json").reference);
}

TEST(CampaignConfig, ReferenceIsRelativeToTheFileAndChecked) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "echoplan_campaign_config_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string campaign = (dir / "c.yaml").string();
  auto write = [&](const std::string& text) { std::ofstream(dir / "ref.yaml") << text; };

  write(
      "label: lab\nobjects:\n  mug: {trials: 3, correct: 2, mean_discounted_reward: 1, "
      "mean_steps: 2}\n");
  const CampaignConfig c = parse_campaign_config(kMinimal + "reference: ref.yaml\n", campaign);
  ASSERT_TRUE(c.reference);
  EXPECT_EQ(c.reference->objects.at("mug").correct, 2);

  // A malformed reference file: the error names that file and its line.
  write("label: lab\nobjects:\n  mug: {trials: 3, correct: 2, mean_steps: 2, misc: 1}\n");
  try {
    parse_campaign_config(kMinimal + "reference: ref.yaml\n", campaign);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir / "ref.yaml").string());
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(e.problem().find("unknown key 'misc'"), std::string::npos) << e.problem();
  }
  // A missing one: the campaign file's line.
  EXPECT_EQ(error_of(kMinimal + "reference: nowhere.yaml\n"),
            "8: reference file '/dir/nowhere.yaml' does not exist");
  fs::remove_all(dir);
}

}  // namespace

// A dataset world: the data folder must exist, so the tests make one (its contents are read by the
// campaign, not by the file's reader).
class DatasetCampaignConfig : public TestFolder {
 protected:
  void SetUp() override {
    TestFolder::SetUp();
    std::filesystem::create_directories(dir_ / "data");
    std::ofstream(dir_ / "groups.csv") << "object,group\nmug,ceramic\n";
  }

  std::string source() const { return (dir_ / "c.yaml").string(); }
  std::string error(const std::string& text) const {
    try {
      parse_campaign_config(text, source());
    } catch (const InputError& e) {
      return std::to_string(e.line()) + ": " + e.problem();
    }
    return "no error";
  }

  const std::string text_ = R"(
world: {type: dataset, data: data, hold_out: object, groups: groups.csv}
task: {rewards: {right: 5, wrong: -50, sense: -2}}
arms:
  - {name: plan, strategy: plan}
  - {name: greedy, strategy: information_gain}
planner: {episodes: 100}
)";
};

TEST_F(DatasetCampaignConfig, ReadsTheDataHoldOutGroupsRewardsAndStrategies) {
  const CampaignConfig c = parse_campaign_config(text_, source());
  EXPECT_EQ(c.world.type, WorldType::dataset);
  EXPECT_EQ(c.world.data, (dir_ / "data").string());
  EXPECT_EQ(c.world.groups, (dir_ / "groups.csv").string());
  EXPECT_EQ(c.world.hold_out, perception::HoldOut::object);
  EXPECT_EQ(c.task.right, 5);
  EXPECT_EQ(c.task.wrong, -50);
  EXPECT_EQ(c.task.sense, -2);
  ASSERT_EQ(c.arms.size(), 2u);
  EXPECT_EQ(c.arms[0].strategy, "plan");
  EXPECT_EQ(c.arms[1].strategy, "information_gain");
  EXPECT_TRUE(c.arms[0].problem.empty());
  EXPECT_TRUE(c.groups.empty());  // the campaign takes its trials from the data
  const CampaignConfig back = campaign_config_from_json(to_json(c), "campaign.json");
  EXPECT_EQ(to_json(back), to_json(c));
}

// unheard: auto chooses by self-play on the arm's problems, as many trials as the planner says;
// left out of the identity at its default.
TEST_F(DatasetCampaignConfig, UnheardAutoAndItsSelfPlayTrials) {
  std::string text = text_;
  text.replace(text.find("{name: plan, strategy: plan}"), 28,
               "{name: plan, strategy: plan, unheard: auto}");
  const CampaignConfig c = parse_campaign_config(text, source());
  EXPECT_EQ(c.arms[0].unheard, "auto");
  EXPECT_EQ(c.planner.self_play_trials, 200);
  std::filesystem::create_directories(dir_ / "data" / "shake");  // the identity hashes the data
  std::ofstream(dir_ / "data" / "shake" / "audio.csv") << "object,session,f\nmug,1,0.5\n";
  EXPECT_FALSE(c.identity()["planner"].contains("self_play_trials"));
  text.replace(text.find("planner: {episodes: 100}"), 24,
               "planner: {episodes: 100, self_play_trials: 40}");
  const CampaignConfig forty = parse_campaign_config(text, source());
  EXPECT_EQ(forty.planner.self_play_trials, 40);
  EXPECT_EQ(forty.identity()["planner"]["self_play_trials"], 40);
  EXPECT_EQ(to_json(campaign_config_from_json(to_json(forty), "campaign.json")), to_json(forty));
  text.replace(text.find("self_play_trials: 40"), 20, "self_play_trials: 1");
  EXPECT_EQ(error(text), "7: self_play_trials must be >= 2");
  // A problem file's arm may leave the choice to self-play too.
  EXPECT_EQ(
      parse_campaign_config(with_arm("{name: a, problem: p.yaml, unheard: auto}"), "/dir/c.yaml")
          .arms[0]
          .unheard,
      "auto");
}

TEST_F(DatasetCampaignConfig, CostsPriceBehavioursAndEnterTheIdentityOnlyWhenGiven) {
  std::string text = text_;
  const std::string rewards = "task: {rewards: {right: 5, wrong: -50, sense: -2}}";
  text.replace(
      text.find(rewards), rewards.size(),
      "task: {rewards: {right: 5, wrong: -50, sense: -2}, costs: {shake: 4.5, look: 0.5}}");
  const CampaignConfig priced = parse_campaign_config(text, source());
  EXPECT_EQ(priced.task.costs, (std::map<std::string, double>{{"look", 0.5}, {"shake", 4.5}}));
  EXPECT_EQ(priced.task.sense, -2);
  const CampaignConfig back = campaign_config_from_json(to_json(priced), "campaign.json");
  EXPECT_EQ(back.task.costs, priced.task.costs);
  std::filesystem::create_directories(dir_ / "data" / "shake");
  std::ofstream(dir_ / "data" / "shake" / "audio.csv") << "object,session,f\nmug,1,0.5\n";
  EXPECT_EQ(priced.identity()["task"]["costs"]["shake"], 4.5);
  // Unpriced campaigns keep the identity they had before costs existed.
  const CampaignConfig plain = parse_campaign_config(text_, source());
  EXPECT_FALSE(plain.identity()["task"].contains("costs"));
  EXPECT_TRUE(to_json(plain)["task"]["costs"].empty());
  // Costs alone keep the default rewards.
  const CampaignConfig only = parse_campaign_config(
      "world: {type: dataset, data: data}\ntask: {costs: {tap: 3}}\narms: [{name: plan}]\n"
      "planner: {episodes: 10}\n",
      source());
  EXPECT_EQ(only.task.sense, -1);
  EXPECT_EQ(only.task.costs.at("tap"), 3);
}

TEST_F(DatasetCampaignConfig, RequiresOpensBehavioursAfterOthersAndEntersTheIdentityOnlyWhenGiven) {
  std::string text = text_;
  const std::string rewards = "task: {rewards: {right: 5, wrong: -50, sense: -2}}";
  text.replace(text.find(rewards), rewards.size(),
               "task: {rewards: {right: 5, wrong: -50, sense: -2},\n"
               "       requires: {shake: [grasp], lift: [grasp, look]}}");
  const CampaignConfig c = parse_campaign_config(text, source());
  const std::map<std::string, std::vector<std::string>> expected{{"lift", {"grasp", "look"}},
                                                                 {"shake", {"grasp"}}};
  EXPECT_EQ(c.task.prerequisites, expected);
  EXPECT_EQ(c.task.sense, -2);
  EXPECT_EQ(campaign_config_from_json(to_json(c), "campaign.json").task.prerequisites, expected);
  std::filesystem::create_directories(dir_ / "data" / "shake");
  std::ofstream(dir_ / "data" / "shake" / "audio.csv") << "object,session,f\nmug,1,0.5\n";
  EXPECT_EQ(c.identity()["task"]["requires"]["lift"], (std::vector<std::string>{"grasp", "look"}));
  // Campaigns without prerequisites keep the identity they had before they existed.
  const CampaignConfig plain = parse_campaign_config(text_, source());
  EXPECT_FALSE(plain.identity()["task"].contains("requires"));
  EXPECT_FALSE(to_json(plain)["task"].contains("requires"));
  // Requires alone keeps the default rewards.
  const CampaignConfig only = parse_campaign_config(
      "world: {type: dataset, data: data}\ntask: {requires: {shake: [grasp]}}\n"
      "arms: [{name: plan}]\nplanner: {episodes: 10}\n",
      source());
  EXPECT_EQ(only.task.right, 10);
  EXPECT_EQ(only.task.prerequisites.at("shake"), (std::vector<std::string>{"grasp"}));
}

TEST_F(DatasetCampaignConfig, RequiresMistakesNameTheirLine) {
  const auto task = [&](const std::string& entries) {
    return error(
        "world: {type: dataset, data: data}\narms: [{name: plan}]\n"
        "planner: {episodes: 10}\ntask:\n  requires:\n" +
        entries);
  };
  const std::string itself = task("    shake: [grasp, shake]\n");
  EXPECT_EQ(itself.substr(0, 2), "6:") << itself;
  EXPECT_NE(itself.find("shake cannot require itself"), std::string::npos) << itself;
  const std::string twice = task("    shake: [grasp, grasp]\n");
  EXPECT_EQ(twice.substr(0, 2), "6:") << twice;
  const std::string scalar = task("    shake: grasp\n");
  EXPECT_NE(scalar.find("task.requires.shake must be a list of behaviours"), std::string::npos)
      << scalar;
  const std::string list = task("    - shake\n");
  EXPECT_EQ(list.substr(0, 2), "6:") << list;
}

TEST_F(DatasetCampaignConfig, DefaultsAreTheReportsRewardsAndSessions) {
  const CampaignConfig c = parse_campaign_config(
      "world: {type: dataset, data: data}\narms: [{name: plan}]\nplanner: {episodes: 10}\n",
      source());
  EXPECT_EQ(c.world.hold_out, perception::HoldOut::session);
  EXPECT_EQ(c.task.right, 10);
  EXPECT_EQ(c.task.wrong, -100);
  EXPECT_EQ(c.task.sense, -1);
  EXPECT_EQ(c.arms[0].strategy, "plan");
}

// A planner sorting novel objects plans with lookalikes and counts unheard outcomes at commit
// unless its arm names them; the fixed strategies, a world holding out sessions and the other
// worlds keep the plain defaults. The configuration keeps the file's words; the resolved values
// are in the identity (a campaign begun with the old defaults is another campaign).
TEST_F(DatasetCampaignConfig, ThePlannersDefaultsOnNovelObjectsAreLookalikesAndCommit) {
  std::string text = text_;
  text.replace(text.find("  - {name: greedy"), 0,
               "  - {name: plain, strategy: plan, unheard: share, lookalike: false}\n"
               "  - {name: rollout, strategy: plan, leaf: rollout}\n"
               "  - {name: exact, strategy: plan, leaf: exact}\n");
  const CampaignConfig c = parse_campaign_config(text, source());
  ASSERT_EQ(c.arms.size(), 5u);
  EXPECT_FALSE(c.arms[0].lookalike.has_value());  // as written
  EXPECT_EQ(c.arms[0].unheard, "");
  const std::vector<ResolvedArm> r = resolve_arms(c);
  EXPECT_TRUE(r[0].plans_with.lookalike);
  EXPECT_EQ(r[0].planner.unheard, "commit");
  EXPECT_FALSE(r[1].plans_with.lookalike);  // named: kept
  EXPECT_EQ(r[1].planner.unheard, "share");
  EXPECT_TRUE(r[2].plans_with.lookalike);
  EXPECT_EQ(r[2].planner.unheard, "");  // a rollout leaf cannot commit: the search's default
  EXPECT_EQ(r[3].planner.unheard, "commit");
  EXPECT_FALSE(r[4].plans_with.lookalike);  // the greedy rule
  EXPECT_EQ(r[4].planner.unheard, "");
  EXPECT_EQ(r[4].planner.solver, "information_gain");
  std::filesystem::create_directories(dir_ / "data" / "shake");  // the identity hashes the data
  std::ofstream(dir_ / "data" / "shake" / "audio.csv") << "object,session,f\nmug,1,0.5\n";
  const nlohmann::json arms = c.identity()["arms"];
  EXPECT_EQ(arms[0]["unheard"], "commit");
  EXPECT_EQ(arms[0]["lookalike"], true);
  EXPECT_FALSE(arms[4].contains("lookalike"));
  EXPECT_EQ(to_json(campaign_config_from_json(to_json(c), "campaign.json")), to_json(c));
  // campaign.json keeps which keys the file gave: read back (a merge, a certificate), the arms
  // resolve as they did, `lookalike: false` named included.
  const std::vector<ResolvedArm> again =
      resolve_arms(campaign_config_from_json(to_json(c), "campaign.json"));
  for (std::size_t a = 0; a < r.size(); ++a) {
    EXPECT_EQ(again[a].plans_with, r[a].plans_with) << r[a].name;
    EXPECT_EQ(again[a].planner.unheard, r[a].planner.unheard) << r[a].name;
  }
  // Known objects' new sessions: the plain planner.
  std::string sessions = text;
  sessions.replace(sessions.find("hold_out: object"), 16, "hold_out: session");
  const ResolvedArm known = resolve_arms(parse_campaign_config(sessions, source()))[0];
  EXPECT_FALSE(known.plans_with.lookalike);
  EXPECT_EQ(known.planner.unheard, "");
  // POMCP has no unheard estimate to choose.
  text.replace(text.find("planner: {episodes: 100}"), 24,
               "planner: {episodes: 100, solver: pomcp}");
  EXPECT_EQ(resolve_arms(parse_campaign_config(text, source()))[0].planner.unheard, "");
  // A problem file's planner keeps the search's defaults.
  const ResolvedArm model =
      resolve_arms(parse_campaign_config(with_arm("{name: a, problem: p.yaml}"), "/dir/c.yaml"))[0];
  EXPECT_FALSE(model.plans_with.lookalike);
  EXPECT_EQ(model.planner.unheard, "");
}

TEST_F(DatasetCampaignConfig, MistakesNameTheLineAndTheProblem) {
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string text = text_;
    text.replace(text.find(from), from.size(), to);
    return error(text);
  };
  EXPECT_NE(replaced("data: data", "data: nowhere").find("does not exist"), std::string::npos);
  EXPECT_NE(replaced("hold_out: object", "hold_out: trial")
                .find("hold-out 'trial': expected session or object"),
            std::string::npos);
  EXPECT_NE(replaced(", groups: groups.csv", "").find("hold_out: object needs groups"),
            std::string::npos);
  EXPECT_NE(replaced("groups.csv", "none.csv").find("groups file"), std::string::npos);
  EXPECT_NE(replaced("strategy: information_gain", "strategy: greedy").find("strategy 'greedy'"),
            std::string::npos);
  EXPECT_NE(replaced("strategy: plan}", "strategy: plan, problem: p.yaml}")
                .find("not for a dataset world's arms"),
            std::string::npos);
  EXPECT_NE(replaced("right: 5", "right: -500").find("right must be greater than wrong"),
            std::string::npos);
  const std::string trials = error(text_ + "trials: [{object: mug}]\n");
  EXPECT_NE(trials.find("(object, session) pairs"), std::string::npos) << trials;
  EXPECT_EQ(trials.substr(0, 2), "8:") << trials;
  // task is for dataset worlds only.
  EXPECT_NE(error_of(kMinimal + "task: {rewards: {right: 1}}\n").find("task is for dataset worlds"),
            std::string::npos);
}

// The identity fingerprints the data as loaded: a changed value changes it, a file the loader skips
// (a README beside the action folders) does not.
TEST_F(DatasetCampaignConfig, IdentityCoversTheDataItself) {
  const CampaignConfig c = parse_campaign_config(text_, source());
  std::filesystem::create_directories(dir_ / "data" / "shake");
  std::ofstream(dir_ / "data" / "shake" / "audio.csv") << "object,session,f\nmug,1,0.5\n";
  const auto before = c.identity();
  std::ofstream(dir_ / "data" / "README.md") << "notes\n";
  EXPECT_EQ(c.identity(), before);
  std::ofstream(dir_ / "data" / "shake" / "audio.csv") << "object,session,f\nmug,1,0.6\n";
  EXPECT_NE(c.identity(), before);
}

}  // namespace echoplan::experiment
