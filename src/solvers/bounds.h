// Bounds on one value (V* at a belief, Q* of an action there): lower <= true value <= upper. The
// one bounds type of the exact solver (identification_solver.h), its guide for ABT
// (exact_bounds_guide.h) and the point-based solver (offline/point_based_solver.h).
#pragma once

namespace echoplan::solvers {

struct Bounds {
  double lower = 0.0;
  double upper = 0.0;
  double gap() const { return upper - lower; }
};

}  // namespace echoplan::solvers
