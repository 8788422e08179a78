// Long calls from Python: the GIL released while they work, and Ctrl-C stopping them cleanly.
//
// Python handles Ctrl-C itself: its C-level handler only notes the signal, and the main thread
// raises KeyboardInterrupt the next time it runs Python code, which a long C++ call never does. So
// the work runs in a thread of its own while the calling thread waits with the GIL released, and
// every 50 ms takes the GIL back to let Python run its signal handlers (PyErr_CheckSignals). When
// one raises (KeyboardInterrupt, or whatever a handler of the user's raises), the work's stop flag
// is set; the work finishes the unit in progress (a step, a trial, a stage), returns, and the
// exception is raised from the call. Libraries take such a flag and never install signal handlers
// (common/stop_signal.h), so nothing is installed here either: Python's handling stays Python's.
//
// Called from a thread other than the main thread, signals are not checked (Python delivers them
// to the main thread only) and the call simply runs to its end.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>

namespace echoplan::python {

// Thrown by a progress callback to end work that has no stop flag of its own (training) once
// `stop` is set; run_interruptibly then raises the pending Python exception instead.
struct Stopped {};

// Runs `work(stop)` (stop: const std::atomic<bool>&) as described above and returns its result.
// Exceptions of the work are rethrown in the calling thread (the GIL held again).
template <class Work>
auto run_interruptibly(Work&& work) {
  namespace py = pybind11;
  using Result = std::invoke_result_t<Work&, const std::atomic<bool>&>;
  using Stored = std::conditional_t<std::is_void_v<Result>, bool, Result>;
  std::atomic<bool> stop{false};
  std::optional<Stored> result;
  std::exception_ptr error;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::optional<py::error_already_set> signal;  // what a signal handler raised
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        if constexpr (std::is_void_v<Result>) {
          work(stop);
          result.emplace(true);
        } else {
          result.emplace(work(stop));
        }
      } catch (const Stopped&) {
        // The work gave up at the stop flag: the signal's exception is raised below.
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      done = true;
      finished.notify_all();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; })) {
      if (signal) continue;
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) {
          signal.emplace();  // takes the exception a handler raised
          stop = true;
        }
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (signal) throw std::move(*signal);
  if (error) std::rethrow_exception(error);
  if constexpr (!std::is_void_v<Result>) return std::move(*result);
}

}  // namespace echoplan::python
