// The shared job pool: every job runs once, each thread keeps its own runner and takes jobs in
// increasing order, a runner's false stops its thread, a stop request stops all, the first
// exception reaches the caller. The TSan stage runs these (scripts/setup.sh).
#include "common/parallel_jobs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <vector>

namespace echoplan {
namespace {

// Runs `count` jobs on `threads` threads and returns the jobs each runner took, in the order it
// took them (one row per runner made).
std::vector<std::vector<std::size_t>> jobs_by_runner(std::size_t count, int threads) {
  std::mutex mutex;
  std::vector<std::shared_ptr<std::vector<std::size_t>>> rows;
  run_jobs(count, threads, [&]() -> JobRunner {
    auto row = std::make_shared<std::vector<std::size_t>>();
    {
      std::lock_guard<std::mutex> lock(mutex);
      rows.push_back(row);
    }
    return [row](std::size_t job) {
      row->push_back(job);  // this thread's own row: no lock needed
      std::this_thread::yield();
      return true;
    };
  });
  std::vector<std::vector<std::size_t>> out;
  for (const auto& row : rows) out.push_back(*row);
  return out;
}

TEST(ParallelJobs, EveryJobRunsOnceEachThreadInIncreasingOrder) {
  for (int threads : {1, 2, 4}) {
    const auto rows = jobs_by_runner(200, threads);
    ASSERT_EQ(rows.size(), static_cast<std::size_t>(threads)) << threads;
    std::vector<std::size_t> all;
    for (const auto& row : rows) {
      EXPECT_TRUE(std::is_sorted(row.begin(), row.end())) << threads;
      all.insert(all.end(), row.begin(), row.end());
    }
    std::sort(all.begin(), all.end());
    std::vector<std::size_t> expected(200);
    std::iota(expected.begin(), expected.end(), 0);
    EXPECT_EQ(all, expected) << threads;
  }
}

TEST(ParallelJobs, NoMoreThreadsThanJobsAndAlwaysTheCaller) {
  EXPECT_EQ(jobs_by_runner(3, 8).size(), 3u);
  const auto none = jobs_by_runner(0, 4);  // the caller makes its runner and finds no job
  ASSERT_EQ(none.size(), 1u);
  EXPECT_TRUE(none[0].empty());
  for (int threads : {0, -1}) {
    const auto rows = jobs_by_runner(5, threads);
    ASSERT_EQ(rows.size(), 1u) << threads;
    EXPECT_EQ(rows[0], (std::vector<std::size_t>{0, 1, 2, 3, 4})) << threads;
  }
}

TEST(ParallelJobs, ARunnerReturningFalseTakesNoMoreJobs) {
  std::vector<std::size_t> ran;
  run_jobs(10, 1, [&]() -> JobRunner {
    return [&](std::size_t job) {
      ran.push_back(job);
      return job < 3;
    };
  });
  EXPECT_EQ(ran, (std::vector<std::size_t>{0, 1, 2, 3}));
}

TEST(ParallelJobs, NoJobIsTakenOnceStopIsSet) {
  std::atomic<bool> stop{false};
  std::vector<std::size_t> ran;
  run_jobs(
      10, 1,
      [&]() -> JobRunner {
        return [&](std::size_t job) {
          ran.push_back(job);
          if (job == 3) stop = true;
          return true;
        };
      },
      &stop);
  EXPECT_EQ(ran, (std::vector<std::size_t>{0, 1, 2, 3}));
}

TEST(ParallelJobs, TheFirstExceptionStopsTheJobsAndReachesTheCaller) {
  std::vector<std::size_t> ran;
  auto throw_at_five = [&]() -> JobRunner {
    return [&](std::size_t job) {
      if (job == 5) throw std::runtime_error("job 5 failed");
      ran.push_back(job);
      return true;
    };
  };
  try {
    run_jobs(100, 1, throw_at_five);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "job 5 failed");
  }
  EXPECT_EQ(ran, (std::vector<std::size_t>{0, 1, 2, 3, 4}));

  // On several threads the exception still reaches the caller, after every thread has joined;
  // one that made no runner throws from its factory.
  std::mutex mutex;
  int made = 0;
  EXPECT_THROW(run_jobs(100, 2,
                        [&]() -> JobRunner {
                          std::lock_guard<std::mutex> lock(mutex);
                          if (made++ == 1) throw std::runtime_error("no runner");
                          return [](std::size_t) { return true; };
                        }),
               std::runtime_error);
  EXPECT_EQ(made, 2);
}

}  // namespace
}  // namespace echoplan
