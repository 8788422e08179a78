#include "common/stop_signal.h"

#include <signal.h>
#include <unistd.h>

#include <stdexcept>

namespace echoplan {

namespace {

// Read and written from the signal handler: must be lock-free to be async-signal-safe.
std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

// Whether a StopSignal is alive, and the handlers it replaced.
bool installed = false;
struct sigaction previous_int;
struct sigaction previous_term;

void write_stderr(const char* text, std::size_t length) {
  // write(2) is async-signal-safe; a failed write has nowhere better to be reported.
  [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, text, length);
}

extern "C" void on_stop_signal(int signal_number) {
  if (stop_requested.exchange(true)) {
    // Second signal: the user does not want to wait for the unit in progress.
    static constexpr char kNow[] = "\nechoplan: stopping now\n";
    write_stderr(kNow, sizeof kNow - 1);
    ::_exit(128 + signal_number);
  }
  static constexpr char kSoon[] =
      "\nechoplan: stopping after the current step, keeping what finished (again to stop now)\n";
  write_stderr(kSoon, sizeof kSoon - 1);
}

}  // namespace

StopSignal::StopSignal() {
  if (installed) throw std::logic_error("StopSignal: only one may be active at a time");
  stop_requested = false;
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  // SA_RESTART: a blocking read or write in the work is resumed, not failed with EINTR.
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
  installed = true;
}

StopSignal::~StopSignal() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
  installed = false;
}

const std::atomic<bool>& StopSignal::flag() const { return stop_requested; }

}  // namespace echoplan
