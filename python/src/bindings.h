// The parts of the Python module `echoplan._echoplan`, one file per area (python/src/<area>.cpp),
// and the conversions they share: actions and observations given by index or by name, numpy
// arrays in and out. docs/python.md is the user's view of all of it.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "audio/clip.h"
#include "pomdp/belief.h"
#include "pomdp/model.h"
#include "pomdp/problem.h"

namespace echoplan::python {

namespace py = pybind11;

void bind_errors(py::module_& m);      // errors.cpp: InputError with file and line
void bind_problems(py::module_& m);    // problems.cpp: Rng, problems, models, beliefs
void bind_planners(py::module_& m);    // planners.cpp: solvers by name, trials
void bind_exact(py::module_& m);       // exact.cpp: the exact solver, certify
void bind_perception(py::module_& m);  // perception.cpp: features, feature sets, models
void bind_robots(py::module_& m);      // robots.cpp: the loop with robot parts in Python
void bind_campaigns(py::module_& m);   // campaigns.cpp: a campaign file run into a folder

// Problems are shared with the planners and loops built on them (which keep them alive).
using ProblemPtr = std::shared_ptr<pomdp::Problem>;

// A belief with the model it is over (so actions and observations can be named).
struct BeliefHandle {
  pomdp::BeliefPtr belief;
  pomdp::ModelPtr model;
};

// An action given as its index or its name; ValueError naming the model's actions otherwise.
int action_index(const pomdp::Model& model, py::handle action);
// An observation given as a symbol index, a symbol name, an Observation, or a sequence of numbers
// (a continuous observation); ValueError naming the model's symbols for an unknown name.
pomdp::Observation to_observation(const pomdp::Model& model, py::handle observation);

// A copy of `values` as a 1-D float64 array (small data: beliefs, values per action).
py::array_t<double> to_array(const std::vector<double>& values);
// A 1-D float64 array over `values`, owned by `owner` (no copy): it lives as long as `owner`.
py::array_t<double> view_of(const std::vector<double>& values, py::handle owner);
// An audio clip from a numpy array: (frames,) mono or (frames, channels), any float dtype (copied
// into the clip's float32 samples), or an AudioClip as it is.
audio::AudioClip to_clip(py::handle samples, int sample_rate);

// A JSON document as Python objects (dicts, lists, numbers, strings).
py::object to_python(const nlohmann::json& json);

}  // namespace echoplan::python
