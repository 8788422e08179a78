// Feature sets from files or numpy arrays, and the model fitted on them: `echoplan train --data
// DIR` (perception/fit_observation_model.h) on a FeatureSet built in memory exactly as
// load_feature_set builds one from DIR/<action>/<modality>.csv, or on a data folder.
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
#include "perception/fit_observation_model.h"
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

// The groups `echoplan train --groups` reads, from a file path or a dict (read with the GIL held).
struct GroupsArgument {
  std::optional<perception::ObjectGroups> groups;
  std::string file;  // names them in errors
};

GroupsArgument groups_of(py::handle groups) {
  GroupsArgument g;
  if (py::isinstance<py::dict>(groups)) {
    g.groups.emplace();
    for (const auto& [object, group] : groups.cast<py::dict>()) {
      g.groups->objects.push_back(object.cast<std::string>());
      g.groups->groups.push_back(group.cast<std::string>());
    }
    g.file = "groups";
  } else if (!groups.is_none()) {
    g.file = py::str(groups).cast<std::string>();
    g.groups = perception::load_groups(g.file);
  }
  return g;
}

perception::DatasetTask task_of(const FeatureSet& set, const GroupsArgument& g,
                                const std::string& hold_out) {
  return perception::make_dataset_task(set, g.groups ? &*g.groups : nullptr,
                                       perception::parse_hold_out(hold_out), g.file);
}

// The task `echoplan train` makes of its flags.
perception::DatasetTask task_of(const FeatureSet& set, py::handle groups,
                                const std::string& hold_out) {
  return task_of(set, groups_of(groups), hold_out);
}

// `data`: a FeatureSet, or the path of a recordings tree or a feature set. Python objects are read
// here, with the GIL held; the work runs interruptibly without it.
std::shared_ptr<perception::ObservationModel> fit(py::handle data, py::handle groups,
                                                  std::optional<std::string> hold_out,
                                                  std::optional<std::vector<int>> sessions,
                                                  const perception::FitChoices& choices) {
  const GroupsArgument g = groups_of(groups);
  const bool task_named = g.groups.has_value() || hold_out.has_value();
  SetPtr given;
  std::string dir;
  perception::DataKind kind = perception::DataKind::features;
  if (py::isinstance<FeatureSet>(data)) {
    given = data.cast<SetPtr>();
  } else {
    dir = py::str(data).cast<std::string>();
    kind = perception::data_kind(dir);
  }
  const perception::FitOptions options = perception::choose_fit_options(choices, kind, task_named);
  return run_interruptibly([&](const std::atomic<bool>& stop) {
    const auto progress = [&](const std::string&, int, int) {
      if (stop) throw Stopped{};
    };
    SetPtr set = given;
    if (!set)
      set = std::make_shared<FeatureSet>(
          kind == perception::DataKind::features
              ? perception::load_feature_set(dir)
              : perception::recordings_as_features(perception::load_recording_set(dir), options,
                                                   progress));
    const perception::DatasetTask task = task_of(*set, g, hold_out.value_or("session"));
    std::vector<int> training(set->sessions.size());
    std::iota(training.begin(), training.end(), 0);
    if (sessions) training = *sessions;
    return std::make_shared<perception::ObservationModel>(
        perception::fit_observation_model(*set, task, training, options, progress));
  });
}

// The problem of a feature set and a model fitted on it, as `echoplan train --problem-out` writes
// it (exact beliefs, default planner settings), read back as a Problem.
ProblemPtr dataset_problem(const SetPtr& set, const perception::ObservationModel& model,
                           py::handle groups, const std::string& hold_out, double right,
                           double wrong, double sense, bool lookalike) {
  const perception::DatasetTask task = task_of(*set, groups, hold_out);
  const auto kind = perception::ObservationKind::labels;
  std::optional<double> lookalike_share;
  if (lookalike) lookalike_share = model.lookalike_share(kind);
  const auto data = loop::dataset_problem(task, model, {right, wrong, sense, {}},
                                          loop::default_uses(*set), kind, lookalike_share);
  std::ostringstream text;
  pomdp::BeliefSettings belief;
  belief.type = pomdp::BeliefSettings::Type::exact;
  pomdp::write_problem_yaml(text, data, belief, pomdp::PlannerDefaults{});
  return std::make_shared<pomdp::Problem>(
      pomdp::parse_problem(text.str(), set->root + "/problem.yaml"));
}

}  // namespace

void bind_feature_sets(py::module_& m) {
  bind_feature_set(m);
  m.def(
      "fit_observation_model",
      [](py::handle data, py::handle groups, std::optional<std::string> hold_out,
         std::optional<std::vector<int>> training_sessions, std::optional<std::string> cv,
         std::optional<std::string> classifier, std::optional<int> folds,
         std::optional<std::uint64_t> seed, std::optional<bool> reject,
         std::optional<double> reject_margin, std::optional<double> alpha,
         std::optional<std::string> table, std::optional<bool> fuse, std::optional<bool> temper,
         std::optional<int> sample_rate) {
        return fit(data, groups, std::move(hold_out), std::move(training_sessions),
                   perception::FitChoices{cv,
                                          classifier,
                                          table,
                                          folds,
                                          sample_rate,
                                          seed,
                                          reject,
                                          fuse,
                                          temper,
                                          reject_margin,
                                          alpha,
                                          {}});
      },
      py::arg("data"), py::kw_only(), py::arg("groups") = py::none(),
      py::arg("hold_out") = py::none(), py::arg("training_sessions") = py::none(),
      py::arg("cross_validation") = py::none(), py::arg("classifier") = py::none(),
      py::arg("folds") = py::none(), py::arg("seed") = py::none(), py::arg("reject") = py::none(),
      py::arg("reject_margin") = py::none(), py::arg("alpha") = py::none(),
      py::arg("table") = py::none(), py::arg("fuse") = py::none(), py::arg("temper") = py::none(),
      py::arg("sample_rate") = py::none(),
      "`echoplan train --data DIR` from Python: the one observation model fitted on a FeatureSet "
      "or on a data folder (a recordings tree or a feature set), with the command's options "
      "under their flags' names (None: the default, which follows cross_validation: 'performance' "
      "for a recordings tree, 'session' for a feature set or when groups or hold_out is given; "
      "docs/feature-sets.md). groups: a groups file path or a dict {object: group}; hold_out: "
      "'session' or 'object'; training_sessions: session indices (default: all). Ctrl-C stops "
      "it.");
  m.def("dataset_problem", &dataset_problem, py::arg("feature_set"), py::arg("model"),
        py::kw_only(), py::arg("groups") = py::none(), py::arg("hold_out") = "session",
        py::arg("right") = 10.0, py::arg("wrong") = -100.0, py::arg("sense") = -1.0,
        py::arg("lookalike") = false,
        "The problem of a feature set with a model fitted on it, as `echoplan train "
        "--problem-out` writes it: the classes, one sensing action per behaviour with its use "
        "limit, one sorting action per bin, the model's table, exact beliefs. lookalike=True adds "
        "a lookalike copy of every class ('<class>~lookalike': sounds like the class, is another) "
        "with its "
        "lookalike_share(), as an arm with `lookalike: true` plans.");
}

}  // namespace echoplan::python
