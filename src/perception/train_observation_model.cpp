#include "perception/train_observation_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <numeric>
#include <span>

#include "common/error.h"
#include "common/rng.h"
#include "common/stable_hash.h"

namespace echoplan::perception {

namespace {

void check_options(const TrainOptions& o) {
  if (!(o.reject_margin >= 1.0 && o.reject_margin <= 100.0))
    throw InputError(fmt::format("reject margin {} is outside 1..100", o.reject_margin));
  if (!(o.dirichlet_alpha >= 0.0 && o.dirichlet_alpha <= 1000.0))
    throw InputError(fmt::format("Dirichlet alpha {} is outside 0..1000", o.dirichlet_alpha));
  if (o.table == TableEstimate::shrunk)
    throw InputError(
        "the shrunk table is fitted on sessions (train --data with --hold-out); clips take counts "
        "or soft");
  if (o.folds < 0 || o.folds == 1)
    throw InputError(fmt::format("folds = {}: use 0 (leave-one-out) or at least 2", o.folds));
}

ModelDescription describe(const RecordingSet& set, const TrainOptions& options,
                          const Classifier& prototype) {
  ModelDescription d;
  d.analysis = options.analysis;
  d.classifier_name = prototype.name();
  d.classes = set.objects;
  d.actions = set.actions;
  d.reject = options.reject;
  d.dirichlet_alpha = options.dirichlet_alpha;
  d.table_estimate = options.table;
  if (d.classes.size() < 2)
    throw InputError(set.root, 0,
                     fmt::format("need recordings of at least two objects to train, found {}",
                                 d.classes.size()));
  return d;
}

// Every recording analysed and embedded once (cross-validation refits on the embeddings), in the
// set's order.
std::vector<std::vector<double>> embed_recordings(const RecordingSet& set,
                                                  const AnalysisSettings& settings,
                                                  const Classifier& prototype,
                                                  const ProgressFn& progress) {
  ClipAnalyzer analyzer(settings);
  ClipAnalysis analysis;
  std::vector<std::vector<double>> embeddings(set.recordings.size());
  for (std::size_t i = 0; i < set.recordings.size(); ++i) {
    const auto& r = set.recordings[i];
    analyzer.analyse(read_recording(r.path, settings.sample_rate), r.path, analysis);
    embeddings[i] = prototype.embed(analysis);
    if (progress)
      progress("analyse", static_cast<int>(i + 1), static_cast<int>(set.recordings.size()));
  }
  return embeddings;
}

// One action's embeddings and their class labels; at least two per class, or cross-validation
// could not hold one out.
struct Examples {
  std::vector<std::vector<double>> embeddings;
  std::vector<int> labels;
};

Examples examples_of(const RecordingSet& set, const std::vector<std::vector<double>>& embeddings,
                     const std::string& action) {
  Examples e;
  std::vector<int> per_class(set.objects.size(), 0);
  for (std::size_t i = 0; i < set.recordings.size(); ++i) {
    if (set.recordings[i].action != action) continue;
    e.embeddings.push_back(embeddings[i]);
    e.labels.push_back(set.object_index(set.recordings[i].object));
    ++per_class[static_cast<std::size_t>(e.labels.back())];
  }
  for (std::size_t k = 0; k < per_class.size(); ++k)
    if (per_class[k] < 2)
      throw InputError(
          (std::filesystem::path(set.root) / set.objects[k] / action).string(), 0,
          "cross-validation needs at least 2 recordings per (object, action), found 1");
  return e;
}

// What the classifier said about each example while it was held out.
struct HeldOut {
  std::vector<std::vector<double>> log_scores;
  std::vector<double> distance;  // to the nearest class
  std::vector<int> best;         // the class with the highest log-score
};

HeldOut cross_validate(const Examples& examples, const Classifier& prototype, int num_classes,
                       const TrainOptions& options, const std::string& action,
                       const ProgressFn& progress) {
  const std::size_t n = examples.embeddings.size();
  const std::vector<int> fold =
      cross_validation_folds(examples.labels, num_classes, options.folds, options.seed, action);
  const int num_folds = options.folds == 0 ? static_cast<int>(n) : options.folds;
  HeldOut held{std::vector<std::vector<double>>(n), std::vector<double>(n), std::vector<int>(n)};
  for (int f = 0; f < num_folds; ++f) {
    std::vector<std::vector<double>> train;
    std::vector<int> train_labels;
    std::vector<std::size_t> test;
    for (std::size_t i = 0; i < n; ++i) {
      if (fold[i] == f) {
        test.push_back(i);
      } else {
        train.push_back(examples.embeddings[i]);
        train_labels.push_back(examples.labels[i]);
      }
    }
    if (test.empty()) continue;
    auto classifier = prototype.clone_unfitted();
    classifier->fit(train, train_labels, num_classes);
    for (std::size_t i : test) {
      const ClassScores s = classifier->score(examples.embeddings[i]);
      held.best[i] = s.best_class();
      held.distance[i] = s.nearest_distance();
      held.log_scores[i] = s.log_scores;
    }
    if (progress) progress("cross-validate " + action, f + 1, num_folds);
  }
  return held;
}

// The reject threshold: reject_margin times the largest held-out distance of a correctly
// classified example (of any example when none was correct); infinity when reject is off.
double reject_threshold(const HeldOut& held, std::span<const int> labels,
                        const TrainOptions& options) {
  if (!options.reject) return std::numeric_limits<double>::infinity();
  double largest_correct = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    largest = std::max(largest, held.distance[i]);
    if (held.best[i] == labels[i]) largest_correct = std::max(largest_correct, held.distance[i]);
  }
  return options.reject_margin * (largest_correct > 0.0 ? largest_correct : largest);
}

// The action's grades from its held-out decisions that were not rejected: the calibrated
// probability of the class each was heard as, and whether it was right; then the graded table.
void grade(ActionCalibration& c, const HeldOut& held, std::span<const int> labels,
           const std::vector<bool>& rejected, int num_classes) {
  std::vector<double> confidence;
  std::vector<bool> right;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (rejected[i]) continue;
    const auto best = static_cast<std::size_t>(held.best[i]);
    confidence.push_back(softmax(held.log_scores[i], c.temperature)[best]);
    right.push_back(held.best[i] == labels[i]);
  }
  c.grades = fit_grades(confidence, right);
  c.graded_table = graded_table(c.table, *c.grades, num_classes);
}

