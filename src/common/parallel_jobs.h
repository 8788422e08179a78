#pragma once
// Jobs numbered 0..count-1 shared among threads: the one pool the campaign's trials, the self-play
// that chooses an estimate and the simulator's recordings all run on.

#include <atomic>
#include <cstddef>
#include <functional>

namespace echoplan {

// Runs one thread's share of the jobs: called with each job number the thread takes, in increasing
// order; returns false to take no more.
using JobRunner = std::function<bool(std::size_t job)>;

// Runs jobs 0..count-1 on min(threads, count) threads, the calling thread among them (at least
// one). Each thread calls `make_runner` once and keeps what it returns, so a thread can own state
// between its jobs (a planner, a scene); it then takes the lowest job no thread has taken yet,
// until none is left or its runner returns false. Which thread runs a job depends on timing, so a
// job's result must not. Once `stop` (optional) is set, or a thread has thrown, no thread takes
// another job (those already running finish); the first exception is rethrown here once all have
// joined.
void run_jobs(std::size_t count, int threads, const std::function<JobRunner()>& make_runner,
              const std::atomic<bool>* stop = nullptr);

}  // namespace echoplan
