// gnuplot: found on PATH (or a clear error naming the package), a script run in its work folder
// writes what it says, a broken one returns gnuplot's error; temporary folders go away whole.
#include "experiment/gnuplot.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/error.h"

namespace echoplan::experiment {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool have_gnuplot() {
  try {
    find_gnuplot();
    return true;
  } catch (const InputError&) {
    return false;
  }
}

TEST(TemporaryFolder, RemovedWithItsContents) {
  fs::path kept;
  {
    const TemporaryFolder a("echoplan-gnuplot-test");
    const TemporaryFolder b("echoplan-gnuplot-test");
    EXPECT_NE(a.path(), b.path());
    EXPECT_TRUE(fs::is_directory(a.path()));
    EXPECT_EQ(a.path().filename().string().rfind("echoplan-gnuplot-test-", 0), 0u);
    fs::create_directories(a.path() / "sub");
    std::ofstream(a.path() / "sub" / "file.txt") << "x";
    kept = a.path();
  }
  EXPECT_FALSE(fs::exists(kept));
}

TEST(Gnuplot, MissingFromPathNamesThePackage) {
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  const TemporaryFolder empty("echoplan-gnuplot-test");
  setenv("PATH", empty.path().c_str(), 1);
  try {
    find_gnuplot();
    ADD_FAILURE() << "found gnuplot in an empty folder";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("gnuplot-nox"), std::string::npos) << e.problem();
  }
  setenv("PATH", saved.c_str(), 1);
}

TEST(Gnuplot, RunsTheScriptInTheWorkFolder) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  EXPECT_EQ(find_gnuplot().filename(), "gnuplot");
  const TemporaryFolder work("echoplan-gnuplot-test");
  std::ofstream(work.path() / "in.dat") << "1 2\n3 4\n";
  std::string error;
  // The data file is found by its relative name: the script runs in the work folder.
  ASSERT_TRUE(run_gnuplot(
      "set print 'out.txt'\nstats 'in.dat' using 1:2 nooutput\nprint STATS_sum_x + STATS_sum_y\n",
      work.path(), error))
      << error;
  EXPECT_EQ(read(work.path() / "out.txt"), "10.0\n");
  EXPECT_EQ(read(work.path() / "plot.gp").rfind("set print", 0), 0u);  // the script is kept there
}

TEST(Gnuplot, FailureReturnsItsError) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const TemporaryFolder work("echoplan-gnuplot-test");
  std::string error;
  EXPECT_FALSE(run_gnuplot("plot 'no-such-file.dat'\n", work.path(), error));
  EXPECT_NE(error.find("no-such-file.dat"), std::string::npos) << error;
}

}  // namespace
}  // namespace echoplan::experiment
