// Feature sets and the observation model fitted on them, from Python (feature_arrays.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace echoplan::python {

// FeatureSet (from files or numpy arrays), fit_observation_model, dataset_problem.
void bind_feature_sets(pybind11::module_& m);

}  // namespace echoplan::python
