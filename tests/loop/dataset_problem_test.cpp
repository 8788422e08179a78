#include "loop/dataset_problem.h"

#include <gtest/gtest.h>

#include "../perception/synthetic_feature_set.h"
#include "common/error.h"
#include "perception/dataset_folds.h"
#include "perception/fit_observation_model.h"
#include "pomdp/object_identification_model.h"

namespace echoplan::loop {
namespace {

using perception::test_features::SyntheticSpec;

struct Fitted {
  perception::FeatureSet set;
  perception::DatasetTask task;
  perception::ObservationModel model;
};

// 6 objects in groups of 3, two actions (strike performed twice per session, press once).
Fitted fitted() {
  const auto dir = perception::test_features::fresh_folder("dataset_problem");
  SyntheticSpec spec;
  spec.objects = 6;
  spec.group_size = 3;
  spec.actions = {"press", "strike"};
  spec.repeats = 1;
  perception::test_features::write_synthetic_feature_set(dir, spec);
  spec.actions = {"strike"};
  spec.repeats = 2;
  perception::test_features::write_synthetic_feature_set(dir, spec);
  Fitted f{perception::load_feature_set(dir.string()), {}, {}};
  const auto groups = perception::load_groups((dir / "groups.csv").string());
  f.task = perception::make_dataset_task(f.set, &groups, perception::HoldOut::session);
  std::vector<int> all(f.set.sessions.size());
  for (std::size_t s = 0; s < all.size(); ++s) all[s] = static_cast<int>(s);
  f.model =
      perception::fit_observation_model(f.set, f.task, all, perception::session_fit_options());
  return f;
}

TEST(DatasetProblem, ObjectsAreClassesSortingIsByBinAndTheTableIsTheModels) {
  const Fitted f = fitted();
  EXPECT_EQ(default_uses(f.set), (std::vector<int>{1, 2}));
  const pomdp::ObjectProblemData p = dataset_problem(f.task, f.model, {}, default_uses(f.set));
  EXPECT_EQ(p.objects, f.set.objects);
  EXPECT_EQ(p.prior, std::vector<double>(6, 1.0 / 6));
  ASSERT_EQ(p.sensing.size(), 2u);
  EXPECT_EQ(p.sensing[0].name, "press");
  EXPECT_EQ(p.sensing[1].name, "strike");
  EXPECT_EQ(p.sensing[1].uses, 2);
  EXPECT_EQ(p.sensing[0].reward, -1.0);
  EXPECT_EQ(p.sorting, (std::vector<std::string>{"group0", "group1"}));
  // obj0-2 are group0: sorting into group0 earns 10 for them and -100 for obj3-5.
  EXPECT_EQ(p.sorting_reward[0], (std::vector<double>{10, 10, 10, -100, -100, -100}));
  EXPECT_EQ(p.sorting_reward[1], (std::vector<double>{-100, -100, -100, 10, 10, 10}));
  EXPECT_EQ(p.observation_symbols, f.set.objects);
  ASSERT_EQ(p.observation_table.size(), 2u);
  EXPECT_EQ(p.observation_table[0], f.model.observation_table("press"));
  EXPECT_EQ(p.observation_table[1], f.model.observation_table("strike"));
  EXPECT_EQ(p.discount, 0.99);
  // A model of it plans with the limits.
  const pomdp::ObjectIdentificationModel model(p);
  EXPECT_EQ(model.max_uses(1), 2);
}

TEST(DatasetProblem, RewardsAndUsesAreTheCallers) {
  const Fitted f = fitted();
  const auto p = dataset_problem(f.task, f.model, {1.0, -5.0, -0.5, {}}, {0, 3});
  EXPECT_EQ(p.sensing[0].uses, 0);
  EXPECT_EQ(p.sensing[1].uses, 3);
  EXPECT_EQ(p.sensing[1].reward, -0.5);
  EXPECT_EQ(p.sorting_reward[1][5], 1.0);
  EXPECT_EQ(p.sorting_reward[1][0], -5.0);
  EXPECT_THROW(dataset_problem(f.task, f.model, {}, {1}), InputError);
  EXPECT_THROW(dataset_problem(f.task, f.model, {}, {1, -1}), InputError);
}

TEST(DatasetProblem, RequiresSetsPrerequisitesByTheDatasBehaviourNames) {
  const Fitted f = fitted();  // behaviours: press, strike
  TaskSpec spec;
  spec.prerequisites = {{"strike", {"press"}}};
  const auto p = dataset_problem(f.task, f.model, spec, {1, 2});
  EXPECT_EQ(p.sensing[0].prerequisites, std::vector<int>{});   // press: open at once
  EXPECT_EQ(p.sensing[1].prerequisites, std::vector<int>{0});  // strike: after a press
  const auto problem_error = [&](const TaskSpec& s) {
    try {
      dataset_problem(f.task, f.model, s, {1, 2});
    } catch (const InputError& e) {
      return e.problem();
    }
    return std::string("no InputError");
  };
  spec.prerequisites = {{"strike", {"shake"}}};
  EXPECT_EQ(problem_error(spec),
            "requires: 'shake' is not a behaviour of the data (it has: press, strike)");
  spec.prerequisites = {{"shake", {"press"}}};
  EXPECT_EQ(problem_error(spec),
            "requires: 'shake' is not a behaviour of the data (it has: press, strike)");
  spec.prerequisites = {{"strike", {"press"}}, {"press", {"strike"}}};
  EXPECT_EQ(problem_error(spec),
            "requires goes round in a circle (press -> strike -> press): none of them could "
            "ever be performed");
  spec.prerequisites = {{"press", {"press"}}};
  EXPECT_EQ(problem_error(spec), "requires: 'press' cannot require itself");
}

TEST(DatasetProblem, CostsPriceBehavioursOneByOneAndTheOthersStayAtSense) {
  const Fitted f = fitted();
  TaskSpec rewards;
  rewards.sense = -0.5;
  rewards.costs = {{"strike", 4.5}};
  const auto p = dataset_problem(f.task, f.model, rewards, {1, 2});
  EXPECT_EQ(p.sensing[0].reward, -0.5);  // press: unpriced
  EXPECT_EQ(p.sensing[1].reward, -4.5);  // strike
  rewards.costs = {{"strike", 0.0}};
  EXPECT_EQ(dataset_problem(f.task, f.model, rewards, {1, 2}).sensing[1].reward, 0.0);
  // A price for a behaviour the data does not have is a mistake, said with the behaviours it has.
  rewards.costs = {{"shake", 1.0}};
  try {
    dataset_problem(f.task, f.model, rewards, {1, 2});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(), "costs: 'shake' is not a behaviour of the data (it has: press, strike)");
  }
  rewards.costs = {{"press", -1.0}};
  EXPECT_THROW(dataset_problem(f.task, f.model, rewards, {1, 2}), InputError);
}

TEST(DatasetProblem, LookalikeCopiesSoundLikeTheirClassAndAreAnyOther) {
  Fitted f = fitted();
  const double rho = 0.1;
  const pomdp::ObjectProblemData p = dataset_problem(f.task, f.model, {}, default_uses(f.set),
                                                     perception::ObservationKind::labels, rho);
  ASSERT_EQ(p.objects.size(), 12u);  // 6 classes, then their lookalikes
  EXPECT_EQ(p.objects[0], "obj0");
  EXPECT_EQ(p.objects[6], "obj0~lookalike");
  EXPECT_EQ(p.objects[11], "obj5~lookalike");
  // Groups of 3: a lookalike of obj0 is one of the 5 others, 2 in obj0's bin and 3 in the other.
  const int bin0 = f.task.bin_of_class[0];
  for (std::size_t j = 0; j < p.sorting.size(); ++j) {
    const int in_bin = static_cast<int>(j) == bin0 ? 2 : 3;
    EXPECT_DOUBLE_EQ(p.sorting_reward[j][6], (in_bin * 10.0 + (5 - in_bin) * -100.0) / 5);
  }
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_DOUBLE_EQ(p.prior[k], (1 - rho) / 6);
    EXPECT_DOUBLE_EQ(p.prior[k + 6], rho / 6);
    for (std::size_t a = 0; a < p.sensing.size(); ++a)
      EXPECT_EQ(p.observation_table[a][k + 6], p.observation_table[a][k]);
  }
  // Without: the classes alone; a share of 0 names the copies and plans as without them.
  EXPECT_EQ(dataset_problem(f.task, f.model, {}, default_uses(f.set)).objects.size(), 6u);
  const pomdp::ObjectProblemData none = dataset_problem(f.task, f.model, {}, default_uses(f.set),
                                                        perception::ObservationKind::labels, 0.0);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_DOUBLE_EQ(none.prior[k], 1.0 / 6);
    EXPECT_EQ(none.prior[k + 6], 0.0);
  }
  // The shape names the copies too, for a campaign's report.
  EXPECT_EQ(dataset_problem_shape(f.task, f.set, {}, true).objects, p.objects);
}

}  // namespace
}  // namespace echoplan::loop
