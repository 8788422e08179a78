// The YAML reader reproduces the report's tables exactly and rejects bad files with file and line.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "common/error.h"
#include "pomdp/problem.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;
using testing::repo_text;

const ObjectIdentificationModel& object_model(const Problem& p) {
  return (*p.model->object_identification());
}

// The report's section 3.3, typed in here independently of the YAML file: [object][action][class].
constexpr double kReportTable[4][2][4] = {
    {{0.5, 0.3, 0.15, 0.05}, {0.6, 0.05, 0.3, 0.05}},
    {{0.11, 0.67, 0.11, 0.11}, {0.05, 0.6, 0.3, 0.05}},
    {{0.11, 0.11, 0.67, 0.11}, {0.11, 0.11, 0.67, 0.11}},
    {{0.01, 0.01, 0.48, 0.5}, {0.11, 0.11, 0.11, 0.67}},
};

TEST(ProblemYaml, ReportProblemMatchesTheReport) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  const auto& m = object_model(p);
  const ObjectProblemData& d = m.data();
  EXPECT_EQ(d.objects,
            (std::vector<std::string>{"pringles_can", "coffee_mug", "plastic_cup", "paper_base"}));
  EXPECT_EQ(m.spec().action_names,
            (std::vector<std::string>{"slide", "strike", "move_to_A", "move_to_B"}));
  EXPECT_EQ(d.discount, 0.99);
  EXPECT_EQ(p.belief.type, BeliefSettings::Type::particle);
  EXPECT_EQ(p.belief.particles, 1000);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(d.prior[k], 0.25);
    for (int a = 0; a < 2; ++a) {
      for (int o = 0; o < 4; ++o)
        EXPECT_EQ(d.observation_table[a][k][o], kReportTable[k][a][o]) << k << a << o;
    }
  }
  // Section 3.3: pringles_can and plastic_cup belong at A, coffee_mug and paper_base at B.
  const double group_a[4] = {10, -100, 10, -100};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(d.sorting_reward[0][k], group_a[k]);
    EXPECT_EQ(d.sorting_reward[1][k], group_a[k] == 10 ? -100 : 10);
  }
  EXPECT_EQ(d.sensing[0].reward, -1);
  EXPECT_EQ(d.sensing[1].reward, -1);
  EXPECT_EQ(d.collision_reward, -100);
  EXPECT_EQ(d.sensing[0].offset_change, (std::array<double, 3>{0.05, 0, 0}));
  EXPECT_EQ(d.sensing[1].offset_change, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(d.initial_offset, (std::array<double, 3>{0.1, 0, 0}));
  EXPECT_EQ(d.initial_joints[0], -2.89527);
  EXPECT_EQ(d.initial_joints[6], -1.54233);
  EXPECT_EQ(p.planner.solver, "abt");
  EXPECT_EQ(p.planner.step_ms, 2000);
  EXPECT_EQ(p.planner.episodes, 0);
}

TEST(ProblemYaml, WeightedPriorIsNormalised) {
  std::string text = repo_text("problems/audio_objects.yaml");
  const std::string from = "objects: uniform";
  text.replace(text.find(from), from.size(), "objects: {pringles_can: 3, coffee_mug: 1}");
  const Problem p = parse_problem_yaml(text, "prior.yaml");
  EXPECT_EQ(object_model(p).data().prior, (std::vector<double>{0.75, 0.25, 0.0, 0.0}));
}

TEST(ProblemYaml, UseLimitsAreReadPerSensingAction) {
  std::string text = repo_text("problems/audio_objects.yaml");
  const std::string from = "sorting: [move_to_A, move_to_B]";
  text.replace(text.find(from), from.size(), from + "\n  uses: {strike: 3}");
  const Problem p = parse_problem_yaml(text, "uses.yaml");
  EXPECT_EQ(object_model(p).data().sensing[0].uses, 0);  // slide: not listed, no limit
  EXPECT_EQ(object_model(p).data().sensing[1].uses, 3);
  EXPECT_EQ(p.model->max_uses(0), 0);
  EXPECT_EQ(p.model->max_uses(1), 3);
  EXPECT_EQ(p.model->max_uses(2), 0);  // a sorting action
}

