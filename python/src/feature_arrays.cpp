// Feature sets from files or numpy arrays, and the model fitted on them: the sessions recipe of
// `echoplan train --data DIR` (fit_feature_model) on a FeatureSet built in memory exactly as
// load_feature_set builds one from DIR/<action>/<modality>.csv, and the clips recipe
// (train_observation_model) on a recordings tree.
#include "feature_arrays.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>

#include "bindings.h"
#include "common/error.h"
#include "interrupt.h"
#include "loop/dataset_problem.h"
#include "perception/dataset_task.h"
#include "perception/feature_model.h"
#include "perception/observation_model.h"
#include "perception/recording_features.h"
#include "perception/recording_set.h"

namespace echoplan::python {

namespace {

using perception::FeatureSet;
using SetPtr = std::shared_ptr<FeatureSet>;

// What errors call arrays: "arrays[<action>][<modality>]", with the row (1-based) as the line.
std::string where(const std::string& action, const std::string& part) {
  return "arrays[" + action + "][" + part + "]";
}

std::vector<std::string> names_of(const py::object& column, const std::string& action,
                                  const std::string& part) {
  std::vector<std::string> out;
  for (py::handle x : column) out.push_back(py::str(x).cast<std::string>());
  for (std::size_t i = 0; i < out.size(); ++i)
    if (out[i].empty()) throw InputError(where(action, part), int(i) + 1, "an empty " + part);
  return out;
}

// One modality's matrix, checked as the CSV reader checks a file: rows x features, every value
// finite, `rows` rows.
perception::Modality modality_of(const std::string& action, const std::string& name,
                                 py::handle values, std::size_t rows, py::handle feature_names) {
  const auto x = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  if (!x || x.ndim() != 2)
    throw InputError(where(action, name), 0, "expected a 2-D array (rows x features)");
  if (std::size_t(x.shape(0)) != rows)
    throw InputError(where(action, name), 0,
                     std::to_string(x.shape(0)) + " rows, but the action has " +
                         std::to_string(rows) +
                         " labels; every modality of an action has one "
                         "row per performance");
  if (x.shape(1) < 1) throw InputError(where(action, name), 0, "no features");
  perception::Modality m;
  m.name = name;
  const auto cols = std::size_t(x.shape(1));
  m.rows.assign(rows, std::vector<double>(cols));
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c) {
      const double v = x.at(py::ssize_t(r), py::ssize_t(c));
      if (!std::isfinite(v))
        throw InputError(where(action, name), int(r) + 1,
                         "feature " + std::to_string(c) + " is not a finite number");
      m.rows[r][c] = v;
    }
  if (feature_names.is_none()) {
    for (std::size_t c = 0; c < cols; ++c) m.feature_names.push_back("f" + std::to_string(c));
  } else {
    m.feature_names = feature_names.cast<std::vector<std::string>>();
    if (m.feature_names.size() != cols)
      throw InputError(where(action, name), 0,
                       "feature_names has " + std::to_string(m.feature_names.size()) +
                           " names for " + std::to_string(cols) + " columns");
  }
  return m;
}

// {action: {"objects": [...], "sessions": [...], "modalities": {name: X}, "feature_names":
// {name: [...]}}}, in load_feature_set's order: actions, then modalities, sorted by name; objects
// and sessions numbered by first appearance (actions in order, rows in order).
FeatureSet from_arrays(const py::dict& actions) {
  FeatureSet set;
  set.root = "arrays";
  std::map<std::string, py::dict> sorted;
  for (const auto& [key, value] : actions) sorted[key.cast<std::string>()] = value.cast<py::dict>();
  if (sorted.empty()) throw InputError("arrays", 0, "no actions");
  for (const auto& [name, d] : sorted) {
    for (const char* key : {"objects", "sessions", "modalities"})
      if (!d.contains(key))
        throw InputError(where(name, key), 0, std::string("missing '") + key + "'");
    const auto objects = names_of(d["objects"], name, "objects");
    const auto sessions = names_of(d["sessions"], name, "sessions");
    if (objects.size() != sessions.size() || objects.empty())
      throw InputError(where(name, "sessions"), 0,
                       "one object and one session per row, and at least one row");
    perception::ActionData action;
    action.name = name;
    for (std::size_t r = 0; r < objects.size(); ++r) {
      const int o = set.add_object(objects[r]);
      action.rows.push_back({o, set.add_session(o, sessions[r])});
    }
    std::map<std::string, py::handle> modalities;
    for (const auto& [m, x] : d["modalities"].cast<py::dict>())
      modalities[m.cast<std::string>()] = x;
    if (modalities.empty()) throw InputError(where(name, "modalities"), 0, "no modalities");
    const py::dict names =
        d.contains("feature_names") ? d["feature_names"].cast<py::dict>() : py::dict();
    for (const auto& [m, x] : modalities)
      action.modalities.push_back(
          modality_of(name, m, x, objects.size(),
                      names.contains(m) ? py::object(names[py::str(m)]) : py::object(py::none())));
    set.actions.push_back(std::move(action));
  }
  for (const auto& action : set.actions)
    for (std::size_t o = 0; o < set.objects.size(); ++o)
      if (std::none_of(action.rows.begin(), action.rows.end(),
                       [&](const perception::RowLabel& r) { return r.object == int(o); }))
        throw InputError(
            where(action.name, "objects"), 0,
            "no rows of object '" + set.objects[o] +
                "', but other actions have it; every object needs rows for every action");
  return set;
}

const perception::ActionData& action_of(const FeatureSet& set, const std::string& name) {
  if (const auto* a = set.action(name)) return *a;
  throw InputError(set.root, 0, "no action '" + name + "'");
}

py::array_t<double> rows_of(const perception::Modality& m) {
  const std::size_t cols = m.feature_names.size();
  py::array_t<double> out({py::ssize_t(m.rows.size()), py::ssize_t(cols)});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t r = 0; r < m.rows.size(); ++r)
    for (std::size_t c = 0; c < cols; ++c) o(r, c) = m.rows[r][c];
  return out;
}

