// The one way a long command stops cleanly on Ctrl-C (SIGINT) or SIGTERM.
//
// A command that runs for a while (trials, dataset, and any new one: run, experiment, train) does:
//
//   const echoplan::StopSignal stop;                  // installs the handlers for this scope
//   auto result = long_work(..., stop.flag());        // the work polls the flag between units
//   save(result);                                     // keep everything that finished
//   if (stop.requested()) throw cli::Interrupted{};   // main() turns this into exit status 130
//
// The first signal only sets the flag (and says on stderr that the run is stopping), so the work
// finishes the unit in progress (a step, a clip) and every file on disk stays complete. A second
// signal ends the process at once with status 128 + signal (130 for Ctrl-C), for when the unit in
// progress takes too long. Leaving the scope restores the previous handlers.
//
// Libraries take `const std::atomic<bool>&` (or a pointer) and never install handlers themselves,
// so they stay usable from programs with their own signal handling.
#pragma once

#include <atomic>

namespace echoplan {

// Installs SIGINT and SIGTERM handlers for its lifetime. At most one StopSignal exists at a time
// (the handlers are process-wide); constructing a second throws std::logic_error.
class StopSignal {
 public:
  StopSignal();
  ~StopSignal();
  StopSignal(const StopSignal&) = delete;
  StopSignal& operator=(const StopSignal&) = delete;

  // True once SIGINT or SIGTERM arrived in this scope. Safe to read from any thread.
  const std::atomic<bool>& flag() const;
  bool requested() const { return flag().load(); }
};

}  // namespace echoplan