TEST(ProblemYaml, PrerequisitesAreReadPerSensingAction) {
  std::string text = repo_text("problems/audio_objects.yaml");
  const std::string from = "sorting: [move_to_A, move_to_B]";
  text.replace(text.find(from), from.size(), from + "\n  requires: {strike: [slide]}");
  const Problem p = parse_problem_yaml(text, "requires.yaml");
  EXPECT_TRUE(p.model->prerequisites(0).empty());
  EXPECT_EQ(p.model->prerequisites(1), (std::vector<int>{0}));
  EXPECT_TRUE(p.model->prerequisites(2).empty());  // a sorting action
}

// Each bad input: replace one piece of the report's problem file and expect the error's line and
// message.
struct BadCase {
  const char* label;
  const char* from;
  const char* to;
  int line;
  const char* message_part;
};

class ProblemYamlErrors : public ::testing::TestWithParam<BadCase> {};

int line_of(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

TEST_P(ProblemYamlErrors, ReportFileLineAndProblem) {
  const BadCase& c = GetParam();
  std::string text = repo_text("problems/audio_objects.yaml");
  const std::size_t at = text.find(c.from);
  ASSERT_NE(at, std::string::npos) << c.from;
  text.replace(at, std::string(c.from).size(), c.to);
  // line -1 means "the line where the replacement starts".
  const int expected_line = c.line >= 0 ? c.line : line_of(text, c.to);
  try {
    parse_problem_yaml(text, "bad.yaml");
    FAIL() << c.label << ": no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.yaml") << c.label;
    EXPECT_EQ(e.line(), expected_line) << c.label << ": " << e.what();
    EXPECT_NE(e.problem().find(c.message_part), std::string::npos) << c.label << ": " << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    EachMistake, ProblemYamlErrors,
    ::testing::Values(
        BadCase{"row_sum", "pringles_can: [0.5, 0.3, 0.15, 0.05]",
                "pringles_can: [0.5, 0.3, 0.15, 0.06]", -1, "sums to 1.01"},
        BadCase{"row_length", "coffee_mug: [0.11, 0.67, 0.11, 0.11]",
                "coffee_mug: [0.11, 0.67, 0.22]", -1, "has 3 entries, expected 4"},
        BadCase{"negative_probability", "paper_base: [0.01, 0.01, 0.48, 0.5]",
                "paper_base: [-0.01, 0.03, 0.48, 0.5]", -1, "outside [0, 1]"},
        BadCase{"unknown_action_in_table", "    strike:\n      pringles_can",
                "    stryke:\n      pringles_can", -1, "unknown sensing action 'stryke'"},
        BadCase{"unknown_object_in_table", "      paper_base: [0.01, 0.01, 0.48, 0.5]",
                "      paper_bass: [0.01, 0.01, 0.48, 0.5]", -1, "unknown object 'paper_bass'"},
        BadCase{"unknown_object_in_reward", "move_to_A: {pringles_can: 10",
                "move_to_A: {pringles: 10", -1, "unknown object 'pringles'"},
        BadCase{"missing_key", "discount: 0.99\n", "", 4, "missing key 'discount'"},
        BadCase{"missing_reward_entry", "sensing: {slide: -1, strike: -1}", "sensing: {slide: -1}",
                -1, "missing key 'strike'"},
        BadCase{"negative_count", "particles: 1000", "particles: -5", -1, "must not be negative"},
        BadCase{"wrong_type_number", "discount: 0.99", "discount: high", -1, "must be a number"},
        BadCase{"wrong_type_list", "objects: [pringles_can, coffee_mug, plastic_cup, paper_base]",
                "objects: pringles_can", -1, "must be a list of names"},
        BadCase{"unknown_top_key", "discount: 0.99", "discont: 0.99", -1, "unknown key 'discont'"},
        BadCase{"bad_discount", "discount: 0.99", "discount: 1.5", -1,
                "discount must be in (0, 1)"},
        BadCase{"unknown_belief", "belief: {type: particle", "belief: {type: kalman", -1,
                "unknown belief.type"},
        BadCase{"two_budgets", "budget: {step_ms: 2000}", "budget: {step_ms: 2000, episodes: 10}",
                -1, "exactly one of episodes or step_ms"},
        BadCase{"joint_count", "joints: [-2.89527, 1.45058,", "joints: [1.45058,", -1,
                "needs 7 numbers"},
        BadCase{"unsupported_part", "type: known_object", "type: rollout", -1,
                "unsupported heuristic.type"},
        BadCase{"duplicate_key",
                "      coffee_mug: [0.11, 0.67, 0.11, 0.11]\n      plastic_cup: [0.11, 0.11, 0.67, "
                "0.11]\n      paper_base: [0.01",
                "      coffee_mug: [0.11, 0.67, 0.11, 0.11]\n      coffee_mug: [0.11, 0.11, 0.67, "
                "0.11]\n      paper_base: [0.01",
                36, "key 'coffee_mug' appears twice"},
        BadCase{"collision_probability", "    slide: 0\n    strike: 0",
                "    slide: 2\n    strike: 0", -1, "collision probability must be in [0, 1]"},
        BadCase{"zero_uses", "sorting: [move_to_A, move_to_B]",
                "sorting: [move_to_A, move_to_B]\n  uses: {slide: 0}", 10,
                "use limit of slide must be a positive integer"},
        BadCase{"fractional_uses", "sorting: [move_to_A, move_to_B]",
                "sorting: [move_to_A, move_to_B]\n  uses: {slide: 1.5}", 10, "use limit of slide"},
        BadCase{"uses_of_a_sorting_action", "sorting: [move_to_A, move_to_B]",
                "sorting: [move_to_A, move_to_B]\n  uses: {move_to_A: 1}", 10,
                "unknown sensing action 'move_to_A'"},
        BadCase{"requires_an_unknown_action", "sorting: [move_to_A, move_to_B]",
                "sorting: [move_to_A, move_to_B]\n  requires: {strike: [grasp]}", 10,
                "unknown sensing action 'grasp'"},
        BadCase{"requires_a_sorting_action", "sorting: [move_to_A, move_to_B]",
                "sorting: [move_to_A, move_to_B]\n  requires: {strike: [move_to_A]}", 10,
                "unknown sensing action 'move_to_A'"},
        BadCase{"requires_itself", "sorting: [move_to_A, move_to_B]",
                "sorting: [move_to_A, move_to_B]\n  requires: {strike: [strike]}", 10,
                "strike cannot require itself"},
        BadCase{"requires_twice", "sorting: [move_to_A, move_to_B]",
                "sorting: [move_to_A, move_to_B]\n  requires: {strike: [slide, slide]}", 10,
                "slide is listed twice in actions.requires of strike"},
        BadCase{"requires_not_a_list", "sorting: [move_to_A, move_to_B]",
                "sorting: [move_to_A, move_to_B]\n  requires: {strike: slide}", 10,
                "actions.requires of strike must be a list of sensing actions"},
        BadCase{"requires_in_a_circle", "sorting: [move_to_A, move_to_B]",
                "sorting: [move_to_A, move_to_B]\n  requires:\n    slide: [strike]\n    strike: "
                "[slide]",
                11, "goes round in a circle (slide -> strike -> slide)"}),
    [](const auto& test_info) { return std::string(test_info.param.label); });

TEST(ProblemYaml, EmptyFileIsAnError) {
  try {
    parse_problem_yaml("", "empty.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(e.problem().find("empty"), std::string::npos);
  }
}

TEST(ProblemYaml, GarbageIsAnErrorNotACrash) {
  const std::vector<std::string> garbage = {"just some words",
                                            "[1, 2, 3]",
                                            "{{{{",
                                            "key: [unclosed",
                                            "\x01\x02\xff\xfe binary",
                                            "- a\n- b\n",
                                            "objects: {a: 1}",
                                            ": : :",
                                            "name: x\ndiscount: [0.9]",
                                            "\t\tname: tab"};
  for (const auto& text : garbage) {
    EXPECT_THROW(parse_problem_yaml(text, "garbage.yaml"), InputError) << text;
  }
}

}  // namespace
}  // namespace echoplan::pomdp

namespace echoplan::pomdp {
namespace {

TEST(ProblemDefaults, FilesWithoutAPlannerSectionGetAnEpisodeBudget) {
  // A .pomdp file cannot say how to plan; a wall-time default would make runs machine-dependent.
  const Problem tiger = load_problem(testing::repo_file("problems/tiger.pomdp"));
  EXPECT_EQ(tiger.planner.episodes, 1000);
  EXPECT_EQ(tiger.planner.step_ms, 0.0);
}

}  // namespace
}  // namespace echoplan::pomdp
