// The Cassandra .pomdp reader: tables of known files, every syntactic form, and its errors.
#include "pomdp/cassandra_reader.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "pomdp/problem.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;

TEST(CassandraReader, TigerTables) {
  const Problem p = load_problem(repo_file("problems/tiger.pomdp"));
  const TabularModel& t = *p.model->tabular();
  ASSERT_EQ(t.num_states(), 2);
  ASSERT_EQ(t.num_actions(), 3);
  ASSERT_EQ(t.num_observations(), 2);
  EXPECT_EQ(t.discount(), 0.95);
  EXPECT_EQ(p.model->spec().action_names,
            (std::vector<std::string>{"listen", "open-left", "open-right"}));
  EXPECT_EQ(t.initial_belief(), (std::vector<double>{0.5, 0.5}));
  // listen keeps the tiger where it is and hears it right 85% of the time.
  EXPECT_EQ(t.transition(0, 0, 0), 1.0);
  EXPECT_EQ(t.transition(0, 0, 1), 0.0);
  EXPECT_EQ(t.observation(0, 0, 0), 0.85);
  EXPECT_EQ(t.observation(0, 1, 0), 0.15);
  EXPECT_EQ(t.observation(0, 1, 1), 0.85);
  // Opening resets the tiger uniformly and tells nothing.
  for (int a = 1; a < 3; ++a) {
    for (int s = 0; s < 2; ++s) {
      EXPECT_EQ(t.transition(s, a, 0), 0.5);
      EXPECT_EQ(t.observation(a, s, 1), 0.5);
    }
  }
  EXPECT_EQ(t.reward(0, 0), -1.0);
  EXPECT_EQ(t.reward(0, 1), -100.0);
  EXPECT_EQ(t.reward(1, 1), 10.0);
  EXPECT_EQ(t.reward(0, 2), 10.0);
  EXPECT_EQ(t.reward(1, 2), -100.0);
  EXPECT_FALSE(t.terminal(0));
  EXPECT_FALSE(t.terminal(1));
  EXPECT_EQ(p.belief.type, BeliefSettings::Type::exact);
}

// The .pomdp version of the report's problem and the YAML version are one model.
TEST(CassandraReader, AudioObjectsPomdpEqualsTheYamlProblem) {
  const Problem pomdp = load_problem(repo_file("problems/audio_objects.pomdp"));
  const TabularModel& a = *pomdp.model->tabular();
  const Problem yaml = load_problem(repo_file("problems/audio_objects.yaml"));
  const TabularModel& b = *yaml.model->tabular();
  ASSERT_EQ(a.num_states(), b.num_states());
  ASSERT_EQ(a.num_actions(), b.num_actions());
  ASSERT_EQ(a.num_observations(), b.num_observations());
  EXPECT_EQ(a.discount(), b.discount());
  EXPECT_EQ(a.initial_belief(), b.initial_belief());
  for (int s = 0; s < a.num_states(); ++s) {
    EXPECT_EQ(a.terminal(s), b.terminal(s)) << s;
    for (int act = 0; act < a.num_actions(); ++act) {
      EXPECT_EQ(a.reward(s, act), b.reward(s, act)) << s << " " << act;
      for (int s2 = 0; s2 < a.num_states(); ++s2)
        EXPECT_EQ(a.transition(s, act, s2), b.transition(s, act, s2));
      for (int o = 0; o < a.num_observations(); ++o)
        EXPECT_EQ(a.observation(act, s, o), b.observation(act, s, o));
    }
  }
  EXPECT_TRUE(a.terminal(4));
}

TEST(CassandraReader, CountsIndicesWildcardsAndCost) {
  const std::string text = R"(
discount: 0.9   # comment after a value
values: cost
states: 3
actions: 2
observations: 2
start: 0.2 0.3 0.5
T: * identity   # the matrix form with the identity keyword, for every action
)";
  const auto m = parse_cassandra_pomdp(text + R"(
T: 1 : 0
0 0.5 0.5
T: 1 : 2 : 0 1.0
T: 1 : 2 : 2 0.0
O: * uniform
O: 0 : 1 : 0 1
O: 0 : 1 : 1 0
R: * : * : * : * 2
R: 1 : 2 : * : * 4
)",
                                       "counts.pomdp");
  EXPECT_EQ(m->num_states(), 3);
  EXPECT_EQ(m->spec().action_names, (std::vector<std::string>{"a0", "a1"}));
  EXPECT_EQ(m->initial_belief(), (std::vector<double>{0.2, 0.3, 0.5}));
  EXPECT_EQ(m->transition(1, 0, 1), 1.0);
  EXPECT_EQ(m->transition(0, 1, 0), 0.0);
  EXPECT_EQ(m->transition(0, 1, 2), 0.5);
  EXPECT_EQ(m->transition(2, 1, 0), 1.0);
  EXPECT_EQ(m->transition(2, 1, 2), 0.0);
  EXPECT_EQ(m->observation(0, 1, 0), 1.0);
  EXPECT_EQ(m->observation(1, 1, 0), 0.5);
  // values: cost negates every reward.
  EXPECT_EQ(m->reward(0, 0), -2.0);
  EXPECT_EQ(m->reward(2, 1), -4.0);
}

// A reward that depends on the next state and observation is folded into its expectation.
TEST(CassandraReader, OutcomeDependentRewardIsExpected) {
  const auto m = parse_cassandra_pomdp(R"(
discount: 0.5
states: a b
actions: go
observations: x y
start: a
T: go : a
0.25 0.75
T: go : b : b 1
O: go
0.5 0.5
1 0
R: go : a : b : x 8
R: go : a : * : y 4
)",
                                       "outcome.pomdp");
  // From a: s'=a (0.25): o=x 0.5 -> 0, o=y 0.5 -> 4; s'=b (0.75): x (1.0) -> 8.
  EXPECT_DOUBLE_EQ(m->reward(0, 0), 0.25 * 0.5 * 4 + 0.75 * 1.0 * 8);
  EXPECT_EQ(m->initial_belief(), (std::vector<double>{1.0, 0.0}));
}

