// The shipped lab problem (problems/audio_objects_lab.yaml) against its source: every cell of its
// observation table is the Dirichlet(0.5) posterior mean (count + 0.5) / (row total + 2) of the
// original robot's counts (original-robot-runs.md, "What the lab's classifier heard", written here
// independently of the file), everything else is the report's problem, and the exact solver
// brackets the reference's V*(b0) = 6.37 under it.
#include <gtest/gtest.h>

#include <array>

#include "../common/source_dir.h"
#include "pomdp/object_identification_model.h"
#include "pomdp/problem.h"
#include "solvers/identification_solver.h"

namespace echoplan::solvers {
namespace {

std::string repo_file(const std::string& relative) {
  return echoplan::testing::source_dir() + "/" + relative;
}

pomdp::ObjectProblemData shipped(const std::string& file) {
  const pomdp::Problem p = pomdp::load_problem(repo_file(file));
  return p.model->object_identification()->data();
}

// The lab's counts: [action][object][heard], actions slide, strike; objects and heard classes
// pringles_can, coffee_mug, plastic_cup, paper_base. 81 sensing actions in all.
using Counts = std::array<std::array<std::array<int, 4>, 4>, 2>;
constexpr Counts kLabCounts = {{
    {{{5, 1, 0, 0}, {0, 6, 0, 0}, {0, 1, 7, 0}, {1, 6, 3, 5}}},    // slide
    {{{7, 1, 2, 0}, {0, 9, 0, 0}, {0, 0, 14, 0}, {0, 0, 0, 13}}},  // strike
}};

TEST(LabProblem, TableIsTheCountsPosteriorMeanUnderDirichletHalf) {
  const pomdp::ObjectProblemData lab = shipped("problems/audio_objects_lab.yaml");
  ASSERT_EQ(lab.sensing.size(), 2u);
  EXPECT_EQ(lab.sensing[0].name, "slide");
  EXPECT_EQ(lab.sensing[1].name, "strike");
  ASSERT_EQ(lab.objects,
            (std::vector<std::string>{"pringles_can", "coffee_mug", "plastic_cup", "paper_base"}));
  EXPECT_EQ(lab.observation_symbols, lab.objects);
  int total = 0;
  for (std::size_t a = 0; a < 2; ++a) {
    for (std::size_t k = 0; k < 4; ++k) {
      const auto& counts = kLabCounts[a][k];
      const int n = counts[0] + counts[1] + counts[2] + counts[3];
      total += n;
      for (std::size_t o = 0; o < 4; ++o) {
        // The file prints 12 significant digits.
        EXPECT_NEAR(lab.observation_table[a][k][o], (counts[o] + 0.5) / (n + 2.0), 1e-12)
            << lab.sensing[a].name << ", " << lab.objects[k] << ", heard " << lab.objects[o];
      }
    }
  }
  EXPECT_EQ(total, 81);
}

TEST(LabProblem, EverythingButTheTableIsTheReportsProblem) {
  const pomdp::ObjectProblemData lab = shipped("problems/audio_objects_lab.yaml");
  const pomdp::ObjectProblemData report = shipped("problems/audio_objects.yaml");
  EXPECT_EQ(lab.discount, report.discount);
  EXPECT_EQ(lab.objects, report.objects);
  EXPECT_EQ(lab.prior, report.prior);
  EXPECT_EQ(lab.initial_joints, report.initial_joints);
  EXPECT_EQ(lab.initial_offset, report.initial_offset);
  ASSERT_EQ(lab.sensing.size(), report.sensing.size());
  for (std::size_t a = 0; a < lab.sensing.size(); ++a) {
    EXPECT_EQ(lab.sensing[a].name, report.sensing[a].name);
    EXPECT_EQ(lab.sensing[a].reward, report.sensing[a].reward);
    EXPECT_EQ(lab.sensing[a].offset_change, report.sensing[a].offset_change);
    EXPECT_EQ(lab.sensing[a].collision_probability, report.sensing[a].collision_probability);
  }
  EXPECT_EQ(lab.sorting, report.sorting);
  EXPECT_EQ(lab.observation_symbols, report.observation_symbols);
  EXPECT_EQ(lab.sorting_reward, report.sorting_reward);
  EXPECT_EQ(lab.collision_reward, report.collision_reward);
  EXPECT_NE(lab.observation_table, report.observation_table);
}

TEST(LabProblem, ExactSolverBracketsTheReferenceValue) {
  // original-robot-runs.md: under the table these counts measure (Dirichlet 0.5 per cell),
  // V*(b0) = 6.37. Bounds after a fixed number of expansions hold wherever the search stops.
  const pomdp::ObjectIdentificationModel model(shipped("problems/audio_objects_lab.yaml"));
  IdentificationSolver solver(*model.tabular());
  RefineLimits limits;
  limits.target_gap = 1e-4;
  limits.expansions = 20000;
  solver.refine(solver.root(), limits);
  const Bounds v = solver.value(solver.root());
  EXPECT_LE(v.lower, 6.375);
  EXPECT_GE(v.upper, 6.365);
  EXPECT_LT(v.gap(), 0.01);  // tight enough that the bracket says something about 6.37
}

}  // namespace
}  // namespace echoplan::solvers
