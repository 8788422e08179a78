#include "perception/fit_observation_model.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>
#include <numeric>

#include "common/error.h"
#include "common/rng.h"
#include "common/stable_hash.h"
#include "perception/calibration.h"
#include "perception/dataset_folds.h"
#include "perception/modality_fusion.h"
#include "perception/observation_grades.h"
#include "perception/observation_table.h"
#include "perception/recording_features.h"
#include "perception/typicality.h"

namespace echoplan::perception {
namespace {

// The classifier of one modality: an audio preset over the clips its extractor turned into rows,
// or a row classifier (with the modality's extractor, if a clip extractor computed its rows; for
// a modality of series, an audio preset's own row classifier).
std::unique_ptr<Classifier> modality_classifier(const std::string& name, const Modality& modality,
                                                const std::string& action) {
  if (!modality.series.empty()) return make_series_classifier(name);
  if (!is_audio_preset(name)) return make_modality_classifier(name, modality.extractor);
  std::unique_ptr<Classifier> classifier = make_classifier(name);
  if (classifier->extractor()->name != modality.extractor)
    throw InputError(fmt::format(
        "classifier '{}' is an audio preset over '{}' rows of clips, and modality '{}' of '{}' {}: "
        "name a row classifier ({})",
        name, classifier->extractor()->name, modality.name, action,
        modality.extractor.empty() ? "has rows a sensor gave"
                                   : "was computed by '" + modality.extractor + "'",
        fmt::join(row_classifier_names(), ", ")));
  return classifier;
}

// One action's training rows: their indices into the action's rows, classes and inner folds.
struct TrainingRows {
  std::vector<int> rows;    // indices into ActionData::rows
  std::vector<int> labels;  // class of each
  std::vector<int> fold;    // inner fold of each
  int num_folds = 0;
};

// [session] -> its inner fold, or -1 for sessions outside training; the folds every action shares.
struct SessionFolds {
  std::vector<int> fold_of_session;
  int num_folds = 0;
};

SessionFolds session_folds(const FeatureSet& set, const DatasetTask& task,
                           std::span<const int> training) {
  std::vector<Fold> folds;
  try {
    folds = make_folds(set, task, training);
  } catch (const InputError& e) {
    throw InputError(e.file(), e.line(),
                     "inner cross-validation within the training sessions: " + e.problem());
  }
  SessionFolds s{std::vector<int>(set.sessions.size(), -1), static_cast<int>(folds.size())};
  for (int f = 0; f < s.num_folds; ++f)
    for (int session : folds[static_cast<std::size_t>(f)].test_sessions)
      s.fold_of_session[static_cast<std::size_t>(session)] = f;
  return s;
}

// Leave-one-out and stratified folds need two performances of every class in the action.
void check_two_per_class(const FeatureSet& set, const DatasetTask& task, const ActionData& action,
                         const TrainingRows& t) {
  std::vector<int> per_class(task.classes.size(), 0);
  for (int label : t.labels) ++per_class[static_cast<std::size_t>(label)];
  for (std::size_t k = 0; k < per_class.size(); ++k)
    if (per_class[k] < 2)
      throw InputError(
          (std::filesystem::path(set.root) / task.classes[k] / action.name).string(), 0,
          fmt::format("cross-validation needs at least 2 performances of each class per action, "
                      "found {}",
                      per_class[k]));
}

TrainingRows training_rows(const FeatureSet& set, const DatasetTask& task, const ActionData& action,
                           const std::vector<bool>& in_training, const SessionFolds* by_session,
                           const FitOptions& options) {
  TrainingRows t;
  for (int r = 0; r < static_cast<int>(action.rows.size()); ++r) {
    const RowLabel& label = action.rows[static_cast<std::size_t>(r)];
    if (!in_training[static_cast<std::size_t>(label.session)]) continue;
    t.rows.push_back(r);
    t.labels.push_back(task.class_of_object[static_cast<std::size_t>(label.object)]);
    if (by_session)
      t.fold.push_back(by_session->fold_of_session[static_cast<std::size_t>(label.session)]);
  }
  if (by_session) {
    t.num_folds = by_session->num_folds;
    return t;
  }
  check_two_per_class(set, task, action, t);
  t.fold = cross_validation_folds(t.labels, static_cast<int>(task.classes.size()), options.folds,
                                  options.seed, action.name);
  t.num_folds = options.folds == 0 ? static_cast<int>(t.rows.size()) : options.folds;
  return t;
}

// What every modality's classifiers said about each training row while its fold was held out.
struct HeldOutScores {
  ModalityScores scores;                    // [modality][row] log-scores
  std::vector<double> distance;             // [row] to the nearest class, by the first modality
  std::vector<std::vector<double>> summed;  // [row] the log-scores the probabilities start from
};

std::shared_ptr<Classifier> fit_on(const std::string& name, const Modality& modality,
                                   const std::string& action, const TrainingRows& t,
                                   int num_classes, int except_fold) {
  std::vector<std::vector<double>> rows;
  std::vector<int> labels;
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    if (t.fold[i] != except_fold) {
      rows.push_back(modality.rows[static_cast<std::size_t>(t.rows[i])]);
      labels.push_back(t.labels[i]);
    }
  std::shared_ptr<Classifier> classifier = modality_classifier(name, modality, action);
  classifier->fit(rows, labels, num_classes);
  return classifier;
}

HeldOutScores held_out_scores(const std::string& classifier, const ActionData& action,
                              const TrainingRows& t, int num_classes) {
  const std::size_t n = t.rows.size();
  HeldOutScores held{ModalityScores(action.modalities.size(), std::vector<std::vector<double>>(n)),
                     std::vector<double>(n),
                     {}};
  std::vector<bool> fold_used(static_cast<std::size_t>(t.num_folds), false);
  for (int f : t.fold) fold_used[static_cast<std::size_t>(f)] = true;
  for (std::size_t m = 0; m < action.modalities.size(); ++m)
    for (int f = 0; f < t.num_folds; ++f) {
      if (!fold_used[static_cast<std::size_t>(f)]) continue;  // k folds beyond a class's rows
      const Modality& modality = action.modalities[m];
      const auto fitted = fit_on(classifier, modality, action.name, t, num_classes, f);
      for (std::size_t i = 0; i < n; ++i) {
        if (t.fold[i] != f) continue;
        ClassScores s = fitted->score(modality.rows[static_cast<std::size_t>(t.rows[i])]);
        if (m == 0) held.distance[i] = s.nearest_distance();
        held.scores[m][i] = std::move(s.log_scores);
      }
    }
  return held;
}

int best_of(const std::vector<double>& scores) {
  return static_cast<int>(std::max_element(scores.begin(), scores.end()) - scores.begin());
}

// Row i's log-scores combined with `weights` (one modality at weight 1: its own scores, exactly).
std::vector<double> combined(const ModalityScores& scores, std::size_t i,
                             const std::vector<double>& weights) {
  if (scores.size() == 1 && weights.front() == 1.0) return scores.front()[i];
  std::vector<std::vector<double>> example(scores.size());
  for (std::size_t m = 0; m < scores.size(); ++m) example[m] = scores[m][i];
  return fuse(example, weights);
}

// One action's held-out decisions: the class (or `unknown`, index num_classes) each training row
// was heard as, the calibrated probability of the class it was heard as, and whether it was right.
struct Decisions {
  std::vector<double> weights;
  double temperature = 1.0;
  double fused_nll = 0.0;
  double reject_threshold = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double>> fused;  // [row] the combined log-scores
  std::vector<int> heard;
  std::vector<bool> rejected;
  std::vector<double> confidence;
  std::vector<bool> right;
};

// The reject threshold: reject_margin times the largest held-out distance of a correctly
// classified row (of any row when none was correct).
double reject_threshold(const std::vector<double>& distance, const std::vector<int>& best,
                        std::span<const int> labels, double margin) {
  double largest_correct = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    largest = std::max(largest, distance[i]);
    if (best[i] == labels[i]) largest_correct = std::max(largest_correct, distance[i]);
  }
  return margin * (largest_correct > 0.0 ? largest_correct : largest);
}

// Fusion weights, or weight 1 per modality and one temperature, with label smoothing matching the
// Dirichlet prior's share of an average row (so the probabilities are no surer than the table).
void fit_probabilities(Decisions& d, const HeldOutScores& held, const TrainingRows& t,
                       int num_classes, const FitOptions& options) {
  const std::size_t n = t.rows.size();
  if (options.fuse) {
    const Fusion fusion = fit_fusion(held.scores, t.labels);
    d.weights = fusion.weights;
    d.fused_nll = fusion.mean_nll;
  } else {
    d.weights.assign(held.scores.size(), 1.0);
  }
  for (std::size_t i = 0; i < n; ++i) d.fused.push_back(combined(held.scores, i, d.weights));
  if (options.fuse) return;
  const double mean_count = static_cast<double>(n) / num_classes;
  const double prior_mass = options.dirichlet_alpha * num_classes;
  d.temperature = fit_temperature(d.fused, t.labels, prior_mass / (mean_count + prior_mass));
  std::vector<double> inverse(d.weights.size(), 1.0 / d.temperature);
  d.fused_nll = fused_mean_nll(held.scores, t.labels, inverse);
}

Decisions decide(const HeldOutScores& held, const TrainingRows& t, int num_classes,
                 const FitOptions& options) {
  Decisions d;
  fit_probabilities(d, held, t, num_classes, options);
  std::vector<int> best;
  for (const auto& fused : d.fused) best.push_back(best_of(fused));
  if (options.reject)
    d.reject_threshold = reject_threshold(held.distance, best, t.labels, options.reject_margin);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const bool rejected = options.reject && held.distance[i] > d.reject_threshold;
    d.rejected.push_back(rejected);
    d.heard.push_back(rejected ? num_classes : best[i]);
    d.confidence.push_back(softmax(d.fused[i], d.temperature)[static_cast<std::size_t>(best[i])]);
    d.right.push_back(best[i] == t.labels[i]);
  }
  return d;
}

