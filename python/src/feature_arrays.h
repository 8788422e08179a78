// Feature sets and the two training recipes from Python (feature_arrays.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace echoplan::python {

// FeatureSet (from files or numpy arrays), train_observation_model, fit_feature_model,
// dataset_problem.
void bind_feature_sets(pybind11::module_& m);

}  // namespace echoplan::python
