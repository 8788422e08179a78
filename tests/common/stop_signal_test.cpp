#include "common/stop_signal.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <cstdlib>
#include <stdexcept>

namespace echoplan {
namespace {

TEST(StopSignal, FirstSignalOnlySetsTheFlag) {
  const StopSignal stop;
  EXPECT_FALSE(stop.requested());
  ASSERT_EQ(::raise(SIGINT), 0);
  EXPECT_TRUE(stop.requested());
  EXPECT_TRUE(stop.flag().load());
}

TEST(StopSignal, SigtermStopsLikeCtrlC) {
  const StopSignal stop;
  ASSERT_EQ(::raise(SIGTERM), 0);
  EXPECT_TRUE(stop.requested());
}

TEST(StopSignal, EachScopeStartsUnstopped) {
  {
    const StopSignal first;
    ::raise(SIGINT);
    ASSERT_TRUE(first.requested());
  }
  const StopSignal second;
  EXPECT_FALSE(second.requested());
}

TEST(StopSignal, OnlyOneAtATime) {
  const StopSignal stop;
  EXPECT_THROW(StopSignal{}, std::logic_error);
}

TEST(StopSignal, LeavingTheScopeRestoresThePreviousHandler) {
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  struct sigaction before {};
  sigaction(SIGINT, &ignore, &before);
  { const StopSignal stop; }
  struct sigaction after {};
  sigaction(SIGINT, nullptr, &after);
  EXPECT_EQ(after.sa_handler, SIG_IGN);
  sigaction(SIGINT, &before, nullptr);
}

TEST(StopSignalDeathTest, SecondCtrlCEndsAtOnceWithStatus130) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        const StopSignal stop;
        ::raise(SIGINT);
        ::raise(SIGINT);
        // Not reached: the second signal exits.
        std::_Exit(0);
      },
      testing::ExitedWithCode(130), "stopping now");
}

TEST(StopSignalDeathTest, SecondSigtermEndsWithStatus143) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        const StopSignal stop;
        ::raise(SIGTERM);
        ::raise(SIGTERM);
        std::_Exit(0);
      },
      testing::ExitedWithCode(143), "stopping now");
}

}  // namespace
}  // namespace echoplan
