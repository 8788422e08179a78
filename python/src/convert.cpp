// The conversions every area shares (bindings.h).
#include <pybind11/stl.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "bindings.h"

namespace echoplan::python {

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

}  // namespace

int action_index(const pomdp::Model& model, py::handle action) {
  const auto& names = model.spec().action_names;
  if (py::isinstance<py::str>(action)) {
    const std::string name = action.cast<std::string>();
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      throw py::value_error("no action '" + name + "' (actions: " + joined(names) + ")");
    return static_cast<int>(it - names.begin());
  }
  const int index = action.cast<int>();
  if (index < 0 || index >= static_cast<int>(names.size()))
    throw py::value_error("action " + std::to_string(index) + " is out of range (" +
                          std::to_string(names.size()) + " actions: " + joined(names) + ")");
  return index;
}

pomdp::Observation to_observation(const pomdp::Model& model, py::handle observation) {
  if (py::isinstance<pomdp::Observation>(observation))
    return observation.cast<pomdp::Observation>();
  pomdp::Observation o;
  if (py::isinstance<py::str>(observation)) {
    const std::string name = observation.cast<std::string>();
    const auto& names = model.spec().observation.names;
    const auto it = std::find(names.begin(), names.end(), name);
    if (!model.spec().observation.discrete || it == names.end())
      throw py::value_error("no observation symbol '" + name + "' (symbols: " + joined(names) +
                            ")");
    o.index = static_cast<int>(it - names.begin());
  } else if (py::isinstance<py::int_>(observation)) {
    o.index = observation.cast<int>();
  } else {
    o.values = observation.cast<std::vector<double>>();
  }
  return o;
}

py::array_t<double> to_array(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::array_t<double> view_of(const std::vector<double>& values, py::handle owner) {
  py::array_t<double> view(static_cast<py::ssize_t>(values.size()), values.data(), owner);
  // Read-only: the data belongs to `owner` and changes only through its own methods.
  view.attr("setflags")(py::arg("write") = false);
  return view;
}

audio::AudioClip to_clip(py::handle samples, int sample_rate) {
  if (py::isinstance<audio::AudioClip>(samples)) return samples.cast<audio::AudioClip>();
  if (sample_rate <= 0) throw py::value_error("sample_rate must be > 0 (Hz)");
  const auto array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(samples);
  if (!array || (array.ndim() != 1 && array.ndim() != 2))
    throw py::value_error("a clip is a numpy array of shape (frames,) or (frames, channels)");
  audio::AudioClip clip;
  clip.sample_rate = sample_rate;
  clip.channels = array.ndim() == 2 ? static_cast<int>(array.shape(1)) : 1;
  if (clip.channels < 1) throw py::value_error("a clip needs at least one channel");
  clip.samples.assign(array.data(), array.data() + array.size());
  return clip;
}

py::object to_python(const nlohmann::json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

}  // namespace echoplan::python
