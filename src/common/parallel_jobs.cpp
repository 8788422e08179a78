#include "common/parallel_jobs.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace echoplan {

void run_jobs(std::size_t count, int threads, const std::function<JobRunner()>& make_runner,
              const std::atomic<bool>* stop) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;
  auto work = [&] {
    try {
      const JobRunner run = make_runner();
      while (!failed.load() && !(stop && stop->load())) {
        const std::size_t job = next.fetch_add(1);
        if (job >= count || !run(job)) break;
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!first_error) first_error = std::current_exception();
      failed = true;
    }
  };
  const std::size_t wanted = std::clamp<std::size_t>(count, 1, std::max(threads, 1));
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < wanted; ++t) pool.emplace_back(work);
  work();
  for (std::thread& thread : pool) thread.join();
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace echoplan
