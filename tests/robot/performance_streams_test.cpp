#include "robot/performance_streams.h"

#include <gtest/gtest.h>

#include <thread>

#include "common/error.h"

namespace echoplan::robot {
namespace {

using namespace std::chrono_literals;

// Two streams as a robot with joint efforts and a wrist force-torque sensor has them.
constexpr std::size_t kEffort = 0, kForce = 1;
const std::vector<std::string> kJoints{"j1", "j2"};
const std::vector<std::string> kForceAxes{"force_x", "force_y", "force_z"};

PerformanceStreams streams() {
  return PerformanceStreams({"/joint_states", "/wrist/wrench"}, "/echoplan/performance");
}

// The problem take() states, checking that it names `source`.
std::string error_of(PerformanceStreams& s, const std::string& action, const std::string& source,
                     std::vector<std::size_t> wanted = {kEffort},
                     std::chrono::milliseconds timeout = 50ms) {
  try {
    s.take(action, wanted, timeout);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), source);
    return e.problem();
  }
  ADD_FAILURE() << "take('" << action << "') did not throw";
  return "";
}

TEST(PerformanceStreams, CutsEachStreamBetweenTheMarkersWithTimesFromTheStart) {
  PerformanceStreams s = streams();
  s.add(kEffort, 9.5, kJoints, {9.0, 9.0});  // before the performance: not in it
  EXPECT_EQ(s.begin("press", 10.0), "");
  s.add(kEffort, 10.01, kJoints, {1.0, 2.0});
  s.add(kForce, 10.015, kForceAxes, {0.0, 0.0, -4.0});
  s.add(kEffort, 10.02, kJoints, {1.5, 2.5});
  s.add(kForce, 10.025, kForceAxes, {0.0, 0.0, -5.0});
  s.add(kEffort, 10.03, kJoints, {2.0, 3.0});
  EXPECT_EQ(s.end(10.04), "");
  s.add(kEffort, 10.05, kJoints, {7.0, 7.0});  // after it: not in it

  const std::vector<signal::Series> got = s.take("press", {kForce, kEffort}, 1s);
  ASSERT_EQ(got.size(), 2u);  // in the order asked for
  EXPECT_EQ(got[0].channels, kForceAxes);
  EXPECT_EQ(got[0].values[2], (std::vector<double>{-4.0, -5.0}));
  const signal::Series& effort = got[1];
  EXPECT_EQ(effort.channels, kJoints);
  ASSERT_EQ(effort.samples(), 3u);
  EXPECT_NEAR(effort.t[0], 0.01, 1e-9);
  EXPECT_NEAR(effort.t[2], 0.03, 1e-9);
  EXPECT_EQ(effort.values[0], (std::vector<double>{1.0, 1.5, 2.0}));
  EXPECT_EQ(effort.values[1], (std::vector<double>{2.0, 2.5, 3.0}));
  EXPECT_NO_THROW(signal::check_series(effort, "effort"));
}

TEST(PerformanceStreams, WaitsForTheEndMarkerOfThePerformanceUnderWay) {
  PerformanceStreams s = streams();
  s.begin("lift", 1.0);
  s.add(kEffort, 1.1, kJoints, {1.0, 1.0});
  s.add(kEffort, 1.2, kJoints, {2.0, 2.0});
  std::thread planner([&] {
    std::this_thread::sleep_for(100ms);
    s.end(1.3);
  });
  const auto start = std::chrono::steady_clock::now();
  const auto got = s.take("lift", {kEffort}, 5s);
  planner.join();
  EXPECT_EQ(got.at(0).samples(), 2u);
  EXPECT_GE(std::chrono::steady_clock::now() - start, 90ms);
}

TEST(PerformanceStreams, EachPerformanceIsTakenOnceAndTheNextRequestWaitsForANewOne) {
  PerformanceStreams s = streams();
  s.begin("press", 0.0);
  s.add(kEffort, 0.1, kJoints, {1.0, 1.0});
  s.add(kEffort, 0.2, kJoints, {1.0, 1.0});
  s.end(0.3);
  s.take("press", {kEffort}, 1s);
  EXPECT_EQ(error_of(s, "press", "/echoplan/performance"),
            "no performance of 'press' ended within 0.05 s (the planner marks each sensing action "
            "with 'start OBJECT ACTION SESSION' and 'end')");
}

