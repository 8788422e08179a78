// For tests of bad input: the message of the InputError a call throws.
#pragma once

#include <string>

#include "common/error.h"

namespace echoplan {

// The message (what()) of the InputError `fn` throws, or "(no InputError)" when it throws none.
template <typename Fn>
std::string input_error_message(Fn fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace echoplan
