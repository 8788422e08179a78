// A fresh folder for the test that is running, removed when it ends. Named after the fixture and
// the test: ctest runs the tests of one binary in parallel processes, so a folder shared between
// tests would be written by two at once.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace echoplan {

class TestFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::path(::testing::TempDir()) /
           ("echoplan_" + std::string(test->test_suite_name()) + "_" + test->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;  // exists and is empty when the test begins
};

}  // namespace echoplan
