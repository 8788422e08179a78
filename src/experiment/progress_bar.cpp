#include "experiment/progress_bar.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace echoplan::experiment {

ProgressBar::ProgressBar(std::string what, int total, int already, std::FILE* out)
    : what_(std::move(what)),
      total_(total),
      already_(already),
      out_(out),
      terminal_(::isatty(::fileno(out)) == 1),
      start_(std::chrono::steady_clock::now()) {}

std::string ProgressBar::render(const std::string& what, int done, int total,
                                double seconds_per_unit) {
  constexpr int width = 30;
  const int filled = total > 0 ? std::clamp(done * width / total, 0, width) : width;
  std::string bar = "[" + std::string(filled, '#') + std::string(width - filled, '-') + "]";
  std::string eta = "estimating";
  if (seconds_per_unit > 0) {
    const long left = std::lround(seconds_per_unit * std::max(0, total - done));
    eta = fmt::format("{}:{:02d} left", left / 60, left % 60);
  }
  return fmt::format("{} {}/{} {}, {}", bar, done, total, what, eta);
}

void ProgressBar::update(int done) {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const int timed = done - already_;
  const std::string line = render(what_, done, total_, timed > 0 ? seconds / timed : 0.0);
  if (terminal_) {
    fmt::print(out_, "\r{}\033[K", line);
  } else {
    const int tenth = total_ > 0 ? done * 10 / total_ : 10;
    if (tenth == last_tenth_) return;
    last_tenth_ = tenth;
    fmt::print(out_, "{}\n", line);
  }
  std::fflush(out_);
}

void ProgressBar::finish() {
  if (terminal_) fmt::print(out_, "\n");
  std::fflush(out_);
}

}  // namespace echoplan::experiment