TEST(PerformanceStreams, APerformanceWithoutItsEndOrOfAnotherActionIsNotHeard) {
  PerformanceStreams s = streams();
  s.begin("press", 0.0);
  EXPECT_EQ(error_of(s, "press", "/echoplan/performance"),
            "'press' began but no end marker came within 0.05 s");
  s.end(0.5);
  EXPECT_EQ(error_of(s, "tap", "/echoplan/performance"),
            "the performance that ended last was of 'press', not 'tap'");
}

TEST(PerformanceStreams, MarkersOutOfOrderAreReportedAndTheNewestStartWins) {
  PerformanceStreams s = streams();
  EXPECT_EQ(s.end(0.1), "an end with no start");
  s.begin("press", 1.0);
  s.add(kEffort, 1.1, kJoints, {5.0, 5.0});
  EXPECT_EQ(s.begin("tap", 2.0),
            "a start of 'tap' while 'press' was under way (since 1.000 s): that performance had "
            "no end and is dropped");
  s.add(kEffort, 2.1, kJoints, {1.0, 1.0});
  s.add(kEffort, 2.2, kJoints, {2.0, 2.0});
  s.end(2.3);
  const auto got = s.take("tap", {kEffort}, 1s);
  EXPECT_EQ(got.at(0).values[0], (std::vector<double>{1.0, 2.0}));  // nothing of the press
}

TEST(PerformanceStreams, AStreamThatStoppedSaysWhenItLastSpoke) {
  PerformanceStreams s = streams();
  s.add(kEffort, 4.0, kJoints, {1.0, 1.0});
  s.begin("press", 7.5);
  s.add(kForce, 7.6, kForceAxes, {0, 0, 1});
  s.add(kForce, 7.7, kForceAxes, {0, 0, 1});
  s.end(8.0);
  s.add(kEffort, 8.2, kJoints, {1.0, 1.0});  // it speaks again after the end, before the request
  EXPECT_EQ(error_of(s, "press", "/joint_states", {kForce, kEffort}),
            "no message during 'press' (0.500 s): the stream stopped (its last message came 3.500 "
            "s before the performance began)");
}

TEST(PerformanceStreams, AStreamThatNeverSpokeAndOneWithASingleMessageAreNamed) {
  PerformanceStreams s = streams();
  s.begin("press", 0.0);
  s.add(kEffort, 0.1, kJoints, {1.0, 1.0});
  s.end(0.25);
  EXPECT_EQ(error_of(s, "press", "/wrist/wrench", {kForce}),
            "no message during 'press' (0.250 s): the stream stopped (nothing has come on it since "
            "the node subscribed)");
  s.begin("press", 1.0);
  s.add(kEffort, 1.1, kJoints, {1.0, 1.0});
  s.end(1.25);
  EXPECT_EQ(error_of(s, "press", "/joint_states", {kEffort}),
            "one message during 'press' (0.250 s), fewer than the 2 a series needs: the stream is "
            "slower than the performance");
}

TEST(PerformanceStreams, AMessageThatCouldNotBeReadSpoilsOnlyItsStreamInItsPerformance) {
  PerformanceStreams s = streams();
  s.bad_message(kEffort, 0.5, "message 3: no joint 'j2'");  // outside: nothing to spoil
  s.begin("press", 1.0);
  for (double t : {1.1, 1.2}) {
    s.add(kEffort, t, kJoints, {1.0, 1.0});
    s.add(kForce, t, kForceAxes, {0, 0, 1});
  }
  s.bad_message(kEffort, 1.25, "message 7: no joint 'j2' (the topic's first message had j1, j2)");
  s.end(1.3);
  EXPECT_EQ(error_of(s, "press", "/joint_states", {kForce, kEffort}),
            "a message 0.250 s into 'press': message 7: no joint 'j2' (the topic's first message "
            "had j1, j2)");
  s.begin("press", 2.0);
  for (double t : {2.1, 2.2}) s.add(kEffort, t, kJoints, {1.0, 1.0});
  s.end(2.3);
  EXPECT_EQ(s.take("press", {kEffort}, 1s).at(0).samples(), 2u);
}

}  // namespace
}  // namespace echoplan::robot