// The table estimator of the options, for one action's decisions.
struct TableFitter {
  const DatasetTask& task;
  const FitOptions& options;
  int num_symbols = 0;

  // Counts of (class, symbol) over the rows `use` accepts: one per decision, or the calibrated
  // probabilities (soft).
  template <class Use>
  std::vector<std::vector<double>> counts(const TrainingRows& t, const Decisions& d,
                                          const Use& use) const {
    const int classes = static_cast<int>(task.classes.size());
    if (options.table == TableEstimate::soft) {
      std::vector<std::vector<double>> scores;
      std::vector<int> labels;
      std::vector<bool> rejected;
      for (std::size_t i = 0; i < t.rows.size(); ++i)
        if (use(i)) {
          scores.push_back(d.fused[i]);
          labels.push_back(t.labels[i]);
          rejected.push_back(d.rejected[i]);
        }
      return soft_confusion(scores, labels, rejected, classes, num_symbols, d.temperature);
    }
    std::vector<std::vector<double>> c(task.classes.size(),
                                       std::vector<double>(static_cast<std::size_t>(num_symbols)));
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      if (use(i))
        c[static_cast<std::size_t>(t.labels[i])][static_cast<std::size_t>(d.heard[i])] += 1.0;
    return c;
  }

  EstimatedTable estimate(const std::vector<std::vector<double>>& counts,
                          std::optional<double> strength = std::nullopt) const {
    TableOptions o{options.table, options.dirichlet_alpha, {}, strength};
    if (options.table == TableEstimate::shrunk) o.bin_of_class = task.bin_of_class;
    return estimate_table(counts, task.classes, o);
  }

