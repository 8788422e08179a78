#include "common/error.h"

#include <fmt/format.h>

namespace echoplan {
namespace {
std::string format_message(const std::string& file, int line, const std::string& problem) {
  if (file.empty()) return problem;
  if (line <= 0) return fmt::format("{}: {}", file, problem);
  return fmt::format("{}:{}: {}", file, line, problem);
}
}  // namespace

InputError::InputError(std::string file, int line, std::string problem)
    : std::runtime_error(format_message(file, line, problem)),
      file_(std::move(file)),
      line_(line),
      problem_(std::move(problem)) {}

}  // namespace echoplan
