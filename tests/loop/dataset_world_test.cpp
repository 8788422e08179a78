// The dataset world replays one session: each sensing action hears the session's next recorded
// performance through the fold's model, a sorting action earns the problem's reward for the true
// class, and a behaviour used more often than recorded is a logic error.
#include "loop/dataset_world.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

#include "../perception/synthetic_feature_set.h"
#include "common/error.h"
#include "loop/dataset_problem.h"
#include "perception/dataset_folds.h"

namespace echoplan::loop {
namespace {

using perception::test_features::SyntheticSpec;

struct Replay {
  std::shared_ptr<const perception::FeatureSet> set;
  perception::DatasetTask task;
  std::shared_ptr<const perception::ObservationModel> model;
};

// 6 objects in groups of 3, 3 sessions each; press once and strike twice per session. The model
// is fitted without session `held_out`.
Replay replay(int held_out) {
  const auto dir = perception::test_features::fresh_folder("dataset_world");
  SyntheticSpec spec;
  spec.objects = 6;
  spec.sessions = 3;
  spec.group_size = 3;
  spec.actions = {"press"};
  perception::test_features::write_synthetic_feature_set(dir, spec);
  spec.actions = {"strike"};
  spec.repeats = 2;
  spec.seed = 2;
  perception::test_features::write_synthetic_feature_set(dir, spec);
  Replay r;
  r.set =
      std::make_shared<const perception::FeatureSet>(perception::load_feature_set(dir.string()));
  const auto groups = perception::load_groups((dir / "groups.csv").string());
  r.task = perception::make_dataset_task(*r.set, &groups, perception::HoldOut::session);
  std::vector<int> training;
  for (std::size_t s = 0; s < r.set->sessions.size(); ++s)
    if (static_cast<int>(s) != held_out) training.push_back(static_cast<int>(s));
  r.model = std::make_shared<const perception::ObservationModel>(perception::fit_observation_model(
      *r.set, r.task, training, perception::session_fit_options()));
  return r;
}

// The rows of `session` in action `action` of the set, in file order.
std::vector<int> rows_of(const perception::FeatureSet& set, int action, int session) {
  std::vector<int> rows;
  for (std::size_t i = 0; i < set.actions[action].rows.size(); ++i)
    if (set.actions[action].rows[i].session == session) rows.push_back(static_cast<int>(i));
  return rows;
}

TEST(DatasetWorld, EachSensingActionHearsTheSessionsNextPerformance) {
  const int session = 4;  // obj1's second session
  const Replay r = replay(session);
  const pomdp::ObjectProblemData shape = dataset_problem(r.task, *r.model, {}, {1, 2});
  const pomdp::ObjectIdentificationModel problem(
      dataset_problem(r.task, *r.model, {}, session_uses(shape, *r.set, session)));
  EXPECT_EQ(problem.max_uses(0), 1);  // press once, strike twice, as the session recorded
  EXPECT_EQ(problem.max_uses(1), 2);
  DatasetWorld world(problem, {r.set, r.model, session});
  Rng rng(1);
  const int object = r.set->sessions[session].object;
  world.reset(pomdp::State{{}, {r.task.class_of_object[object]}}, rng);
  // strike (data action 1) twice: the session's first, then second strike row, as the model hears
  // them.
  const std::vector<int> strikes = rows_of(*r.set, 1, session);
  ASSERT_EQ(strikes.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const WorldStep step = world.execute(1, rng);
    EXPECT_EQ(step.outcome.observation.index,
              perception::classify_row(*r.model, 1, *r.set, strikes[k]));
    EXPECT_EQ(step.outcome.reward, -1.0);
    EXPECT_FALSE(step.outcome.terminal);
    EXPECT_FALSE(step.robot.has_value());
    // The model's calibrated probability of the class it heard: at least chance among the classes.
    ASSERT_TRUE(step.outcome.heard_probability.has_value());
    EXPECT_GE(*step.outcome.heard_probability, 1.0 / r.task.classes.size());
    EXPECT_LE(*step.outcome.heard_probability, 1.0);
  }
  // A third strike was never recorded: the planner's limits were not the session's.
  EXPECT_THAT([&] { world.execute(1, rng); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr(
                  "the planner chose 'strike' more often than the session recorded it (2 times)")));
  const WorldStep press = world.execute(0, rng);
  EXPECT_EQ(press.outcome.observation.index,
            perception::classify_row(*r.model, 0, *r.set, rows_of(*r.set, 0, session)[0]));
  // obj1 is in group0: sorting into group0 (action 2) is right, into group1 wrong.
  const WorldStep sort = world.execute(2, rng);
  EXPECT_EQ(sort.outcome.reward, 10.0);
  EXPECT_FALSE(sort.outcome.heard_probability.has_value());  // sorting hears nothing
  world.reset(pomdp::State{{}, {r.task.class_of_object[object]}}, rng);
  const WorldStep wrong = world.execute(3, rng);
  EXPECT_EQ(wrong.outcome.reward, -100.0);
  EXPECT_TRUE(wrong.outcome.terminal);
  EXPECT_EQ(wrong.outcome.observation.index, problem.none_symbol());
  // A new trial starts from the session's first performance again.
  EXPECT_EQ(world.execute(1, rng).outcome.observation.index,
            perception::classify_row(*r.model, 1, *r.set, strikes[0]));
}

TEST(DatasetWorld, ASessionMissingABehaviourIsAnInputErrorNamingIt) {
  const Replay r = replay(0);
  pomdp::ObjectProblemData data = dataset_problem(r.task, *r.model, {}, {1, 2});
  // A problem naming an action the data does not have.
  data.sensing[0].name = "shake";
  EXPECT_THROW(session_uses(data, *r.set, 0), InputError);
  perception::FeatureSet missing = *r.set;
  // Session 0's strike rows relabelled as session 1's: session 0 never struck.
  for (perception::RowLabel& row : missing.actions[1].rows)
    if (row.session == 0) row.session = 1;
  try {
    session_uses(dataset_problem(r.task, *r.model, {}, {1, 2}), missing, 0);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no recording of 'strike'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace echoplan::loop