  // [fold] the table from the decisions of every other inner fold (the same prior strength).
  std::vector<Table> cross_fitted(const TrainingRows& t, const Decisions& d,
                                  double strength) const {
    std::vector<Table> tables;
    for (int f = 0; f < t.num_folds; ++f)
      tables.push_back(
          estimate(counts(t, d, [&](std::size_t i) { return t.fold[i] != f; }), strength).table);
    return tables;
  }
};

// The repeats row i is one of: its session's performances, as recorded or (a noisy copy) as heard
// through added noise. A noisy copy is the same performance as its quiet recording, so the two
// must not count as two readings of the object: the tempering and the lookalike shares fitted on
// them would take the copy's agreement for the agreement of repeats.
int sequence_of_row(const ActionData& action, const TrainingRows& t, std::size_t i) {
  const RowLabel& row = action.rows[static_cast<std::size_t>(t.rows[i])];
  return 2 * row.session + (row.noisy_copy ? 1 : 0);
}

// Each inner-held-out sequence of repeats (sequence_of_row()) of `symbols` for this action.
std::vector<Sequence> sequences_of(const ActionData& action, const TrainingRows& t,
                                   const std::vector<int>& symbols) {
  std::map<int, Sequence> by_session;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    Sequence& s = by_session[sequence_of_row(action, t, i)];
    s.true_class = t.labels[i];
    s.table = t.fold[i];
    s.symbols.push_back(symbols[i]);
  }
  std::vector<Sequence> sequences;
  for (auto& [session, sequence] : by_session) sequences.push_back(std::move(sequence));
  return sequences;
}

