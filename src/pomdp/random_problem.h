// Random object-identification problems of any size, for scale studies (16, 64 objects, ...).
//
// Each observation row P(. | object k, action a) is drawn from a Dirichlet distribution whose
// parameter is `concentration` x (C-1) on the true class and 1 on each other class, so the
// expected probability of hearing the right class is concentration / (concentration + 1),
// whatever the number of objects (1.5 gives 0.6, close to the report's table). Rows are rounded
// to 4 decimals with a floor of 1e-4 (no observation is impossible) and the diagonal absorbs the
// rounding so every row sums to 1. The objects are split at random into `bins` groups (sorting
// actions move_to_A, move_to_B, ...): floor(K / bins) objects each, the last bin takes the rest
// (with 2 bins, a random half rounded down belongs at A). Sorting right pays +10 and wrong -100,
// each sensing action -1, as in the report.
#pragma once

#include <cstdint>

#include "common/rng.h"
#include "pomdp/object_identification_model.h"

namespace echoplan::pomdp {

struct RandomProblemSettings {
  int objects = 16;            // >= 2
  int sensing_actions = 4;     // >= 1
  double concentration = 1.5;  // > 0, see above
  std::uint64_t seed = 1;      // recorded in the problem's name
  int bins = 2;                // sorting actions, 2 to min(26, objects)
};

// Throws std::invalid_argument for settings out of range.
ObjectProblemData make_random_object_problem(const RandomProblemSettings& settings, Rng& rng);

}  // namespace echoplan::pomdp
