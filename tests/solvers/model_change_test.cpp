// observation_table_change() on the report's shipped problem with edited observation rows (it must
// find exactly the edited (action, object) rows), its refusal of every other kind of difference,
// and ModelChange::affects() on the states a step can reach.
#include "solvers/model_change.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "../common/source_dir.h"
#include "common/error.h"
#include "pomdp/object_identification_model.h"
#include "pomdp/problem.h"

namespace echoplan::solvers {
namespace {

using pomdp::ObjectIdentificationModel;
using pomdp::ObjectProblemData;

// problems/audio_objects.yaml: sensing actions slide, strike; objects pringles_can, coffee_mug,
// plastic_cup, paper_base.
constexpr int kSlide = 0;
constexpr int kStrike = 1;
constexpr int kPringles = 0;
constexpr int kMug = 1;
constexpr int kPaper = 3;

std::shared_ptr<const ObjectIdentificationModel> report_model() {
  const pomdp::Problem p =
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
  const ObjectIdentificationModel* objects = p.model->object_identification();
  if (!objects)
    throw std::logic_error("audio_objects.yaml is not an object-identification problem");
  // The same model, shared with the problem's pointer (aliasing constructor).
  return std::shared_ptr<const ObjectIdentificationModel>(p.model, objects);
}

std::shared_ptr<const ObjectIdentificationModel> model_of(ObjectProblemData data) {
  return std::make_shared<const ObjectIdentificationModel>(std::move(data));
}

// The message of the InputError observation_table_change throws, or "" when it does not throw.
std::string refusal(const ObjectIdentificationModel& before, ObjectProblemData after) {
  try {
    observation_table_change(before, model_of(std::move(after)));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

pomdp::State state_with_object(const ObjectIdentificationModel& model, int object) {
  pomdp::State s = model.tabular_state(object);
  EXPECT_EQ(s.discrete.at(0), object);
  return s;
}

TEST(ObservationTableChange, IdenticalModelsChangeNoRow) {
  const auto before = report_model();
  const auto after = model_of(before->data());
  const ModelChange change = observation_table_change(*before, after);
  EXPECT_TRUE(change.rows.empty());
  EXPECT_EQ(change.model, after);
}

TEST(ObservationTableChange, FindsExactlyTheEditedRowsInTableOrder) {
  const auto before = report_model();
  ObjectProblemData data = before->data();
  // The paper base slid: 0.48 on plastic_cup and 0.5 on itself in the file; swap them.
  data.observation_table[kSlide][kPaper] = {0.01, 0.01, 0.5, 0.48};
  // The struck mug: 0.6 on itself in the file; the pringles row stays as written.
  data.observation_table[kStrike][kMug] = {0.05, 0.7, 0.2, 0.05};
  const ModelChange change = observation_table_change(*before, model_of(std::move(data)));
  EXPECT_EQ(change.rows, (std::vector<ObservationRow>{{kSlide, kPaper}, {kStrike, kMug}}));
}

TEST(ObservationTableChange, AnyDifferenceInARowCounts) {
  // "the rows whose probabilities differ at all": a shift far below the loader's 1e-6 sum check.
  const auto before = report_model();
  ObjectProblemData data = before->data();
  data.observation_table[kStrike][kPringles][0] += 1e-12;
  data.observation_table[kStrike][kPringles][2] -= 1e-12;
  const ModelChange change = observation_table_change(*before, model_of(std::move(data)));
  EXPECT_EQ(change.rows, (std::vector<ObservationRow>{{kStrike, kPringles}}));
}

TEST(ObservationTableChange, RefusesEveryOtherDifferenceNamingIt) {
  const auto before = report_model();
  const ObjectProblemData report = before->data();
  struct Case {
    const char* what;  // the phrase the message must contain
    ObjectProblemData data;
  };
  std::vector<Case> cases;
  auto edited = [&](const char* what, auto edit) {
    ObjectProblemData d = report;
    edit(d);
    cases.push_back({what, std::move(d)});
  };
  edited("its objects", [](ObjectProblemData& d) { d.objects[kMug] = "teacup"; });
  edited("its prior", [](ObjectProblemData& d) { d.prior = {0.4, 0.2, 0.2, 0.2}; });
  edited("its discount", [](ObjectProblemData& d) { d.discount = 0.95; });
  edited("its initial configuration", [](ObjectProblemData& d) { d.initial_joints[3] += 0.1; });
  edited("its initial configuration", [](ObjectProblemData& d) { d.initial_offset[0] = 0.2; });
  edited("sensing action 'slide'", [](ObjectProblemData& d) { d.sensing[kSlide].reward = -2; });
  edited("sensing action 'strike'",
         [](ObjectProblemData& d) { d.sensing[kStrike].offset_change[2] = 0.01; });
  edited("sensing action 'strike'",
         [](ObjectProblemData& d) { d.sensing[kStrike].collision_probability = 0.1; });
  edited("its sorting actions or rewards", [](ObjectProblemData& d) { d.sorting[1] = "bin_B"; });
  edited("its sorting actions or rewards",
         [](ObjectProblemData& d) { d.sorting_reward[0][kPringles] = 5; });
  edited("its sorting actions or rewards", [](ObjectProblemData& d) { d.collision_reward = -50; });
  edited("its observation symbols",
         [](ObjectProblemData& d) { d.observation_symbols[kPaper] = "cardboard"; });
  for (Case& c : cases) {
    const std::string message = refusal(*before, std::move(c.data));
    EXPECT_NE(message.find(c.what), std::string::npos) << c.what << ": got '" << message << "'";
  }
}

TEST(ObservationTableChange, RefusesARenamedSensingActionEvenWithTheSameTable) {
  const auto before = report_model();
  ObjectProblemData data = before->data();
  data.sensing[kSlide].name = "push";
  EXPECT_THROW(observation_table_change(*before, model_of(std::move(data))), InputError);
}

TEST(ObservationTableChange, RejectsAMissingNewModel) {
  const auto before = report_model();
  EXPECT_THROW(observation_table_change(*before, nullptr), std::invalid_argument);
}

TEST(ModelChangeAffects, OnlyStepsOfAChangedActionThatReachAChangedObject) {
  const auto model = report_model();
  ModelChange change;
  change.model = model;
  change.rows = {{kStrike, kMug}, {kSlide, kPaper}};
  EXPECT_TRUE(change.affects(state_with_object(*model, kMug), kStrike));
  EXPECT_TRUE(change.affects(state_with_object(*model, kPaper), kSlide));
  // The same objects under the other action drew from unchanged rows.
  EXPECT_FALSE(change.affects(state_with_object(*model, kMug), kSlide));
  EXPECT_FALSE(change.affects(state_with_object(*model, kPaper), kStrike));
  EXPECT_FALSE(change.affects(state_with_object(*model, kPringles), kStrike));
  // Sorting actions (indices after the sensing ones) have no row in the table.
  EXPECT_FALSE(change.affects(state_with_object(*model, kMug), model->num_sensing()));
}

TEST(ModelChangeAffects, ARowForEveryObjectCoversEveryNextState) {
  const auto model = report_model();
  ModelChange change;
  change.model = model;
  change.rows = {{kSlide, -1}};
  for (int k = 0; k < 4; ++k) {
    EXPECT_TRUE(change.affects(state_with_object(*model, k), kSlide)) << k;
    EXPECT_FALSE(change.affects(state_with_object(*model, k), kStrike)) << k;
  }
  // A state without an object variable is still "every next state"; an object row is not.
  EXPECT_TRUE(change.affects(pomdp::State{}, kSlide));
  change.rows = {{kSlide, kPringles}};
  EXPECT_FALSE(change.affects(pomdp::State{}, kSlide));
}

TEST(ModelChangeAffects, NoRowsAffectNothing) {
  const auto model = report_model();
  const ModelChange change = observation_table_change(*model, model_of(model->data()));
  for (int a = 0; a < model->num_actions(); ++a)
    for (int k = 0; k < 4; ++k) EXPECT_FALSE(change.affects(state_with_object(*model, k), a));
}

TEST(ModelChangeAffects, AgreesWithTheRowsFoundForAnEditedTable) {
  // The two functions together: a step is affected exactly when its (action, object) row changed.
  const auto before = report_model();
  ObjectProblemData data = before->data();
  data.observation_table[kStrike][kPaper] = {0.05, 0.05, 0.2, 0.7};
  const ModelChange change = observation_table_change(*before, model_of(std::move(data)));
  for (int a = 0; a < before->num_sensing(); ++a)
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(change.affects(state_with_object(*before, k), a), a == kStrike && k == kPaper)
          << "action " << a << " object " << k;
}

}  // namespace
}  // namespace echoplan::solvers