// One action's inner-held-out performances as symbols (typicality.h), each fold's table
// untempered, with the action's power `beta` (fit_lookalikes tries the shares both ways).
HeldOutPerformances held_out(const ActionData& action, const TrainingRows& t,
                             const std::vector<int>& symbols,
                             const std::vector<Table>& cross_fitted, double beta) {
  HeldOutPerformances held{{}, t.fold, t.labels, symbols, cross_fitted, beta};
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    held.session.push_back(sequence_of_row(action, t, i));
  return held;
}

// The held-out accuracy and NLL of each modality alone (at its fitted temperature) and combined.
void measure(ActionFit& fit, const HeldOutScores& held, const TrainingRows& t, const Decisions& d) {
  const auto n = static_cast<double>(t.labels.size());
  for (std::size_t m = 0; m < held.scores.size(); ++m) {
    std::vector<double> w(held.scores.size(), 0.0);
    w[m] = 1.0 / fit_temperature(held.scores[m], t.labels);
    int right = 0;
    for (std::size_t i = 0; i < t.labels.size(); ++i)
      right += best_of(held.scores[m][i]) == t.labels[i];
    fit.modality_accuracy.push_back(right / n);
    fit.modality_nll.push_back(fused_mean_nll(held.scores, t.labels, w));
  }
  int right = 0;
  for (std::size_t i = 0; i < t.labels.size(); ++i) right += d.heard[i] == t.labels[i];
  fit.fused_accuracy = right / n;
  fit.fused_nll = d.fused_nll;
}

// What one action's fit adds to the model's shares of lookalikes: its held-out performances as
// labels and as graded symbols (cross-validation by session only).
struct ActionShares {
  std::vector<HeldOutPerformances> labels, graded;
};

}  // namespace

const char* cross_validation_name(CrossValidation cv) {
  switch (cv) {
    case CrossValidation::by_session:
      return "session";
    case CrossValidation::by_surface:
      return "surface";
    case CrossValidation::by_performance:
      break;
  }
  return "performance";
}

CrossValidation parse_cross_validation(const std::string& name) {
  if (name == "performance") return CrossValidation::by_performance;
  if (name == "session") return CrossValidation::by_session;
  if (name == "surface") return CrossValidation::by_surface;
  throw InputError(
      fmt::format("cross-validation '{}' is not one of: performance, session, surface", name));
}

FitOptions session_fit_options(std::string classifier) {
  FitOptions o;
  o.classifier = std::move(classifier);
  o.cross_validation = CrossValidation::by_session;
  o.fuse = true;
  o.reject = false;
  o.dirichlet_alpha = 0.0;
  o.table = TableEstimate::shrunk;
  o.temper = true;
  return o;
}

