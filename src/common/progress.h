// Progress of long work (synthesising a training set, training, evaluating), for a command's
// progress bar or log: the one callback type every long stage reports through.
#pragma once

#include <functional>
#include <string>

namespace echoplan {

// (what, done, total): `what` names the stage ("analyse", "synthesise") or the item just finished
// (a file written), `done` of `total` are finished.
using ProgressFn = std::function<void(const std::string& what, int done, int total)>;

}  // namespace echoplan
