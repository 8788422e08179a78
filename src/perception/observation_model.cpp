#include "perception/observation_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>

#include "common/error.h"
#include "common/file_io.h"
#include "common/rng.h"
#include "perception/json_fields.h"

namespace echoplan::perception {

namespace {

constexpr const char* kFormatName = "echoplan-observation-model";

struct PerAction {
  std::unique_ptr<Classifier> classifier;
  ActionCalibration calibration;
};

std::size_t argmax(const std::vector<double>& v) {
  return static_cast<std::size_t>(std::max_element(v.begin(), v.end()) - v.begin());
}

}  // namespace

struct ObservationModel::Impl {
  AnalysisSettings analysis;
  std::string classifier_name;
  std::vector<std::string> classes;
  std::vector<std::string> actions;
  bool reject = true;
  double dirichlet_alpha = 1.0;
  TableEstimate table_estimate = TableEstimate::counts;
  std::vector<PerAction> per_action;  // actions order

  // classify(clip) analyses into one reused buffer; the mutex makes classify() safe to call from
  // threads.
  mutable std::mutex mutex;
  mutable std::unique_ptr<ClipAnalyzer> analyzer;
  mutable ClipAnalysis scratch;

  const PerAction& of(const std::string& action) const {
    const auto it = std::find(actions.begin(), actions.end(), action);
    if (it == actions.end())
      throw InputError(fmt::format("action '{}' is not in the model (it was trained for: {})",
                                   action, fmt::join(actions, ", ")));
    return per_action[static_cast<std::size_t>(it - actions.begin())];
  }
};

ObservationModel::ObservationModel() : impl_(std::make_unique<Impl>()) {}
ObservationModel::~ObservationModel() = default;
ObservationModel::ObservationModel(ObservationModel&&) noexcept = default;
ObservationModel& ObservationModel::operator=(ObservationModel&&) noexcept = default;

const AnalysisSettings& ObservationModel::analysis() const { return impl_->analysis; }
const std::string& ObservationModel::classifier_name() const { return impl_->classifier_name; }
const std::vector<std::string>& ObservationModel::classes() const { return impl_->classes; }
const std::vector<std::string>& ObservationModel::actions() const { return impl_->actions; }
bool ObservationModel::reject() const { return impl_->reject; }
TableEstimate ObservationModel::table_estimate() const { return impl_->table_estimate; }

const char* table_estimate_name(TableEstimate estimate) {
  return estimate == TableEstimate::soft ? "soft" : "counts";
}

const std::vector<std::string>& table_estimate_names() {
  static const std::vector<std::string> names{"counts", "soft"};
  return names;
}

TableEstimate parse_table_estimate(const std::string& name) {
  if (name == "counts") return TableEstimate::counts;
  if (name == "soft") return TableEstimate::soft;
  throw InputError(fmt::format("table estimate '{}' is not one of: {}", name,
                               fmt::join(table_estimate_names(), ", ")));
}

std::vector<std::string> ObservationModel::observation_symbols() const {
  std::vector<std::string> symbols = impl_->classes;
  if (impl_->reject) symbols.emplace_back(kUnknownSymbol);
  return symbols;
}

const ActionCalibration& ObservationModel::calibration(const std::string& action) const {
  return impl_->of(action).calibration;
}

const std::vector<std::vector<double>>& ObservationModel::observation_table(
    const std::string& action) const {
  return calibration(action).table;
}

Prediction ObservationModel::classify(const audio::AudioClip& clip,
                                      const std::string& action) const {
  impl_->of(action);  // an unknown action is reported before any audio work
  const std::lock_guard lock(impl_->mutex);
  if (!impl_->analyzer) impl_->analyzer = std::make_unique<ClipAnalyzer>(impl_->analysis);
  impl_->analyzer->analyse(clip, "clip", impl_->scratch);
  return classify(impl_->scratch, action);
}

Prediction ObservationModel::classify(const ClipAnalysis& analysed,
                                      const std::string& action) const {
  const PerAction& a = impl_->of(action);
  const ClassScores scores = a.classifier->score_clip(analysed);
  Prediction p;
  p.action = action;
  p.probabilities = softmax(scores.log_scores, a.calibration.temperature);
  p.best_class = static_cast<int>(argmax(scores.log_scores));
  p.distance = *std::min_element(scores.distances.begin(), scores.distances.end());
  p.reject_threshold = a.calibration.reject_threshold;
  p.unknown = impl_->reject && p.distance > a.calibration.reject_threshold;
  p.symbol = p.unknown ? static_cast<int>(impl_->classes.size()) : p.best_class;
  p.label = p.unknown ? kUnknownSymbol : impl_->classes[static_cast<std::size_t>(p.best_class)];
  return p;
}

// ---------------------------------------------------------------------------------------------------------
// Training

namespace {

void check_options(const TrainOptions& o) {
  if (!(o.reject_margin >= 1.0 && o.reject_margin <= 100.0))
    throw InputError(fmt::format("reject margin {} is outside 1..100", o.reject_margin));
  if (!(o.dirichlet_alpha >= 0.0 && o.dirichlet_alpha <= 1000.0))
    throw InputError(fmt::format("Dirichlet alpha {} is outside 0..1000", o.dirichlet_alpha));
  if (o.folds < 0 || o.folds == 1)
    throw InputError(fmt::format("folds = {}: use 0 (leave-one-out) or at least 2", o.folds));
}

// Fold of each example: leave-one-out, or stratified k folds (each class dealt round-robin after a
// shuffle).
std::vector<int> assign_folds(std::span<const int> labels, int num_classes, int folds,
                              std::uint64_t seed, const std::string& action) {
  std::vector<int> fold(labels.size());
  if (folds == 0) {
    std::iota(fold.begin(), fold.end(), 0);
    return fold;
  }
  Rng rng(
      derive_seed(seed, {0x666f6c64, std::hash<std::string>{}(action)}));  // stream "fold", action
  for (int k = 0; k < num_classes; ++k) {
    std::vector<std::size_t> members;
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (labels[i] == k) members.push_back(i);
    for (std::size_t i = members.size(); i > 1; --i)
      std::swap(members[i - 1],
                members[static_cast<std::size_t>(uniform01(rng) * static_cast<double>(i))]);
    for (std::size_t j = 0; j < members.size(); ++j)
      fold[members[j]] = static_cast<int>(j % static_cast<std::size_t>(folds));
  }
  return fold;
}

}  // namespace

ObservationModel train_observation_model(const RecordingSet& set, const TrainOptions& options,
                                         const ProgressFn& progress) {
  check_options(options);
  ObservationModel model;
  ObservationModel::Impl& m = *model.impl_;
  const auto prototype = make_classifier(options.classifier);
  m.analysis = options.analysis;
  m.classifier_name = prototype->name();
  m.classes = set.objects;
  m.actions = set.actions;
  m.reject = options.reject;
  m.dirichlet_alpha = options.dirichlet_alpha;
  m.table_estimate = options.table;
  if (m.classes.size() < 2)
    throw InputError(set.root, 0,
                     fmt::format("need recordings of at least two objects to train, found {}",
                                 m.classes.size()));

  // Every recording is analysed and embedded once; cross-validation refits on the embeddings.
  ClipAnalyzer analyzer(options.analysis);
  ClipAnalysis analysis;
  std::vector<std::vector<double>> embeddings(set.recordings.size());
  for (std::size_t i = 0; i < set.recordings.size(); ++i) {
    const auto& r = set.recordings[i];
    analyzer.analyse(read_recording(r.path, options.analysis.sample_rate), r.path, analysis);
    embeddings[i] = prototype->embed(analysis);
    if (progress)
      progress("analyse", static_cast<int>(i + 1), static_cast<int>(set.recordings.size()));
  }

  const std::vector<std::string> symbols = model.observation_symbols();
  const int num_classes = static_cast<int>(m.classes.size());
  for (const auto& action : m.actions) {
    std::vector<std::vector<double>> examples;
    std::vector<int> labels;
    std::vector<int> per_class(m.classes.size(), 0);
    for (std::size_t i = 0; i < set.recordings.size(); ++i) {
      if (set.recordings[i].action != action) continue;
      examples.push_back(embeddings[i]);
      labels.push_back(set.object_index(set.recordings[i].object));
      ++per_class[static_cast<std::size_t>(labels.back())];
    }
    for (std::size_t k = 0; k < per_class.size(); ++k)
      if (per_class[k] < 2)
        throw InputError(
            (std::filesystem::path(set.root) / m.classes[k] / action).string(), 0,
            "cross-validation needs at least 2 recordings per (object, action), found 1");

    // Held-out scores of every example.
    const std::vector<int> fold =
        assign_folds(labels, num_classes, options.folds, options.seed, action);
    const int num_folds = options.folds == 0 ? static_cast<int>(examples.size()) : options.folds;
    std::vector<std::vector<double>> held_log_scores(examples.size());
    std::vector<double> held_distance(examples.size());
    std::vector<int> held_best(examples.size());
    for (int f = 0; f < num_folds; ++f) {
      std::vector<std::vector<double>> train;
      std::vector<int> train_labels;
      std::vector<std::size_t> test;
      for (std::size_t i = 0; i < examples.size(); ++i) {
        if (fold[i] == f) {
          test.push_back(i);
        } else {
          train.push_back(examples[i]);
          train_labels.push_back(labels[i]);
        }
      }
      if (test.empty()) continue;
      auto classifier = prototype->clone_unfitted();
      classifier->fit(train, train_labels, num_classes);
      for (std::size_t i : test) {
        const ClassScores s = classifier->score(examples[i]);
        held_best[i] = static_cast<int>(argmax(s.log_scores));
        held_distance[i] = *std::min_element(s.distances.begin(), s.distances.end());
        held_log_scores[i] = s.log_scores;
      }
      if (progress) progress("cross-validate " + action, f + 1, num_folds);
    }

    PerAction a;
    a.calibration.action = action;
    // Label smoothing matching the Dirichlet prior's share of an average row keeps the
    // probabilities no more confident than the table the planner gets.
    const double mean_count = static_cast<double>(examples.size()) / num_classes;
    const double prior_mass = options.dirichlet_alpha * num_classes;
    a.calibration.temperature =
        fit_temperature(held_log_scores, labels, prior_mass / (mean_count + prior_mass));
    a.calibration.reject_threshold = std::numeric_limits<double>::infinity();
    if (options.reject) {
      double largest_correct = 0.0, largest = 0.0;
      for (std::size_t i = 0; i < examples.size(); ++i) {
        largest = std::max(largest, held_distance[i]);
        if (held_best[i] == labels[i])
          largest_correct = std::max(largest_correct, held_distance[i]);
      }
      a.calibration.reject_threshold =
          options.reject_margin * (largest_correct > 0.0 ? largest_correct : largest);
    }
    a.calibration.confusion = ConfusionMatrix::zeros(m.classes, symbols);
    std::vector<bool> rejected(examples.size());
    for (std::size_t i = 0; i < examples.size(); ++i) {
      rejected[i] = options.reject && held_distance[i] > a.calibration.reject_threshold;
      ++a.calibration.confusion.counts[static_cast<std::size_t>(
          labels[i])][rejected[i] ? m.classes.size() : static_cast<std::size_t>(held_best[i])];
    }
    a.calibration.table =
        options.table == TableEstimate::soft
            ? dirichlet_smoothed(
                  soft_confusion(held_log_scores, labels, rejected, num_classes,
                                 static_cast<int>(symbols.size()), a.calibration.temperature),
                  m.classes, options.dirichlet_alpha)
            : dirichlet_smoothed(a.calibration.confusion, options.dirichlet_alpha);
    a.classifier = prototype->clone_unfitted();
    a.classifier->fit(examples, labels, num_classes);
    m.per_action.push_back(std::move(a));
  }
  return model;
}

// ---------------------------------------------------------------------------------------------------------
// The model file

nlohmann::json ObservationModel::to_json() const {
  const Impl& m = *impl_;
  const auto& o = m.analysis.onset;
  nlohmann::json per_action = nlohmann::json::object();
  for (const auto& a : m.per_action) {
    const auto& c = a.calibration;
    per_action[c.action] = {
        {"classifier", a.classifier->save()},
        {"temperature", c.temperature},
        {"reject_threshold",
         m.reject ? nlohmann::json(c.reject_threshold) : nlohmann::json(nullptr)},
        {"symbols", c.confusion.symbols},
        {"confusion", c.confusion.counts},
        {"table", c.table},
    };
  }
  return {{"format", kFormatName},
          {"version", kModelFormatVersion},
          {"analysis",
           {{"sample_rate", m.analysis.sample_rate},
            {"preset", m.analysis.preset},
            {"silence_rms", m.analysis.silence_rms},
            {"onset",
             {{"pre_max", o.pre_max},
              {"post_max", o.post_max},
              {"pre_avg", o.pre_avg},
              {"post_avg", o.post_avg},
              {"delta", o.delta},
              {"wait", o.wait}}}}},
          {"classifier", m.classifier_name},
          {"classes", m.classes},
          {"actions", m.actions},
          {"reject", m.reject},
          {"dirichlet_alpha", m.dirichlet_alpha},
          {"table_estimate", table_estimate_name(m.table_estimate)},
          {"per_action", per_action}};
}

namespace {

AnalysisSettings read_analysis(const nlohmann::json& doc, const std::string& source) {
  namespace jf = json_fields;
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
  return s;
}

}  // namespace

ObservationModel ObservationModel::from_json(const nlohmann::json& doc, const std::string& source) {
  namespace jf = json_fields;
  if (!doc.is_object())
    throw InputError(source, 0, "not an observation model: expected a JSON object");
  if (!doc.contains("format") || !doc["format"].is_string() || doc["format"] != kFormatName)
    throw InputError(
        source, 0,
        fmt::format("format: not an observation model (expected \"format\": \"{}\")", kFormatName));
  const int version = jf::integer(jf::member(doc, "version", "", source), 0,
                                  std::numeric_limits<int>::max(), "version", source);
  if (version != kModelFormatVersion)
    throw InputError(
        source, 0,
        fmt::format(
            "version: model format version {} is not supported (this build reads version {}); "
            "retrain with `echoplan train`",
            version, kModelFormatVersion));
  ObservationModel model;
  Impl& m = *model.impl_;
  m.analysis = read_analysis(doc, source);
  try {
    m.analyzer = std::make_unique<ClipAnalyzer>(m.analysis);
  } catch (const InputError& e) {
    throw InputError(source, 0, "analysis: " + e.problem());
  }
  m.classifier_name = jf::string(jf::member(doc, "classifier", "", source), "classifier", source);
  std::unique_ptr<Classifier> prototype;
  try {
    prototype = make_classifier(m.classifier_name);
  } catch (const InputError& e) {
    throw InputError(source, 0, "classifier: " + e.problem());
  }
  m.classes = jf::names(jf::member(doc, "classes", "", source), -1, "classes", source);
  if (m.classes.size() < 2)
    throw InputError(source, 0, "classes: a model needs at least two classes");
  for (const auto& c : m.classes)
    if (c == kUnknownSymbol)
      throw InputError(source, 0, "classes: 'unknown' is reserved for rejected clips");
  m.actions = jf::names(jf::member(doc, "actions", "", source), -1, "actions", source);
  if (m.actions.empty()) throw InputError(source, 0, "actions: a model needs at least one action");
  m.reject = jf::boolean(jf::member(doc, "reject", "", source), "reject", source);
  m.dirichlet_alpha =
      jf::number(jf::member(doc, "dirichlet_alpha", "", source), "dirichlet_alpha", source);
  if (m.dirichlet_alpha < 0.0) throw InputError(source, 0, "dirichlet_alpha: must be >= 0");
  if (doc.contains("table_estimate")) {
    const std::string name = jf::string(doc["table_estimate"], "table_estimate", source);
    try {
      m.table_estimate = parse_table_estimate(name);
    } catch (const InputError& e) {
      throw InputError(source, 0, "table_estimate: " + e.problem());
    }
  }
  const std::vector<std::string> symbols = model.observation_symbols();
  const auto& per_action = jf::member(doc, "per_action", "", source);
  if (!per_action.is_object() || per_action.size() != m.actions.size())
    throw InputError(source, 0,
                     fmt::format("per_action: expected an object with one entry per action ({})",
                                 m.actions.size()));
  const auto rows = static_cast<long long>(m.classes.size());
  const auto cols = static_cast<long long>(symbols.size());
  for (const auto& action : m.actions) {
    const std::string where = "per_action." + action;
    const auto& entry = jf::member(per_action, action, "per_action", source);
    PerAction a;
    a.calibration.action = action;
    a.classifier = prototype->clone_unfitted();
    try {
      a.classifier->load(jf::member(entry, "classifier", where, source), source);
    } catch (const InputError& e) {
      throw InputError(source, 0, where + "." + e.problem());
    }
    if (a.classifier->num_classes() != static_cast<int>(m.classes.size()))
      throw InputError(source, 0,
                       fmt::format("{}.classifier: fitted for {} classes, the model has {}", where,
                                   a.classifier->num_classes(), m.classes.size()));
    a.calibration.temperature =
        jf::number(jf::member(entry, "temperature", where, source), where + ".temperature", source);
    if (!(a.calibration.temperature > 0.0))
      throw InputError(source, 0, where + ".temperature: must be positive");
    const auto& threshold = jf::member(entry, "reject_threshold", where, source);
    if (m.reject) {
      a.calibration.reject_threshold = jf::number(threshold, where + ".reject_threshold", source);
      if (a.calibration.reject_threshold < 0.0)
        throw InputError(source, 0, where + ".reject_threshold: must be >= 0");
    } else {
      if (!threshold.is_null())
        throw InputError(source, 0, where + ".reject_threshold: must be null when reject is false");
      a.calibration.reject_threshold = std::numeric_limits<double>::infinity();
    }
    const auto listed =
        jf::names(jf::member(entry, "symbols", where, source), cols, where + ".symbols", source);
    if (listed != symbols)
      throw InputError(source, 0,
                       fmt::format("{}.symbols: expected [{}] (the classes{})", where,
                                   fmt::join(symbols, ", "), m.reject ? " and unknown" : ""));
    const auto counts = jf::matrix(jf::member(entry, "confusion", where, source), rows, cols,
                                   where + ".confusion", source);
    a.calibration.confusion = ConfusionMatrix::zeros(m.classes, symbols);
    for (std::size_t i = 0; i < counts.size(); ++i) {
      if (counts[i] < 0 || counts[i] > 1e9 || counts[i] != std::floor(counts[i]))
        throw InputError(source, 0, where + ".confusion: counts must be whole numbers >= 0");
      a.calibration.confusion.counts[i / symbols.size()][i % symbols.size()] =
          static_cast<int>(counts[i]);
    }
    const auto table =
        jf::matrix(jf::member(entry, "table", where, source), rows, cols, where + ".table", source);
    for (std::size_t k = 0; k < m.classes.size(); ++k) {
      std::vector<double> row(
          table.begin() + static_cast<std::ptrdiff_t>(k * symbols.size()),
          table.begin() + static_cast<std::ptrdiff_t>((k + 1) * symbols.size()));
      double sum = 0.0;
      for (double p : row) {
        if (p < 0.0 || p > 1.0)
          throw InputError(source, 0,
                           fmt::format("{}.table[{}]: probabilities must be in [0, 1]", where, k));
        sum += p;
      }
      if (std::abs(sum - 1.0) > 1e-6)
        throw InputError(
            source, 0, fmt::format("{}.table[{}]: probabilities sum to {}, not 1", where, k, sum));
      a.calibration.table.push_back(std::move(row));
    }
    m.per_action.push_back(std::move(a));
  }
  return model;
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
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    // parse_error for broken syntax, out_of_range for a number beyond double: both a corrupt file.
    throw InputError(
        source, 0,
        fmt::format("not a valid JSON model file (truncated or corrupt?): {}", e.what()));
  }
  try {
    return ObservationModel::from_json(doc, source);
  } catch (const nlohmann::json::exception& e) {
    // A shape the checks above did not anticipate: still an input error, never a crash.
    throw InputError(source, 0, fmt::format("malformed model: {}", e.what()));
  }
}