FitOptions choose_fit_options(const FitChoices& c, DataKind kind, bool task_named,
                              bool several_modalities) {
  const CrossValidation cv = c.cross_validation ? parse_cross_validation(*c.cross_validation)
                             : kind == DataKind::features || task_named
                                 ? CrossValidation::by_session
                                 : CrossValidation::by_performance;
  // By surface: a recordings tree's defaults (the report's setting), its folds the tables.
  FitOptions o = cv == CrossValidation::by_session ? session_fit_options() : FitOptions{};
  o.cross_validation = cv;
  if (cv == CrossValidation::by_surface && (kind == DataKind::features || task_named))
    throw InputError(
        "cross-validation by surface holds out the tables of a recordings tree recorded on "
        "several (its manifest's `surface` column); " +
        std::string(kind == DataKind::features ? "a feature set names no tables"
                                               : "--groups and --hold-out make folds of objects"));
  if (c.classifier) o.classifier = *c.classifier;
  if (c.table) o.table = parse_table_estimate(*c.table);
  if (c.folds) o.folds = *c.folds;
  if (c.sample_rate) o.analysis.sample_rate = *c.sample_rate;
  if (c.seed) o.seed = *c.seed;
  if (several_modalities) o.reject = false;
  if (c.reject) o.reject = *c.reject;
  if (!c.series.empty() && kind == DataKind::features)
    throw InputError(
        fmt::format("series features chosen for '{}', but a feature set's rows are "
                    "given, not computed from series",
                    c.series.begin()->first));
  o.series = c.series;
  if (c.fuse) o.fuse = *c.fuse;
  if (c.temper) o.temper = *c.temper;
  if (c.reject_margin) o.reject_margin = *c.reject_margin;
  if (c.alpha) o.dirichlet_alpha = *c.alpha;
  check_fit_options(o);
  return o;
}

