// load_problem() picks the reader by the file's extension and names the file when it cannot read
// it.
#include <gtest/gtest.h>

#include "common/error.h"
#include "pomdp/problem.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;

TEST(LoadProblem, PomdpFilesAreCassandraFormatWithAnExactBelief) {
  const Problem p = load_problem(repo_file("problems/tiger.pomdp"));
  EXPECT_NE(p.model->tabular(), nullptr);
  EXPECT_EQ(p.belief.type, BeliefSettings::Type::exact);
  EXPECT_EQ(p.source_path, repo_file("problems/tiger.pomdp"));
  EXPECT_EQ(p.model->spec().action_names,
            (std::vector<std::string>{"listen", "open-left", "open-right"}));
}

TEST(LoadProblem, OtherFilesAreYamlProblems) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  EXPECT_NE(p.model->object_identification(), nullptr);
  EXPECT_EQ(p.belief.type, BeliefSettings::Type::particle);
  EXPECT_EQ(p.source_path, repo_file("problems/audio_objects.yaml"));
}

TEST(LoadProblem, MissingFileOrDirectoryIsAnError) {
  try {
    load_problem("/nonexistent/problem.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/problem.yaml");
    EXPECT_NE(e.problem().find("cannot open the problem file"), std::string::npos) << e.what();
  }
  try {
    load_problem(repo_file("problems"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("not a regular file"), std::string::npos);
  }
}

}  // namespace
}  // namespace echoplan::pomdp