void bind_feature_set(py::module_& m) {
  py::class_<FeatureSet, SetPtr>(
      m, "FeatureSet",
      "Recorded data from any robot and sensor (docs/feature-sets.md): per action (behaviour), "
      "rows of performances labelled by object and session, one matrix per modality. "
      "load_feature_set(dir), load_data(dir) (a recordings tree too) or "
      "FeatureSet.from_arrays({action: {'objects': [...], 'sessions': [...], 'modalities': "
      "{'audio': X, ...}}}).")
      .def_static(
          "from_arrays",
          [](const py::dict& d) { return std::make_shared<FeatureSet>(from_arrays(d)); },
          py::arg("actions"),
          "A feature set from numpy arrays, ordered as load_feature_set orders files "
          "(actions and modalities by name), so the same numbers give the same model as "
          "`echoplan train --data DIR`. Optional per action: 'feature_names': {modality: "
          "[...]}. InputError names arrays[action][part] and the row of a mistake.")
      .def_readonly("root", &FeatureSet::root)
      .def_readonly("objects", &FeatureSet::objects)
      .def_property_readonly(
          "sessions",
          [](const FeatureSet& s) {
            std::vector<std::pair<std::string, std::string>> out;
            for (const auto& x : s.sessions) out.emplace_back(s.objects[x.object], x.name);
            return out;
          },
          "(object, session name) of every session.")
      .def_property_readonly("actions",
                             [](const FeatureSet& s) {
                               std::vector<std::string> out;
                               for (const auto& a : s.actions) out.push_back(a.name);
                               return out;
                             })
      .def(
          "modalities",
          [](const FeatureSet& s, const std::string& action) {
            std::vector<std::string> out;
            for (const auto& x : action_of(s, action).modalities) out.push_back(x.name);
            return out;
          },
          py::arg("action"))
      .def(
          "rows",
          [](const FeatureSet& s, const std::string& action, const std::string& modality) {
            for (const auto& x : action_of(s, action).modalities)
              if (x.name == modality) return rows_of(x);
            throw InputError(s.root, 0,
                             "action '" + action + "' has no modality '" + modality + "'");
          },
          py::arg("action"), py::arg("modality"), "The modality's rows x features (a copy).")
      .def(
          "labels",
          [](const FeatureSet& s, const std::string& action) {
            std::vector<std::pair<std::string, std::string>> out;
            for (const auto& r : action_of(s, action).rows)
              out.emplace_back(s.objects[r.object], s.sessions[r.session].name);
            return out;
          },
          py::arg("action"), "(object, session) of every row of the action.");
  m.def(
      "load_feature_set",
      [](const std::string& dir) {
        return std::make_shared<FeatureSet>(perception::load_feature_set(dir));
      },
      py::arg("dir"), "Reads DIR/<action>/<modality>.csv; InputError naming the file and line.");
  m.def(
      "load_data",
      [](const std::string& dir) {
        return run_interruptibly([&](const std::atomic<bool>& stop) {
          return std::make_shared<FeatureSet>(
              perception::load_data(dir, [&](const std::string&, int, int) {
                if (stop) throw Stopped{};
              }));
        });
      },
      py::arg("dir"), "A feature set or a recordings tree (its audio analysed) as a FeatureSet.");
}

