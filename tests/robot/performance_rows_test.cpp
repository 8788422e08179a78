#include "robot/performance_rows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "common/error.h"

namespace echoplan::robot {
namespace {

using namespace std::chrono_literals;

// press has two sensors, tap one; squeeze is heard from its clip alone (not listed).
PerformanceRows rows() {
  return PerformanceRows({{"press", {"haptic", "force"}}, {"tap", {"haptic"}}}, "/features");
}

std::string error_of(PerformanceRows& r, const std::string& action,
                     std::chrono::milliseconds timeout = 50ms) {
  try {
    r.take(action, timeout);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "/features");
    return e.problem();
  }
  ADD_FAILURE() << "take('" << action << "') did not throw";
  return "";
}

TEST(PerformanceRows, TakesTheActionsRowsInTheModelsModalityOrder) {
  PerformanceRows r = rows();
  EXPECT_EQ(r.add({"press", "force", {3.0}}), "");
  EXPECT_EQ(r.add({"press", "haptic", {1.0, 2.0}}), "");
  const auto taken = r.take("press", 1s);
  ASSERT_EQ(taken.rows.size(), 2u);
  EXPECT_EQ(taken.rows[0], (std::vector<double>{1.0, 2.0}));  // haptic first, as the model has it
  EXPECT_EQ(taken.rows[1], (std::vector<double>{3.0}));
  EXPECT_TRUE(taken.unused.empty());
}

TEST(PerformanceRows, WaitsForARowPublishedAfterTheRequest) {
  PerformanceRows r = rows();
  std::thread robot([&] {
    std::this_thread::sleep_for(100ms);
    r.add({"tap", "haptic", {0.5}});
  });
  const auto start = std::chrono::steady_clock::now();
  const auto taken = r.take("tap", 5s);
  robot.join();
  EXPECT_EQ(taken.rows.at(0), std::vector<double>{0.5});
  EXPECT_GE(std::chrono::steady_clock::now() - start, 90ms);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 4s);
}

TEST(PerformanceRows, NoRowInTimeNamesTheMissingSensorAndWhatDidArrive) {
  PerformanceRows r = rows();
  r.add({"press", "haptic", {1.0}});
  r.add({"tap", "haptic", {2.0}});
  r.add({"press", "force_sensor", {1.0}});  // misnamed: refused, and said so again below
  const std::string why = error_of(r, "press");
  EXPECT_NE(why.find("no 'force' row of 'press' arrived within 0.05 s"), std::string::npos) << why;
  EXPECT_NE(why.find("rows since the previous observation: press/haptic, tap/haptic"),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("ignored: a 'force_sensor' row of 'press'"), std::string::npos) << why;
  // The failed request closed the window: its rows are not taken for the next performance.
  EXPECT_NE(error_of(r, "tap").find("no row arrived since the previous observation"),
            std::string::npos);
}

TEST(PerformanceRows, TwoRowsOfOneSensorSinceTheLastObservationAreAnError) {
  PerformanceRows r = rows();
  r.add({"tap", "haptic", {1.0}});
  r.add({"tap", "haptic", {2.0}});
  EXPECT_NE(error_of(r, "tap").find("two 'haptic' rows of 'tap' arrived"), std::string::npos);
}

TEST(PerformanceRows, EachObservationStartsANewWindowAndDropsOtherBehavioursRows) {
  PerformanceRows r = rows();
  r.add({"press", "haptic", {1.0}});  // a press whose observation was never asked for
  r.add({"tap", "haptic", {2.0}});
  const auto taken = r.take("tap", 1s);
  EXPECT_EQ(taken.unused, std::vector<std::string>{"press/haptic"});
  r.add({"press", "force", {3.0}});
  // The stale press/haptic row went with the tap's window.
  EXPECT_NE(error_of(r, "press").find("no 'haptic' row of 'press'"), std::string::npos);
  // And a row of the next performance is taken by the next request.
  r.add({"tap", "haptic", {4.0}});
  EXPECT_EQ(r.take("tap", 1s).rows.at(0), std::vector<double>{4.0});
}

TEST(PerformanceRows, RowsNoRequestCanUseAreRefusedWithTheReason) {
  PerformanceRows r = rows();
  EXPECT_NE(r.add({"squeeze", "haptic", {1.0}}).find("the model reads no sensor rows of 'squeeze'"),
            std::string::npos);
  EXPECT_NE(r.add({"tap", "force", {1.0}}).find("the model's sensors for 'tap' are: haptic"),
            std::string::npos);
  EXPECT_NE(r.add({"tap", "haptic", {}}).find("with no values"), std::string::npos);
  EXPECT_NE(r.add({"tap", "haptic", {1.0, std::nan("")}}).find("value 2 is nan"),
            std::string::npos);
  EXPECT_NE(error_of(r, "tap").find("no 'haptic' row of 'tap'"), std::string::npos);
  // An action without sensor rows is not the topic's to serve.
  EXPECT_NE(error_of(r, "squeeze").find("'squeeze' has no sensor rows"), std::string::npos);
}

}  // namespace
}  // namespace echoplan::robot
