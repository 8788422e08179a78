// A progress bar for long runs on stderr: done/total, the rate and the time left.
//
// On a terminal it redraws one line; otherwise (a log file, a cluster job) it prints a line at
// every tenth of the work, so logs stay short.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace echoplan::experiment {

class ProgressBar {
 public:
  // `what` names the units ("trials"); `already` units were done before this run (not timed).
  ProgressBar(std::string what, int total, int already = 0, std::FILE* out = stderr);

  // Reports `done` units in total (including `already`).
  void update(int done);
  // Ends the line.
  void finish();

  // The text of one update, for tests: e.g. "[#####-----] 5/10 trials, 0:12 left".
  static std::string render(const std::string& what, int done, int total, double seconds_per_unit);

 private:
  std::string what_;
  int total_;
  int already_;
  std::FILE* out_;
  bool terminal_;
  int last_tenth_ = -1;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace echoplan::experiment
