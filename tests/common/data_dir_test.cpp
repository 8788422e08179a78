#include "common/data_dir.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/error.h"
#include "test_folder.h"

namespace echoplan {
namespace {

namespace fs = std::filesystem;

// Sets ECHOPLAN_DATA_DIR for one test and restores it after; the test's data folder is `dir_`.
class DataDirTest : public TestFolder {
 protected:
  void SetUp() override {
    if (const char* old = std::getenv("ECHOPLAN_DATA_DIR")) saved_ = old;
    TestFolder::SetUp();
  }
  void TearDown() override {
    if (saved_.empty()) {
      unsetenv("ECHOPLAN_DATA_DIR");
    } else {
      setenv("ECHOPLAN_DATA_DIR", saved_.c_str(), 1);
    }
    TestFolder::TearDown();
  }

  std::string saved_;
};

TEST_F(DataDirTest, EnvironmentVariableNamesTheDataFolder) {
  fs::create_directories(dir_ / "problems");
  fs::create_directories(dir_ / "objects");
  std::ofstream(dir_ / "objects" / "catalogue.yaml") << "materials: {}\n";
  setenv("ECHOPLAN_DATA_DIR", dir_.c_str(), 1);
  EXPECT_EQ(shipped_data_dir(), dir_);
  EXPECT_EQ(shipped_file("objects/catalogue.yaml"), (dir_ / "objects" / "catalogue.yaml").string());
  try {
    shipped_file("objects/missing.yaml");
    FAIL() << "a missing shipped file must be an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir_ / "objects" / "missing.yaml").string());
  }
}

TEST_F(DataDirTest, AFolderWithoutTheDataIsRefused) {
  fs::create_directories(dir_ / "problems");  // no objects/
  setenv("ECHOPLAN_DATA_DIR", dir_.c_str(), 1);
  try {
    shipped_data_dir();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("without problems/ and objects/"), std::string::npos) << e.what();
  }
}

TEST_F(DataDirTest, WithoutDataNextToTheExecutableTheErrorSaysWhereItLooked) {
  // The test binary lives in build/tests/common/: neither ../share/echoplan nor share/echoplan.
  unsetenv("ECHOPLAN_DATA_DIR");
  try {
    shipped_data_dir();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string exe_dir = fs::canonical("/proc/self/exe").parent_path().string();
    EXPECT_NE(e.problem().find("looked in: " + fs::path(exe_dir).parent_path().string()),
              std::string::npos)
        << e.what();
    EXPECT_NE(e.problem().find("ECHOPLAN_DATA_DIR"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace echoplan