TEST(CassandraReader, StartIncludeExcludeForms) {
  const std::string head =
      "discount: 0.9\nstates: a b c d\nactions: x\nobservations: o\nT: x identity\nO: x uniform\n";
  EXPECT_EQ(parse_cassandra_pomdp(head + "start include: a c\n", "s.pomdp")->initial_belief(),
            (std::vector<double>{0.5, 0, 0.5, 0}));
  EXPECT_EQ(parse_cassandra_pomdp(head + "start exclude: b\n", "s.pomdp")->initial_belief(),
            (std::vector<double>{1.0 / 3, 0, 1.0 / 3, 1.0 / 3}));
  EXPECT_EQ(parse_cassandra_pomdp(head + "start: uniform\n", "s.pomdp")->initial_belief(),
            (std::vector<double>{0.25, 0.25, 0.25, 0.25}));
  EXPECT_EQ(parse_cassandra_pomdp(head + "start: d\n", "s.pomdp")->initial_belief(),
            (std::vector<double>{0, 0, 0, 1}));
  // No start line: uniform. Every state is absorbing here (identity, zero reward).
  const auto m = parse_cassandra_pomdp(head, "s.pomdp");
  EXPECT_EQ(m->initial_belief(), (std::vector<double>{0.25, 0.25, 0.25, 0.25}));
  EXPECT_TRUE(m->terminal(0));
}

struct BadPomdp {
  const char* label;
  const char* text;
  int line;
  const char* message_part;
};

class CassandraErrors : public ::testing::TestWithParam<BadPomdp> {};

TEST_P(CassandraErrors, ReportFileLineAndProblem) {
  const BadPomdp& c = GetParam();
  try {
    parse_cassandra_pomdp(c.text, "bad.pomdp");
    FAIL() << c.label << ": no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.pomdp");
    EXPECT_EQ(e.line(), c.line) << c.label << ": " << e.what();
    EXPECT_NE(e.problem().find(c.message_part), std::string::npos) << c.label << ": " << e.what();
  }
}

#define HEAD "discount: 0.9\nstates: a b\nactions: x\nobservations: o p\n"
INSTANTIATE_TEST_SUITE_P(
    EachMistake, CassandraErrors,
    ::testing::Values(
        BadPomdp{"empty", "", 1, "empty"},
        BadPomdp{"comments_only", "# nothing\n# here\n", 1, "empty"},
        BadPomdp{"garbage", "hello world\n", 1, "unexpected 'hello'"},
        BadPomdp{"binary", "\x01\x02\xff\n", 1, "unexpected"},
        BadPomdp{"missing_discount",
                 "states: a\nactions: x\nobservations: o\nT: x identity\nO: x uniform\n", 1,
                 "missing 'discount:'"},
        BadPomdp{"bad_discount", "discount: 2\n", 1, "discount must be in (0, 1)"},
        BadPomdp{"discount_not_number", "discount: high\n", 1, "expected a number"},
        BadPomdp{"unknown_state", HEAD "T: x : a : c 1\n", 5, "unknown state 'c'"},
        BadPomdp{"unknown_action", HEAD "T: y identity\n", 5, "unknown action 'y'"},
        BadPomdp{"index_out_of_range", HEAD "O: x : 5 uniform\n", 5, "out of range"},
        BadPomdp{"row_sum", HEAD "T: x identity\nO: x : a\n0.5 0.6\nO: x : b uniform\n", 6,
                 "O row for action 'x' and state 'a' sums to 1.1"},
        BadPomdp{"row_never_given", HEAD "T: x identity\nO: x : a uniform\n", 6, "never given"},
        BadPomdp{"wrong_count", HEAD "T: x\n1 0\n0\n", 6, "expects 4 number(s)"},
        BadPomdp{"not_a_number", HEAD "T: x : a\n1 zero\n", 6, "expected a number, got 'zero'"},
        BadPomdp{"table_before_sizes", "discount: 0.9\nstates: 2\nT: 0 identity\n", 3,
                 "before 'states:'"},
        BadPomdp{"negative_count", "discount: 0.9\nstates: -2\n", 2, "positive whole number"},
        BadPomdp{"bad_values", HEAD "values: money\n", 5, "'reward' or 'cost'"},
        BadPomdp{"missing_colon", "discount 0.9\n", 1, "expected ':'"},
        BadPomdp{"start_sum", HEAD "start: 0.5 0.4\n", 5, "sums to"},
        // Found by fuzz/problem_file_fuzz: '*' indexed state -1 (a heap overflow).
        BadPomdp{"start_wildcard", HEAD "start: *\n", 5, "not '*'"},
        BadPomdp{"start_include_wildcard", HEAD "start include: a\n*: x\n", 6, "not '*'"},
        BadPomdp{"duplicate_state", "discount: 0.9\nstates: a a\n", 2, "duplicate name 'a'"},
        BadPomdp{"reward_needs_state", HEAD "R: x 5\n", 5, "at least"},
        BadPomdp{"too_large", "discount: 0.9\nstates: 100000\nactions: 10\nobservations: 2\n", 4,
                 "too large"}),
    [](const auto& test_info) { return std::string(test_info.param.label); });
#undef HEAD

}  // namespace
}  // namespace echoplan::pomdp
