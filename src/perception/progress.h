// Progress of long perception work (training, evaluation), for a command's progress line.
#pragma once

#include <functional>
#include <string>

namespace echoplan::perception {

// (what, done, total), e.g. ("analyse", 12, 80).
using ProgressFn = std::function<void(const std::string& stage, int done, int total)>;

}  // namespace echoplan::perception