// The task `echoplan train` makes of its flags: groups from a file path or a dict.
perception::DatasetTask task_of(const FeatureSet& set, py::handle groups,
                                const std::string& hold_out) {
  std::optional<perception::ObjectGroups> g;
  std::string file;
  if (py::isinstance<py::dict>(groups)) {
    g.emplace();
    for (const auto& [object, group] : groups.cast<py::dict>()) {
      g->objects.push_back(object.cast<std::string>());
      g->groups.push_back(group.cast<std::string>());
    }
    file = "groups";
  } else if (!groups.is_none()) {
    file = py::str(groups).cast<std::string>();
    g = perception::load_groups(file);
  }
  return perception::make_dataset_task(set, g ? &*g : nullptr, perception::parse_hold_out(hold_out),
                                       file);
}

std::shared_ptr<perception::ObservationModel> fit(const SetPtr& set, py::handle groups,
                                                  const std::string& hold_out,
                                                  const std::string& classifier,
                                                  std::optional<std::vector<int>> sessions) {
  const perception::DatasetTask task = task_of(*set, groups, hold_out);
  std::vector<int> training(set->sessions.size());
  std::iota(training.begin(), training.end(), 0);
  if (sessions) training = *sessions;
  return run_interruptibly([&](const std::atomic<bool>& stop) {
    return std::make_shared<perception::ObservationModel>(perception::fit_feature_model(
        *set, task, training, {classifier}, [&](const std::string&, int, int) {
          if (stop) throw Stopped{};
        }));
  });
}

// The problem of a feature set and a model fitted on it, as `echoplan train --problem-out` writes
// it (exact beliefs, default planner settings), read back as a Problem.
ProblemPtr dataset_problem(const SetPtr& set, const perception::ObservationModel& model,
                           py::handle groups, const std::string& hold_out, double right,
                           double wrong, double sense, bool atypical, bool lookalike) {
  const perception::DatasetTask task = task_of(*set, groups, hold_out);
  const auto kind = perception::ObservationKind::labels;
  loop::UnlikeTheirClass unlike;
  if (atypical) unlike.atypical = model.atypical_share(kind);
  if (lookalike) unlike.lookalike = model.lookalike_share(kind);
  const auto data = loop::dataset_problem(task, model, {right, wrong, sense, {}},
                                          loop::default_uses(*set), kind, unlike);
  std::ostringstream text;
  pomdp::BeliefSettings belief;
  belief.type = pomdp::BeliefSettings::Type::exact;
  pomdp::write_problem_yaml(text, data, belief, pomdp::PlannerDefaults{});
  return std::make_shared<pomdp::Problem>(
      pomdp::parse_problem(text.str(), set->root + "/problem.yaml"));
}

