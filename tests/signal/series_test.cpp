// Tests of the series file: what it reads back, and every malformed file's error with its line.
#include "signal/series.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"

namespace echoplan::signal {
namespace {

using ::testing::HasSubstr;

void expect_error(const std::string& text, const std::string& where, const std::string& what) {
  try {
    parse_series_csv(text, "s.csv");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr(where)) << e.what();
    EXPECT_THAT(std::string(e.what()), HasSubstr(what)) << e.what();
  }
}

TEST(SeriesFile, ReadsChannelsAndTimes) {
  const Series s = parse_series_csv("t,j1,j2\n0,1.5,-2\n0.01,2.5,-3\r\n\n0.02,3.5,-4\n", "s.csv");
  EXPECT_EQ(s.channels, (std::vector<std::string>{"j1", "j2"}));
  EXPECT_EQ(s.t, (std::vector<double>{0, 0.01, 0.02}));
  EXPECT_EQ(s.values[0], (std::vector<double>{1.5, 2.5, 3.5}));
  EXPECT_EQ(s.values[1], (std::vector<double>{-2, -3, -4}));
  EXPECT_DOUBLE_EQ(s.duration(), 0.02);
  EXPECT_EQ(s.channel_index("j2"), 1);
  EXPECT_EQ(s.channel_index("j3"), -1);
}

TEST(SeriesFile, WritesWhatItReadsBackExactly) {
  Series s;
  s.channels = {"force_x", "force_y"};
  s.t = {0.0, 1.0 / 3.0, 0.7};
  s.values = {{0.1, 1e-300, -7.25}, {2.0 / 3.0, 123456789.125, 0.0}};
  const Series back = parse_series_csv(series_csv(s), "s.csv");
  EXPECT_EQ(back.channels, s.channels);
  EXPECT_EQ(back.t, s.t);
  EXPECT_EQ(back.values, s.values);
}

TEST(SeriesFile, BadFilesNameTheLine) {
  expect_error("", "s.csv:1", "no header");
  expect_error("time,j1\n0,1\n", "s.csv:1", "t followed by");
  expect_error("t\n0\n", "s.csv:1", "at least one channel");
  expect_error("t,j1,j1\n0,1,2\n", "s.csv:1", "'j1' appears twice");
  expect_error("t,j1,\n0,1,2\n", "s.csv:1", "empty");
  expect_error("t,j1\n0,1\n0.1\n", "s.csv:3", "ragged");
  expect_error("t,j1\n0,1\n0.1,x\n", "s.csv:3", "'j1' is 'x', not a number");
  expect_error("t,j1\n0,nan\n", "s.csv:2", "finite");
  expect_error("t,j1\n0,inf\n", "s.csv:2", "finite");
  expect_error("t,j1\n0, 1\n", "s.csv:2", "not a number");
  expect_error("t,j1\n0.2,1\n0.1,1\n", "s.csv:3", "earlier than the row before");
  expect_error("t,j1\n", "s.csv:2", "no samples");
  try {
    read_series_csv("/nonexistent/x.effort.csv");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("/nonexistent/x.effort.csv"));
  }
}

TEST(SeriesFile, CheckSeriesRefusesBrokenInvariants) {
  Series s;
  s.channels = {"a"};
  s.t = {0, 1};
  s.values = {{1, 2}};
  EXPECT_NO_THROW(check_series(s, "x"));
  s.values = {{1}};
  EXPECT_THROW(check_series(s, "x"), InputError);
  s.values = {{1, 2}};
  s.t = {1, 0};
  EXPECT_THROW(check_series(s, "x"), InputError);
  s.t = {0, 1};
  s.channels = {""};
  EXPECT_THROW(check_series(s, "x"), InputError);
}

}  // namespace
}  // namespace echoplan::signal