void check_fit_options(const FitOptions& o) {
  if (!(o.reject_margin >= 1.0 && o.reject_margin <= 100.0))
    throw InputError(fmt::format("reject margin {} is outside 1..100", o.reject_margin));
  if (!(o.dirichlet_alpha >= 0.0 && o.dirichlet_alpha <= 1000.0))
    throw InputError(fmt::format("Dirichlet alpha {} is outside 0..1000", o.dirichlet_alpha));
  if (o.folds < 0 || o.folds == 1)
    throw InputError(fmt::format("folds = {}: use 0 (leave-one-out) or at least 2", o.folds));
  if (o.temper && o.cross_validation == CrossValidation::by_performance)
    throw InputError(
        "tempering fits how a session's repeats err together: it needs cross-validation by "
        "session (or by surface)");
  if (o.table == TableEstimate::shrunk && o.reject)
    throw InputError(
        "the shrunk table's pooled structure has no `unknown`: turn the reject option off");
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

namespace {

struct ObservationModelFitter {
  const FeatureSet& set;
  const DatasetTask& task;
  const FitOptions& options;
  std::vector<bool> in_training;
  std::optional<SessionFolds> by_session;

  int num_classes() const { return static_cast<int>(task.classes.size()); }

  // Grades and their table (observation_grades.h) by `score`, one per training row (the heard
  // class's confidence, or the recording's measured level), tempered for repeats as the label
  // table is: each inner fold's graded sequences scored with the table of the other folds'
  // decisions.
  struct Graded {
    GradeCalibration grades;
    Table table;
    double temper = 1.0;
    std::vector<int> symbols;  // the graded symbol of each training row
    std::vector<Table> cross_fitted;
  };
  // Edges by terciles (confidences) or by informative_edges() (levels: `informative`).
  Graded grade(const ActionData& action, const TrainingRows& t, const Decisions& d,
               const std::vector<double>& score, const Table& untempered,
               const std::vector<Table>& cross_fitted, bool informative = false) const {
    const auto kept = [&](std::size_t i, int except_fold) {
      return !d.rejected[i] && t.fold[i] != except_fold;
    };
    const auto decisions = [&](int except_fold, std::vector<double>& scores,
                               std::vector<bool>& right) {
      for (std::size_t i = 0; i < t.rows.size(); ++i)
        if (kept(i, except_fold)) {
          scores.push_back(score[i]);
          right.push_back(d.right[i]);
        }
    };
    Graded g;
    std::vector<double> all_scores;
    std::vector<bool> all_right;
    decisions(-1, all_scores, all_right);
    g.grades = informative
                   ? fit_grades(all_scores, all_right, informative_edges(all_scores, all_right))
                   : fit_grades(all_scores, all_right);
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      g.symbols.push_back(graded_symbol(d.heard[i], grade_of(g.grades, score[i]), num_classes()));
    for (std::size_t f = 0; f < cross_fitted.size(); ++f) {
      std::vector<double> fold_scores;
      std::vector<bool> fold_right;
      decisions(static_cast<int>(f), fold_scores, fold_right);
      g.cross_fitted.push_back(graded_table(
          cross_fitted[f], fit_grades(fold_scores, fold_right, g.grades.edges), num_classes()));
    }
    if (options.temper) g.temper = fit_temper(g.cross_fitted, sequences_of(action, t, g.symbols));
    g.table = graded_table(untempered, g.grades, num_classes());
    if (options.temper) g.table = temper(g.table, g.temper);
    return g;
  }

  // Each training row's measured level, when every one has one (a recordings tree's).
  static std::optional<std::vector<double>> levels_of(const ActionData& action,
                                                      const TrainingRows& t) {
    std::vector<double> levels;
    for (int row : t.rows) {
      const std::optional<double>& level = action.rows.at(static_cast<std::size_t>(row)).ebr_db;
      if (!level) return std::nullopt;
      levels.push_back(*level);
    }
    return levels;
  }

  // Temperature or fusion, reject, table, grades and, by session, tempering and the performances
  // for the lookalike shares.
  ActionCalibration calibrate(const ActionData& action, const TrainingRows& t,
                              const HeldOutScores& held, const Decisions& d,
                              ActionShares& shares) const {
    ActionCalibration c;
    c.action = action.name;
    c.temperature = d.temperature;
    c.reject_threshold = d.reject_threshold;
    const std::vector<std::string> symbols = observation_symbols(description_of());
    const TableFitter tables{task, options, static_cast<int>(symbols.size())};
    const auto all = tables.counts(t, d, [](std::size_t) { return true; });
    c.confusion = ConfusionMatrix::zeros(task.classes, symbols);
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      ++c.confusion
            .counts[static_cast<std::size_t>(t.labels[i])][static_cast<std::size_t>(d.heard[i])];
    const EstimatedTable table = tables.estimate(all);
    ActionFit fit;
    measure(fit, held, t, d);
    fit.shrinkage_strength = table.strength;
    // The other folds' tables score each fold's sequences: needed by session only.
    std::vector<Table> cross_fitted;
    if (by_session) cross_fitted = tables.cross_fitted(t, d, table.strength);
    if (options.temper) fit.temper = fit_temper(cross_fitted, sequences_of(action, t, d.heard));
    c.table = options.temper ? temper(table.table, fit.temper) : table.table;
    Graded graded = grade(action, t, d, d.confidence, table.table, cross_fitted);
    c.grades = graded.grades;
    c.graded_table = graded.table;
    fit.graded_temper = graded.temper;
    if (const auto levels = levels_of(action, t)) {
      Graded by_level = grade(action, t, d, *levels, table.table, cross_fitted, true);
      c.level_grades = by_level.grades;
      c.level_table = std::move(by_level.table);
      fit.level_temper = by_level.temper;
    }
    if (by_session) {
      shares.labels.push_back(held_out(action, t, d.heard, cross_fitted, fit.temper));
      shares.graded.push_back(
          held_out(action, t, graded.symbols, graded.cross_fitted, fit.graded_temper));
    }
    c.fit = std::move(fit);
    return c;
  }

  ActionModel fit_action(const ActionData& action, ActionShares& shares) const {
    if (options.reject && action.modalities.size() > 1)
      throw InputError(set.root, 0,
                       fmt::format("the reject option needs one modality per action, and '{}' "
                                   "has {}: turn it off (--no-reject)",
                                   action.name, action.modalities.size()));
    const TrainingRows t =
        training_rows(set, task, action, in_training, by_session ? &*by_session : nullptr, options);
    const HeldOutScores held = held_out_scores(options.classifier, action, t, num_classes());
    const Decisions d = decide(held, t, num_classes(), options);
    ActionModel model;
    model.weights = d.weights;
    model.calibration = calibrate(action, t, held, d, shares);
    for (const Modality& m : action.modalities)
      model.modalities.push_back(
          {m.name, fit_on(options.classifier, m, action.name, t, num_classes(), -1), m.series});
    return model;
  }

  ModelDescription description_of() const {
    ModelDescription d;
    d.analysis = options.analysis;
    d.classifier_name = options.classifier;
    d.classes = task.classes;
    d.reject = options.reject;
    d.dirichlet_alpha = options.dirichlet_alpha;
    d.table_estimate = options.table;
    return d;
  }

  ObservationModel fit(const ProgressFn& progress) const {
    ModelDescription description = description_of();
    std::vector<ActionModel> per_action;
    ActionShares shares;
    const int total = static_cast<int>(set.actions.size());
    for (int a = 0; a < total; ++a) {
      const ActionData& action = set.actions[static_cast<std::size_t>(a)];
      description.actions.push_back(action.name);
      per_action.push_back(fit_action(action, shares));
      if (progress) progress("fit", a + 1, total);
    }
    if (by_session) {
      const LookalikeFit labels = fit_lookalikes(shares.labels),
                         graded = fit_lookalikes(shares.graded);
      description.lookalike_share = labels.share;
      description.lookalike_untempered = labels.untempered;
      description.graded_lookalike_share = graded.share;
      description.graded_lookalike_untempered = graded.untempered;
    }
    return ObservationModel(std::move(description), std::move(per_action));
  }
};

// The options' classifier under its current name (an alias of a preset becomes the preset's);
// InputError for a name that is neither a preset nor a row classifier.
std::string classifier_name(const std::string& name) {
  if (is_audio_preset(name)) return make_classifier(name)->name();
  try {
    return make_row_classifier(name)->name();
  } catch (const InputError&) {
    throw InputError(fmt::format(
        "classifier '{}' is neither an audio preset ({}) nor a row "
        "classifier ({})",
        name, fmt::join(classifier_names(), ", "), fmt::join(row_classifier_names(), ", ")));
  }
}

}  // namespace

ObservationModel fit_observation_model(const FeatureSet& set, const DatasetTask& task,
                                       std::span<const int> training_sessions,
                                       const FitOptions& options, const ProgressFn& progress) {
  check_fit_options(options);
  FitOptions resolved = options;
  resolved.classifier = classifier_name(options.classifier);
  if (task.classes.size() < 2)
    throw InputError(
        set.root, 0,
        fmt::format("need at least two classes to train, found {}", task.classes.size()));
  ObservationModelFitter fitter{set, task, resolved, std::vector<bool>(set.sessions.size()), {}};
  std::vector<bool> has_class(task.classes.size(), false);
  for (int s : training_sessions) {
    const Session& session = set.sessions.at(static_cast<std::size_t>(s));
    fitter.in_training[static_cast<std::size_t>(s)] = true;
    has_class[static_cast<std::size_t>(
        task.class_of_object[static_cast<std::size_t>(session.object)])] = true;
  }
  for (std::size_t c = 0; c < has_class.size(); ++c)
    if (!has_class[c])
      throw InputError(set.root, 0,
                       fmt::format("class '{}' has no training session", task.classes[c]));
  if (options.cross_validation != CrossValidation::by_performance)
    fitter.by_session = session_folds(set, task, training_sessions);
  return fitter.fit(progress);
}

FeatureSet recordings_as_features(const RecordingSet& set, const FitOptions& options,
                                  const ProgressFn& progress) {
  const std::string classifier = classifier_name(options.classifier);
  return feature_set_from_recordings(
      options.cross_validation == CrossValidation::by_surface ? sessions_by_surface(set) : set,
      options.analysis, progress,
      is_audio_preset(classifier) ? make_classifier(classifier)->extractor()->name : "summary",
      options.series);
}

ObservationModel train_observation_model(const RecordingSet& set, const FitOptions& options,
                                         const ProgressFn& progress) {
  check_fit_options(options);
  const FeatureSet features = recordings_as_features(set, options, progress);
  const DatasetTask task = make_dataset_task(features, nullptr, HoldOut::session);
  std::vector<int> all(features.sessions.size());
  std::iota(all.begin(), all.end(), 0);
  return fit_observation_model(features, task, all, options, progress);
}

}  // namespace echoplan::perception
