// Perception from Python: audio clips as numpy arrays, their features (the presets of `echoplan
// features`), feature sets from files or from numpy arrays, and the one observation model
// (perception/observation_model.h): fitted on a recordings tree or a feature set
// (fit_observation_model), classifying a clip or a feature row, saved and loaded.
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>
#include <numeric>
#include <optional>

#include "audio/features.h"
#include "audio/io.h"
#include "bindings.h"
#include "common/error.h"
#include "feature_arrays.h"
#include "interrupt.h"
#include "perception/dataset_task.h"
#include "perception/fit_observation_model.h"
#include "perception/observation_model.h"
#include "perception/performance_reader.h"
#include "perception/recording_features.h"

namespace echoplan::python {

namespace {

using perception::ObservationModel;
using ModelPtr = std::shared_ptr<ObservationModel>;

// The kind of observation a Python call's `graded` flag names.
perception::ObservationKind kind_of(bool graded) {
  return graded ? perception::ObservationKind::graded : perception::ObservationKind::labels;
}

// A matrix handed to Python without a copy: the array owns the moved matrix.
py::array_t<float> take(audio::FeatureMatrix&& matrix) {
  auto* owned = new audio::FeatureMatrix(std::move(matrix));
  py::capsule free_it(owned, [](void* p) { delete static_cast<audio::FeatureMatrix*>(p); });
  return py::array_t<float>({py::ssize_t(owned->rows), py::ssize_t(owned->cols)},
                            owned->values.data(), free_it);
}

void bind_clip(py::module_& m) {
  py::class_<audio::AudioClip>(m, "AudioClip",
                               "Sound: float samples in [-1, 1) at `sample_rate` Hz, "
                               "`channels` interleaved. AudioClip(samples, sample_rate) takes a "
                               "numpy array of shape (frames,) or (frames, channels).")
      .def(py::init([](py::array samples, int rate) { return to_clip(samples, rate); }),
           py::arg("samples"), py::arg("sample_rate") = 44100)
      .def_readonly("sample_rate", &audio::AudioClip::sample_rate)
      .def_readonly("channels", &audio::AudioClip::channels)
      .def_property_readonly(
          "samples",
          [](py::object self) {
            const auto& c = self.cast<const audio::AudioClip&>();
            const py::ssize_t ch = c.channels, frames = c.frames();
            py::array_t<float> view({frames, ch}, c.samples.data(), self);
            view.attr("setflags")(py::arg("write") = false);
            return view;
          },
          "The samples, (frames, channels), a read-only view without a copy.")
      .def_property_readonly("duration", &audio::AudioClip::duration_seconds, "seconds");
  m.def(
      "read_audio",
      [](const std::string& path, int rate) {
        audio::ReadOptions options;
        options.target_sample_rate = rate;
        return audio::read_audio(path, options);
      },
      py::arg("path"), py::arg("resample") = 0,
      "Reads WAV, FLAC or AIFF (libsndfile) as an AudioClip, resampled when `resample` > 0.");
}

py::dict features(py::handle samples, int rate, const std::string& preset, py::object channel) {
  audio::ReadOptions read;
  if (channel.is_none()) {
    read.channel_policy = audio::ChannelPolicy::mean;
  } else {
    read.channel_policy = audio::ChannelPolicy::select;
    read.channel = channel.cast<int>();
  }
  const audio::AudioClip clip = audio::convert_clip(to_clip(samples, rate), read, "<clip>");
  audio::FeatureExtractor extractor(audio::preset_by_name(preset, clip.sample_rate));
  audio::Features f;
  {
    py::gil_scoped_release release;
    extractor.compute(clip.samples, f);
  }
  py::dict out;
  out["logmel"] = take(std::move(f.log_mel));
  out["mfcc"] = take(std::move(f.mfcc));
  out["centroid"] = take(std::move(f.centroid));
  out["bandwidth"] = take(std::move(f.bandwidth));
  out["rolloff"] = take(std::move(f.rolloff));
  out["flatness"] = take(std::move(f.flatness));
  out["flux"] = take(std::move(f.flux));
  out["rms"] = take(std::move(f.rms));
  out["zcr"] = take(std::move(f.zcr));
  return out;
}

void bind_prediction(py::module_& m) {
  using perception::Prediction;
  py::class_<Prediction>(m, "Prediction", "What the model makes of one performance.")
      .def_readonly("action", &Prediction::action)
      .def_readonly("symbol", &Prediction::symbol, "Index into the model's observation symbols.")
      .def_readonly("label", &Prediction::label, "A class name or 'unknown'.")
      .def_readonly("unknown", &Prediction::unknown)
      .def_readonly("best_class", &Prediction::best_class)
      .def_readonly("grade", &Prediction::grade,
                    "The confidence grade of the heard class (0 low, 1 mid, 2 high), -1 without "
                    "grades.")
      .def_readonly("level_grade", &Prediction::level_grade,
                    "The level grade of the recording (0 noisy, 1 fair, 2 clear), -1 without "
                    "level grades or a measured level.")
      .def_property_readonly(
          "probabilities", [](const Prediction& p) { return to_array(p.probabilities); },
          "Calibrated P(class), in the model's class order.")
      .def_readonly("distance", &Prediction::distance)
      .def_readonly("reject_threshold", &Prediction::reject_threshold)
      .def("__repr__",
           [](const Prediction& p) { return "Prediction(" + p.action + ": " + p.label + ")"; });
}

perception::Prediction classify_clip(const ObservationModel& model, py::handle clip,
                                     const std::string& action, int rate) {
  (void)model.calibration(action);  // an unknown action fails before any analysis
  const audio::AudioClip c = to_clip(clip, rate);
  py::gil_scoped_release release;
  perception::ClipAnalyzer analyzer(model.analysis());
  perception::ClipAnalysis analysis;
  analyzer.analyse(c, "<clip>", analysis);
  return model.classify(analysis, action);
}

// One performance given as one row per modality: a dict by modality name, a list in the model's
// modality order, or one array for a model with one modality.
perception::Prediction classify_rows(const ObservationModel& model, const std::string& action,
                                     py::handle rows) {
  const auto& modalities = model.modalities(action);
  std::vector<std::vector<double>> values;
  if (py::isinstance<py::dict>(rows)) {
    const py::dict d = rows.cast<py::dict>();
    for (const auto& modality : modalities) {
      if (!d.contains(modality.name))
        throw InputError("no row for modality '" + modality.name + "' of action '" + action + "'");
      values.push_back(d[py::str(modality.name)].cast<std::vector<double>>());
    }
  } else if (const auto one = py::array_t<double>::ensure(rows);
             modalities.size() == 1 && one && one.ndim() == 1) {
    values.push_back(rows.cast<std::vector<double>>());
  } else {
    values = rows.cast<std::vector<std::vector<double>>>();
  }
  std::vector<std::span<const double>> spans(values.begin(), values.end());
  return model.classify_rows(model.action_index(action), spans);
}

void bind_model(py::module_& m) {
  py::class_<ObservationModel, ModelPtr>(
      m, "ObservationModel",
      "The observation model (perception/observation_model.h): per sensing action, a classifier "
      "per modality, their fusion and calibration, and the table P(symbol | object) the planner "
      "plans with. Fit with fit_observation_model (a FeatureSet or a data folder); "
      "load_observation_model(path); save(path).")
      .def_property_readonly("classes", &ObservationModel::classes)
      .def_property_readonly("actions", &ObservationModel::actions)
      .def_property_readonly("observation_symbols",
                             [](const ObservationModel& x) { return x.observation_symbols(); })
      .def_property_readonly("graded", &ObservationModel::graded,
                             "Every action has graded observations (class@low/mid/high).")
      .def_property_readonly(
          "graded_symbols",
          [](const ObservationModel& x) {
            return x.observation_symbols(perception::ObservationKind::graded);
          },
          "The graded observation symbols ('mug@low', ...), the alphabet of a graded problem.")
      .def_property_readonly("levelled", &ObservationModel::levelled,
                             "Every action has observations graded by the recording's measured "
                             "level (class@noisy/fair/clear): a model trained on recordings.")
      .def_property_readonly(
          "level_symbols",
          [](const ObservationModel& x) {
            return x.observation_symbols(perception::ObservationKind::levels);
          },
          "The level-graded observation symbols ('mug@noisy', ...), the alphabet of a problem "
          "with `observations: levels`.")
      .def(
          "lookalike_share",
          [](const ObservationModel& x, bool graded) { return x.lookalike_share(kind_of(graded)); },
          py::arg("graded") = false,
          "The share of objects that sound like another class the model fitted on held-out "
          "sessions (0 for a model trained on recordings): the prior of the lookalike copies of "
          "dataset_problem(..., lookalike=True).")
      .def(
          "lookalikes_untempered",
          [](const ObservationModel& x, bool graded) {
            return x.lookalikes_untempered(kind_of(graded));
          },
          py::arg("graded") = false,
          "Whether that share was fitted on the untempered tables, which "
          "dataset_problem(..., lookalike=True) then plans with (False: the tempered ones, as "
          "without lookalikes; docs/feature-sets.md, 6).")
      .def_property_readonly("classifier_name", &ObservationModel::classifier_name)
      .def_property_readonly("reject", &ObservationModel::reject)
      .def(
          "modalities",
          [](const ObservationModel& x, const std::string& action) {
            std::vector<std::string> names;
            for (const auto& modality : x.modalities(action)) names.push_back(modality.name);
            return names;
          },
          py::arg("action"))
      .def(
          "weights",
          [](const ObservationModel& x, const std::string& a) { return to_array(x.weights(a)); },
          py::arg("action"), "The fusion weight of each modality.")
      .def(
          "table",
          [](const ObservationModel& x, const std::string& action, bool graded) {
            const auto& t = x.observation_table(action, kind_of(graded));
            py::array_t<double> out(
                {py::ssize_t(t.size()), py::ssize_t(t.empty() ? 0 : t[0].size())});
            auto o = out.mutable_unchecked<2>();
            for (std::size_t k = 0; k < t.size(); ++k)
              for (std::size_t s = 0; s < t[k].size(); ++s) o(k, s) = t[k][s];
            return out;
          },
          py::arg("action"), py::arg("graded") = false,
          "P(symbol | class) for `action`: classes x observation symbols (graded: x graded "
          "symbols).")
      .def("classify", &classify_clip, py::arg("clip"), py::arg("action"),
           py::arg("sample_rate") = 44100,
           "Classifies a clip (AudioClip, or a numpy array with its sample_rate) recorded with "
           "`action`, as `echoplan classify` does.")
      .def("classify_rows", &classify_rows, py::arg("action"), py::arg("rows"),
           "Classifies one performance given as feature rows: a dict {modality: row}, a list in "
           "modalities(action) order, or one row for a single modality.")
      .def(
          "save",
          [](const ObservationModel& x, const std::string& path) {
            perception::save_observation_model(x, path);
          },
          py::arg("path"), "Writes the model file (JSON), atomically.")
      .def(
          "to_json",
          [](const ObservationModel& x) {
            return to_python(perception::observation_model_to_json(x));
          },
          "The model file's content as Python objects.");
  m.def(
      "load_observation_model",
      [](const std::string& path) {
        return std::make_shared<ObservationModel>(perception::load_observation_model(path));
      },
      py::arg("path"), "Reads a model file; InputError naming the file and field of a mistake.");
}

}  // namespace

void bind_perception(py::module_& m) {
  bind_clip(m);
  m.def("features", &features, py::arg("clip"), py::kw_only(), py::arg("sample_rate") = 44100,
        py::arg("preset") = "psf", py::arg("channel") = py::none(),
        "Every frame-wise feature of a clip, as `echoplan features --preset P --feature F` "
        "computes them: a dict of float32 arrays (frames x columns, no copy) named logmel, mfcc, "
        "centroid, bandwidth, rolloff, flatness, flux, rms, zcr. `clip`: an AudioClip or a numpy "
        "array (frames,) or (frames, channels) at `sample_rate`; channels are averaged unless "
        "`channel` picks one. preset: 'psf' or 'librosa'.");
  bind_prediction(m);
  bind_model(m);
  bind_feature_sets(m);
}

}  // namespace echoplan::python
