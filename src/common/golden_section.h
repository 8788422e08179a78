// The minimiser of a unimodal function on an interval, by golden-section search: what temperature
// calibration and the shrunk table's empirical-Bayes strength both fit with.
#pragma once

#include <functional>

namespace echoplan {

// The minimiser of `f` on [lo, hi], after 80 steps (the interval shrinks by 0.618 each step).
// `f` must be unimodal there for the result to be the minimum.
double golden_section_minimum(const std::function<double(double)>& f, double lo, double hi);

}  // namespace echoplan
