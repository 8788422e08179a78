// Errors that carry where the problem is and what to do about it.
//
// Libraries never print and exit: they throw InputError for bad user input (a file, a flag, a
// value) and let the caller decide. The `echoplan` command turns an InputError into one line on
// stderr and exit status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace echoplan {

// Bad input from the user: a file, a command-line value, a recording. `file` may be empty (for
// flags); `line` is 1-based, 0 when unknown. what() is the full message "file:line: problem".
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string problem);
  explicit InputError(std::string problem) : InputError("", 0, std::move(problem)) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  int line_;
  std::string problem_;
};

}  // namespace echoplan