std::shared_ptr<perception::ObservationModel> train_clips(const std::string& dir,
                                                          const perception::TrainOptions& options) {
  const perception::RecordingSet set = perception::load_recording_set(dir);
  return run_interruptibly([&](const std::atomic<bool>& stop) {
    return std::make_shared<perception::ObservationModel>(
        perception::train_observation_model(set, options, [&](const std::string&, int, int) {
          if (stop) throw Stopped{};
        }));
  });
}

}  // namespace

void bind_feature_sets(py::module_& m) {
  bind_feature_set(m);
  m.def("fit_feature_model", &fit, py::arg("feature_set"), py::kw_only(),
        py::arg("groups") = py::none(), py::arg("hold_out") = "session",
        py::arg("classifier") = std::string(perception::kDefaultRowClassifier),
        py::arg("training_sessions") = py::none(),
        "The sessions recipe of `echoplan train --data DIR` on a FeatureSet: a row classifier "
        "per (action, modality), fused and calibrated by session-grouped cross-validation. "
        "groups: a groups file path or a dict {object: group}; hold_out: 'session' or 'object'; "
        "classifier: 'lda' or 'nearest-neighbour'; training_sessions: session indices (default: "
        "all). Ctrl-C stops it.");
  m.def("dataset_problem", &dataset_problem, py::arg("feature_set"), py::arg("model"),
        py::kw_only(), py::arg("groups") = py::none(), py::arg("hold_out") = "session",
        py::arg("right") = 10.0, py::arg("wrong") = -100.0, py::arg("sense") = -1.0,
        py::arg("atypical") = false, py::arg("lookalike") = false,
        "The problem of a feature set with a model fitted on it, as `echoplan train "
        "--problem-out` writes it: the classes, one sensing action per behaviour with its use "
        "limit, one sorting action per bin, the model's table, exact beliefs. atypical=True adds "
        "an atypical copy of every class ('<class>~atypical') with the model's atypical_share() "
        "of the prior, as a campaign arm with `atypical: true` plans; lookalike=True a lookalike "
        "copy ('<class>~lookalike': sounds like the class, is another) with its "
        "lookalike_share(), as an arm with `lookalike: true` plans.");
  const perception::TrainOptions d;
  m.def(
      "train_observation_model",
      [](const std::string& dir, const std::string& classifier, bool reject, double margin,
         double alpha, const std::string& table, int folds, std::uint64_t seed, int rate) {
        perception::TrainOptions o;
        o.classifier = classifier;
        o.reject = reject;
        o.reject_margin = margin;
        o.dirichlet_alpha = alpha;
        o.table = perception::parse_table_estimate(table);
        o.folds = folds;
        o.seed = seed;
        o.analysis.sample_rate = rate;
        return train_clips(dir, o);
      },
      py::arg("recordings"), py::kw_only(), py::arg("classifier") = d.classifier,
      py::arg("reject") = d.reject, py::arg("reject_margin") = d.reject_margin,
      py::arg("alpha") = d.dirichlet_alpha, py::arg("table") = "counts", py::arg("folds") = d.folds,
      py::arg("seed") = d.seed, py::arg("sample_rate") = d.analysis.sample_rate,
      "The clips recipe of `echoplan train --data DIR --out MODEL` on a recordings tree "
      "DIR/<object>/<action>/*.wav: one audio classifier per action, cross-validated and "
      "calibrated; the same options as the command's flags. Ctrl-C stops it.");
}

}  // namespace echoplan::python