// Temperature, reject threshold, confusion and table of one action from its held-out scores.
ActionCalibration calibrate(const HeldOut& held, std::span<const int> labels,
                            const ModelDescription& model, const TrainOptions& options,
                            const std::string& action) {
  const int num_classes = static_cast<int>(model.classes.size());
  const std::vector<std::string> symbols = observation_symbols(model);
  ActionCalibration c;
  c.action = action;
  // Label smoothing matching the Dirichlet prior's share of an average row keeps the
  // probabilities no more confident than the table the planner gets.
  const double mean_count = static_cast<double>(labels.size()) / num_classes;
  const double prior_mass = options.dirichlet_alpha * num_classes;
  c.temperature = fit_temperature(held.log_scores, labels, prior_mass / (mean_count + prior_mass));
  c.reject_threshold = reject_threshold(held, labels, options);
  c.confusion = ConfusionMatrix::zeros(model.classes, symbols);
  std::vector<bool> rejected(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) {
    rejected[i] = options.reject && held.distance[i] > c.reject_threshold;
    ++c.confusion.counts[static_cast<std::size_t>(
        labels[i])][rejected[i] ? model.classes.size() : static_cast<std::size_t>(held.best[i])];
  }
  std::vector<std::vector<double>> counts;
  if (options.table == TableEstimate::soft)
    counts = soft_confusion(held.log_scores, labels, rejected, num_classes,
                            static_cast<int>(symbols.size()), c.temperature);
  else
    for (const auto& row : c.confusion.counts) counts.emplace_back(row.begin(), row.end());
  c.table =
      estimate_table(counts, model.classes, {options.table, options.dirichlet_alpha, {}, {}}).table;
  grade(c, held, labels, rejected, num_classes);
  return c;
}

}  // namespace

const std::vector<std::string>& clip_table_estimate_names() {
  static const std::vector<std::string> names{"counts", "soft"};
  return names;
}

std::vector<int> cross_validation_folds(std::span<const int> labels, int num_classes, int folds,
                                        std::uint64_t seed, const std::string& action) {
  std::vector<int> fold(labels.size());
  if (folds == 0) {
    std::iota(fold.begin(), fold.end(), 0);
    return fold;
  }
  // Stream "fold" (its ASCII bytes) and the action's name. stable_hash, not std::hash: the folds,
  // hence the calibration, must be the same on every platform and standard library.
  Rng rng(derive_seed(seed, {0x666f6c64, stable_hash(action)}));
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

ObservationModel train_observation_model(const RecordingSet& set, const TrainOptions& options,
                                         const ProgressFn& progress) {
  check_options(options);
  const auto prototype = make_classifier(options.classifier);
  ModelDescription description = describe(set, options, *prototype);
  const auto embeddings = embed_recordings(set, options.analysis, *prototype, progress);
  const int num_classes = static_cast<int>(description.classes.size());
  std::vector<ActionModel> per_action;
  for (const auto& action : description.actions) {
    const Examples examples = examples_of(set, embeddings, action);
    const HeldOut held =
        cross_validate(examples, *prototype, num_classes, options, action, progress);
    ActionModel a;
    a.calibration = calibrate(held, examples.labels, description, options, action);
    std::unique_ptr<Classifier> classifier = prototype->clone_unfitted();
    classifier->fit(examples.embeddings, examples.labels, num_classes);
    a.modalities.push_back({"audio", std::move(classifier)});
    a.weights = {1.0};
    per_action.push_back(std::move(a));
  }
  return ObservationModel(std::move(description), std::move(per_action));
}

}  // namespace echoplan::perception
