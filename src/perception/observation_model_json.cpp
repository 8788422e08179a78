#include "perception/observation_model_json.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

#include "common/error.h"
#include "common/file_io.h"
#include "common/json_fields.h"
#include "common/json_parse.h"
#include "perception/typicality.h"
#include "signal/series_features.h"

namespace echoplan::perception {

namespace {

namespace jf = json_fields;

constexpr const char* kFormatName = "echoplan-observation-model";

// The tables a lookalike share mixes, as the file names them.
const char* tables_name(bool untempered) { return untempered ? "untempered" : "tempered"; }

nlohmann::json analysis_json(const AnalysisSettings& analysis) {
  const auto& o = analysis.onset;
  return {{"sample_rate", analysis.sample_rate},
          {"preset", analysis.preset},
          {"silence_rms", analysis.silence_rms},
          {"onset",
           {{"pre_max", o.pre_max},
            {"post_max", o.post_max},
            {"pre_avg", o.pre_avg},
            {"post_avg", o.post_avg},
            {"delta", o.delta},
            {"wait", o.wait}}}};
}

}  // namespace

nlohmann::json fit_json(const ActionFit& fit) {
  return {{"modality_accuracy", fit.modality_accuracy},   {"modality_nll", fit.modality_nll},
          {"fused_accuracy", fit.fused_accuracy},         {"fused_nll", fit.fused_nll},
          {"shrinkage_strength", fit.shrinkage_strength}, {"temper", fit.temper},
          {"graded_temper", fit.graded_temper},           {"level_temper", fit.level_temper}};
}

nlohmann::json modalities_json(const std::vector<ModalityModel>& modalities) {
  nlohmann::json list = nlohmann::json::array();
  for (const ModalityModel& m : modalities) {
    const ClipExtractor* extractor = m.classifier->extractor();
    nlohmann::json entry = {
        {"name", m.name},
        {"extractor", extractor ? nlohmann::json(extractor->name) : nlohmann::json()},
        {"classifier", m.classifier->save()}};
    if (!m.series.empty()) entry["series"] = m.series;
    list.push_back(std::move(entry));
  }
  return list;
}

nlohmann::json observation_model_to_json(const ObservationModel& model) {
  nlohmann::json per_action = nlohmann::json::object();
  for (const auto& action : model.actions()) {
    const ActionCalibration& c = model.calibration(action);
    per_action[action] = {
        {"modalities", modalities_json(model.modalities(action))},
        {"weights", model.weights(action)},
        {"temperature", c.temperature},
        {"reject_threshold",
         model.reject() ? nlohmann::json(c.reject_threshold) : nlohmann::json(nullptr)},
        {"symbols", c.confusion.symbols},
        {"confusion", c.confusion.counts},
        {"table", c.table},
    };
    if (c.fit) per_action[action]["fit"] = fit_json(*c.fit);
    const auto grades_json = [](const GradeCalibration& g, const Table& table) {
      return nlohmann::json{{"edges", g.edges},
                            {"given_right", g.given_right},
                            {"given_wrong", g.given_wrong},
                            {"table", table}};
    };
    if (c.grades) per_action[action]["grades"] = grades_json(*c.grades, c.graded_table);
    if (c.level_grades)
      per_action[action]["level_grades"] = grades_json(*c.level_grades, c.level_table);
  }
  return {{"format", kFormatName},
          {"version", kModelFormatVersion},
          {"analysis", analysis_json(model.analysis())},
          {"classifier", model.classifier_name()},
          {"classes", model.classes()},
          {"actions", model.actions()},
          {"reject", model.reject()},
          {"dirichlet_alpha", model.dirichlet_alpha()},
          {"table_estimate", table_estimate_name(model.table_estimate())},
          {"lookalike_share",
           {{"labels", model.lookalike_share(ObservationKind::labels)},
            {"graded", model.lookalike_share(ObservationKind::graded)}}},
          {"lookalike_tables",
           {{"labels", tables_name(model.lookalikes_untempered(ObservationKind::labels))},
            {"graded", tables_name(model.lookalikes_untempered(ObservationKind::graded))}}},
          {"per_action", per_action}};
}

namespace {

// The file's version: 1 (one audio classifier per action) or kModelFormatVersion.
int check_format_and_version(const nlohmann::json& doc, const std::string& source) {
  if (!doc.is_object())
    throw InputError(source, 0, "not an observation model: expected a JSON object");
  if (!doc.contains("format") || !doc["format"].is_string() || doc["format"] != kFormatName)
    throw InputError(
        source, 0,
        fmt::format("format: not an observation model (expected \"format\": \"{}\")", kFormatName));
  const int version = jf::integer(jf::member(doc, "version", "", source), 0,
                                  std::numeric_limits<int>::max(), "version", source);
  if (version < 1 || version > kModelFormatVersion)
    throw InputError(
        source, 0,
        fmt::format(
            "version: model format version {} is not supported (this build reads versions 1 to "
            "{}); retrain with `echoplan train --data DIR --out MODEL`",
            version, kModelFormatVersion));
  return version;
}

// The analysis settings, checked by building an analyser with them.
AnalysisSettings read_analysis(const nlohmann::json& doc, const std::string& source) {
  const auto& a = jf::member(doc, "analysis", "", source);
  AnalysisSettings s;
  s.sample_rate = jf::integer(jf::member(a, "sample_rate", "analysis", source), 1000, 384000,
                              "analysis.sample_rate", source);
  s.preset = jf::string(jf::member(a, "preset", "analysis", source), "analysis.preset", source);
  s.silence_rms =
      jf::number(jf::member(a, "silence_rms", "analysis", source), "analysis.silence_rms", source);
  const auto& o = jf::member(a, "onset", "analysis", source);
  auto frames = [&](const char* key) {
    return jf::integer(jf::member(o, key, "analysis.onset", source), 0, 10000,
                       std::string("analysis.onset.") + key, source);
  };
  s.onset.pre_max = frames("pre_max");
  s.onset.post_max = frames("post_max");
  s.onset.pre_avg = frames("pre_avg");
  s.onset.post_avg = frames("post_avg");
  s.onset.wait = frames("wait");
  s.onset.delta =
      jf::number(jf::member(o, "delta", "analysis.onset", source), "analysis.onset.delta", source);
  if (s.onset.delta < 0.0) throw InputError(source, 0, "analysis.onset.delta: must be >= 0");
  try {
    const ClipAnalyzer check(s);
  } catch (const InputError& e) {
    throw InputError(source, 0, "analysis: " + e.problem());
  }
  return s;
}

// Everything but the per-action entries; the classifier name is checked against the registry,
// and an old name (classifier_aliases()) becomes the current one.
// A share of objects `key` (`lookalike_share`): {labels, graded}, each in [0, kLargestShare].
// Absent in files written before such objects were modelled: none. (Files that also hold an
// `atypical_share`, written when the class-blind copies existed, read as ever: it is ignored.)
void read_shares(const nlohmann::json& doc, const char* key, const std::string& source,
                 double& labels, double& graded) {
  if (!doc.contains(key)) return;
  const auto& shares = doc[key];
  const auto share = [&](const char* kind) {
    const std::string where = std::string(key) + "." + kind;
    const double rho = jf::number(jf::member(shares, kind, key, source), where, source);
    if (!(rho >= 0.0 && rho <= kLargestShare))
      throw InputError(source, 0,
                       fmt::format("{}: {} is not in [0, {}]", where, rho, kLargestShare));
    return rho;
  };
  labels = share("labels");
  graded = share("graded");
}

// Which tables the lookalike shares mix (`lookalike_tables`): {labels, graded}, each "tempered"
// or "untempered". Absent in files written before the choice existed: tempered.
void read_share_tables(const nlohmann::json& doc, const std::string& source, bool& labels,
                       bool& graded) {
  const char* key = "lookalike_tables";
  if (!doc.contains(key)) return;
  const auto untempered = [&](const char* kind) {
    const std::string where = std::string(key) + "." + kind;
    const std::string name = jf::string(jf::member(doc[key], kind, key, source), where, source);
    if (name != tables_name(true) && name != tables_name(false))
      throw InputError(source, 0,
                       fmt::format("{}: '{}' is not one of: tempered, untempered", where, name));
    return name == tables_name(true);
  };
  labels = untempered("labels");
  graded = untempered("graded");
}

ModelDescription read_description(const nlohmann::json& doc, const std::string& source) {
  ModelDescription d;
  d.analysis = read_analysis(doc, source);
  const std::string classifier =
      jf::string(jf::member(doc, "classifier", "", source), "classifier", source);
  try {
    d.classifier_name = is_audio_preset(classifier) ? make_classifier(classifier)->name()
                                                    : make_row_classifier(classifier)->name();
  } catch (const InputError& e) {
    throw InputError(source, 0,
                     fmt::format("classifier: '{}' is neither an audio preset ({}) nor a row "
                                 "classifier ({})",
                                 classifier, fmt::join(classifier_names(), ", "),
                                 fmt::join(row_classifier_names(), ", ")));
  }
  read_shares(doc, "lookalike_share", source, d.lookalike_share, d.graded_lookalike_share);
  read_share_tables(doc, source, d.lookalike_untempered, d.graded_lookalike_untempered);
  d.classes = jf::names(jf::member(doc, "classes", "", source), -1, "classes", source);
  if (d.classes.size() < 2)
    throw InputError(source, 0, "classes: a model needs at least two classes");
  for (const auto& c : d.classes)
    if (c == kUnknownSymbol)
      throw InputError(source, 0, "classes: 'unknown' is reserved for rejected clips");
  d.actions = jf::names(jf::member(doc, "actions", "", source), -1, "actions", source);
  if (d.actions.empty()) throw InputError(source, 0, "actions: a model needs at least one action");
  d.reject = jf::boolean(jf::member(doc, "reject", "", source), "reject", source);
  d.dirichlet_alpha =
      jf::number(jf::member(doc, "dirichlet_alpha", "", source), "dirichlet_alpha", source);
  if (d.dirichlet_alpha < 0.0) throw InputError(source, 0, "dirichlet_alpha: must be >= 0");
  // Absent in files written before the option existed: those tables were counts.
  if (doc.contains("table_estimate")) {
    const std::string name = jf::string(doc["table_estimate"], "table_estimate", source);
    try {
      d.table_estimate = parse_table_estimate(name);
    } catch (const InputError& e) {
      throw InputError(source, 0, "table_estimate: " + e.problem());
    }
  }
  return d;
}

// One action's entry is read at the dotted path `where` ("per_action.strike") of `source`.
struct ActionEntry {
  const nlohmann::json& json;
  const std::string& where;
  const std::string& source;
};

// A fitted classifier read from `fit` at `where`, checked to have the model's classes.
std::shared_ptr<const Classifier> read_fit(std::unique_ptr<Classifier> classifier,
                                           const nlohmann::json& fit, const std::string& where,
                                           const ActionEntry& e, const ModelDescription& d) {
  try {
    classifier->load(fit, e.source);
  } catch (const InputError& error) {
    throw InputError(e.source, 0, where + "." + error.problem());
  }
  if (classifier->num_classes() != static_cast<int>(d.classes.size()))
    throw InputError(e.source, 0,
                     fmt::format("{}.classifier: fitted for {} classes, the model has {}", where,
                                 classifier->num_classes(), d.classes.size()));
  return classifier;
}

// Version 1: one audio classifier per action, `classifier` beside the calibration.
void read_v1_modality(const ActionEntry& e, const ModelDescription& d, ActionModel& a) {
  if (!is_audio_preset(d.classifier_name))
    throw InputError(e.source, 0, "classifier: version 1 files hold audio presets only");
  a.modalities.push_back(
      {"audio", read_fit(make_classifier(d.classifier_name),
                         jf::member(e.json, "classifier", e.where, e.source), e.where, e, d)});
  a.weights = {1.0};
}

// One modality of a version 2 entry: its name, extractor and fit.
ModalityModel read_modality(const nlohmann::json& entry, const std::string& where,
                            const ActionEntry& e, const ModelDescription& d) {
  ModalityModel m;
  m.name = jf::string(jf::member(entry, "name", where, e.source), where + ".name", e.source);
  const auto& extractor = jf::member(entry, "extractor", where, e.source);
  const std::string extractor_name =
      extractor.is_null() ? "" : jf::string(extractor, where + ".extractor", e.source);
  std::unique_ptr<Classifier> classifier;
  try {
    if (entry.contains("series")) {
      if (!extractor_name.empty()) throw InputError("a modality of series has no clip extractor");
      classifier = make_series_classifier(d.classifier_name);
    } else if (is_audio_preset(d.classifier_name)) {
      classifier = make_classifier(d.classifier_name);
      if (classifier->extractor()->name != extractor_name)
        throw InputError(fmt::format("the '{}' preset computes its rows with '{}'",
                                     d.classifier_name, classifier->extractor()->name));
    } else {
      classifier = make_modality_classifier(d.classifier_name, extractor_name);
    }
  } catch (const InputError& error) {
    throw InputError(e.source, 0, where + ".extractor: " + error.problem());
  }
  m.classifier = read_fit(std::move(classifier), jf::member(entry, "classifier", where, e.source),
                          where, e, d);
  if (entry.contains("series")) {
    m.series = jf::string(entry["series"], where + ".series", e.source);
    try {
      m.series = signal::parse_series_features(m.series).spec();
    } catch (const InputError& error) {
      throw InputError(e.source, 0, where + ".series: " + error.problem());
    }
  }
  return m;
}

void read_modalities(const ActionEntry& e, const ModelDescription& d, ActionModel& a) {
  const auto& list = jf::member(e.json, "modalities", e.where, e.source);
  if (!list.is_array() || list.empty() || list.size() > 1000)
    throw InputError(e.source, 0, e.where + ".modalities: expected 1 to 1000 modalities");
  for (std::size_t m = 0; m < list.size(); ++m)
    a.modalities.push_back(
        read_modality(list[m], fmt::format("{}.modalities[{}]", e.where, m), e, d));
  a.weights = jf::numbers(jf::member(e.json, "weights", e.where, e.source),
                          static_cast<long long>(list.size()), e.where + ".weights", e.source);
  for (double w : a.weights)
    if (w < 0.0) throw InputError(e.source, 0, e.where + ".weights: must be >= 0");
  if (d.reject && list.size() != 1)
    throw InputError(e.source, 0, e.where + ".modalities: the reject option needs one modality");
}

std::optional<ActionFit> read_fit_report(const ActionEntry& e, std::size_t modalities) {
  if (!e.json.contains("fit")) return std::nullopt;
  const auto& j = e.json["fit"];
  const std::string where = e.where + ".fit";
  ActionFit fit;
  const auto n = static_cast<long long>(modalities);
  fit.modality_accuracy = jf::numbers(jf::member(j, "modality_accuracy", where, e.source), n,
                                      where + ".modality_accuracy", e.source);
  fit.modality_nll = jf::numbers(jf::member(j, "modality_nll", where, e.source), n,
                                 where + ".modality_nll", e.source);
  const auto number = [&](const char* key) {
    return jf::number(jf::member(j, key, where, e.source), where + "." + key, e.source);
  };
  fit.fused_accuracy = number("fused_accuracy");
  fit.fused_nll = number("fused_nll");
  fit.shrinkage_strength = number("shrinkage_strength");
  fit.temper = number("temper");
  // Absent in files written before graded observations.
  if (j.contains("graded_temper")) fit.graded_temper = number("graded_temper");
  if (j.contains("level_temper")) fit.level_temper = number("level_temper");
  return fit;
}

double read_reject_threshold(const ActionEntry& e, bool reject) {
  const auto& threshold = jf::member(e.json, "reject_threshold", e.where, e.source);
  if (!reject) {
    if (!threshold.is_null())
      throw InputError(e.source, 0,
                       e.where + ".reject_threshold: must be null when reject is false");
    return std::numeric_limits<double>::infinity();
  }
  const double value = jf::number(threshold, e.where + ".reject_threshold", e.source);
  if (value < 0.0) throw InputError(e.source, 0, e.where + ".reject_threshold: must be >= 0");
  return value;
}

ConfusionMatrix read_confusion(const ActionEntry& e, const ModelDescription& d,
                               const std::vector<std::string>& symbols) {
  const auto counts = jf::matrix(
      jf::member(e.json, "confusion", e.where, e.source), static_cast<long long>(d.classes.size()),
      static_cast<long long>(symbols.size()), e.where + ".confusion", e.source);
  ConfusionMatrix confusion = ConfusionMatrix::zeros(d.classes, symbols);
  for (std::size_t i = 0; i < counts.size(); ++i) {
    if (counts[i] < 0 || counts[i] > 1e9 || counts[i] != std::floor(counts[i]))
      throw InputError(e.source, 0, e.where + ".confusion: counts must be whole numbers >= 0");
    confusion.counts[i / symbols.size()][i % symbols.size()] = static_cast<int>(counts[i]);
  }
  return confusion;
}

// The observation table `e.json`.table: one probability row per class, each summing to 1.
std::vector<std::vector<double>> read_table(const ActionEntry& e, std::size_t rows,
                                            std::size_t cols) {
  const auto table =
      jf::matrix(jf::member(e.json, "table", e.where, e.source), static_cast<long long>(rows),
                 static_cast<long long>(cols), e.where + ".table", e.source);
  std::vector<std::vector<double>> out;
  for (std::size_t k = 0; k < rows; ++k) {
    std::vector<double> row(table.begin() + static_cast<std::ptrdiff_t>(k * cols),
                            table.begin() + static_cast<std::ptrdiff_t>((k + 1) * cols));
    double sum = 0.0;
    for (double p : row) {
      if (p < 0.0 || p > 1.0)
        throw InputError(e.source, 0,
                         fmt::format("{}.table[{}]: probabilities must be in [0, 1]", e.where, k));
      sum += p;
    }
    if (std::abs(sum - 1.0) > 1e-6)
      throw InputError(
          e.source, 0,
          fmt::format("{}.table[{}]: probabilities sum to {}, not 1", e.where, k, sum));
    out.push_back(std::move(row));
  }
  return out;
}

// A probability distribution over the grades at `where`.
std::vector<double> read_grade_distribution(const ActionEntry& e, const char* key) {
  const std::string where = e.where + "." + key;
  std::vector<double> p =
      jf::numbers(jf::member(e.json, key, e.where, e.source), kGrades, where, e.source);
  double sum = 0.0;
  for (double x : p) {
    if (!(x >= 0.0 && x <= 1.0))
      throw InputError(e.source, 0, where + ": probabilities must be in [0, 1]");
    sum += x;
  }
  if (std::abs(sum - 1.0) > 1e-6)
    throw InputError(e.source, 0, fmt::format("{}: probabilities sum to {}, not 1", where, sum));
  return p;
}

// The optional `grades` entry (observation_grades.h; absent in files written before them) or
// `level_grades` (kind levels; absent for a model trained on features without levels).
void read_grades(const ActionEntry& action, const ModelDescription& d, ObservationKind kind,
                 std::optional<GradeCalibration>& out, Table& table) {
  const char* key = kind == ObservationKind::levels ? "level_grades" : "grades";
  if (!action.json.contains(key)) return;
  const std::string where = action.where + "." + key;
  const ActionEntry e{action.json[key], where, action.source};
  GradeCalibration grades;
  grades.edges = jf::numbers(jf::member(e.json, "edges", where, e.source), kGrades - 1,
                             where + ".edges", e.source);
  if (!std::is_sorted(grades.edges.begin(), grades.edges.end()))
    throw InputError(e.source, 0, where + ".edges: must be ascending");
  grades.given_right = read_grade_distribution(e, "given_right");
  grades.given_wrong = read_grade_distribution(e, "given_wrong");
  table = read_table(e, d.classes.size(), graded_symbols(d.classes, d.reject, kind).size());
  out = std::move(grades);
}

ActionModel read_action(const ActionEntry& e, const std::string& action, const ModelDescription& d,
                        int version) {
  const std::vector<std::string> symbols = observation_symbols(d);
  ActionModel a;
  a.calibration.action = action;
  if (version == 1)
    read_v1_modality(e, d, a);
  else
    read_modalities(e, d, a);
  a.calibration.temperature = jf::number(jf::member(e.json, "temperature", e.where, e.source),
                                         e.where + ".temperature", e.source);
  if (!(a.calibration.temperature > 0.0))
    throw InputError(e.source, 0, e.where + ".temperature: must be positive");
  a.calibration.reject_threshold = read_reject_threshold(e, d.reject);
  const auto listed =
      jf::names(jf::member(e.json, "symbols", e.where, e.source),
                static_cast<long long>(symbols.size()), e.where + ".symbols", e.source);
  if (listed != symbols)
    throw InputError(e.source, 0,
                     fmt::format("{}.symbols: expected [{}] (the classes{})", e.where,
                                 fmt::join(symbols, ", "), d.reject ? " and unknown" : ""));
  a.calibration.confusion = read_confusion(e, d, symbols);
  a.calibration.table = read_table(e, d.classes.size(), symbols.size());
  a.calibration.fit = read_fit_report(e, a.modalities.size());
  ActionCalibration& c = a.calibration;
  read_grades(e, d, ObservationKind::graded, c.grades, c.graded_table);
  read_grades(e, d, ObservationKind::levels, c.level_grades, c.level_table);
  return a;
}

}  // namespace

ObservationModel observation_model_from_json(const nlohmann::json& doc, const std::string& source) {
  const int version = check_format_and_version(doc, source);
  ModelDescription description = read_description(doc, source);
  const auto& per_action = jf::member(doc, "per_action", "", source);
  if (!per_action.is_object() || per_action.size() != description.actions.size())
    throw InputError(source, 0,
                     fmt::format("per_action: expected an object with one entry per action ({})",
                                 description.actions.size()));
  std::vector<ActionModel> actions;
  for (const auto& action : description.actions) {
    const std::string where = "per_action." + action;
    const auto& entry = jf::member(per_action, action, "per_action", source);
    actions.push_back(read_action({entry, where, source}, action, description, version));
  }
  return ObservationModel(std::move(description), std::move(actions));
}

ObservationModel load_observation_model(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, "is a folder; expected a model file (JSON)");
  return parse_observation_model(read_text_file(path, "model file"), path);
}

ObservationModel parse_observation_model(const std::string& text, const std::string& source) {
  nlohmann::json doc;
  try {
    doc = parse_json(text, source);
  } catch (const nlohmann::json::exception& e) {
    // parse_error for broken syntax, out_of_range for a number beyond double: both a corrupt file.
    throw InputError(
        source, 0,
        fmt::format("not a valid JSON model file (truncated or corrupt?): {}", e.what()));
  }
  try {
    return observation_model_from_json(doc, source);
  } catch (const nlohmann::json::exception& e) {
    // A shape the checks above did not anticipate: still an input error, never a crash.
    throw InputError(source, 0, fmt::format("malformed model: {}", e.what()));
  }
}

void save_observation_model(const ObservationModel& model, const std::string& path) {
  write_file_atomically(path, observation_model_to_json(model).dump() + '\n');
}

}  // namespace echoplan::perception