void save_observation_model(const ObservationModel& model, const std::string& path) {
  // An interrupted save never leaves half a model.
  write_file_atomically(path, model.to_json().dump() + '\n');
}

// ---------------------------------------------------------------------------------------------------------
// Held-out evaluation

Evaluation evaluate_observation_model(const ObservationModel& model, const RecordingSet& set,
                                      const ProgressFn& progress) {
  for (const auto& action : set.actions)
    if (std::find(model.actions().begin(), model.actions().end(), action) == model.actions().end())
      throw InputError(
          set.root, 0,
          fmt::format("action '{}' of the recordings is not in the model (it was trained for: {})",
                      action, fmt::join(model.actions(), ", ")));
  Evaluation evaluation;
  const auto symbols = model.observation_symbols();
  ClipAnalyzer analyzer(model.analysis());
  ClipAnalysis analysis;
  int done = 0;
  for (const auto& action : model.actions()) {
    if (std::find(set.actions.begin(), set.actions.end(), action) == set.actions.end()) continue;
    ConfusionMatrix confusion = ConfusionMatrix::zeros(set.objects, symbols);
    for (const Recording* r : set.of_action(action)) {
      analyzer.analyse(read_recording(r->path, model.analysis().sample_rate), r->path, analysis);
      const Prediction p = model.classify(analysis, action);
      ++confusion.counts[static_cast<std::size_t>(set.object_index(r->object))]
                        [static_cast<std::size_t>(p.symbol)];
      if (progress) progress("evaluate", ++done, static_cast<int>(set.recordings.size()));
    }
    evaluation.per_action.push_back(std::move(confusion));
  }
  return evaluation;
}

}  // namespace echoplan::perception
