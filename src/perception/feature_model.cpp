#include "perception/feature_model.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <limits>
#include <map>

#include "common/error.h"
#include "perception/calibration.h"
#include "perception/dataset_folds.h"
#include "perception/modality_fusion.h"
#include "perception/observation_grades.h"
#include "perception/observation_table.h"
#include "perception/typicality.h"

namespace echoplan::perception {
namespace {

// One action's training rows: their indices into the action's rows, classes and inner folds.
struct TrainingRows {
  std::vector<int> rows;    // indices into ActionData::rows
  std::vector<int> labels;  // class of each
  std::vector<int> fold;    // inner fold of each
};

TrainingRows training_rows(const DatasetTask& task, const ActionData& action,
                           const std::vector<int>& fold_of_session) {
  TrainingRows t;
  for (int r = 0; r < static_cast<int>(action.rows.size()); ++r) {
    const RowLabel& label = action.rows[static_cast<std::size_t>(r)];
    const int fold = fold_of_session[static_cast<std::size_t>(label.session)];
    if (fold < 0) continue;
    t.rows.push_back(r);
    t.labels.push_back(task.class_of_object[static_cast<std::size_t>(label.object)]);
    t.fold.push_back(fold);
  }
  return t;
}

std::shared_ptr<Classifier> fit_on(const std::string& classifier_name, const Modality& modality,
                                   const TrainingRows& t, int num_classes, int except_fold) {
  std::vector<std::vector<double>> rows;
  std::vector<int> labels;
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    if (t.fold[i] != except_fold) {
      rows.push_back(modality.rows[static_cast<std::size_t>(t.rows[i])]);
      labels.push_back(t.labels[i]);
    }
  std::shared_ptr<Classifier> classifier =
      make_modality_classifier(classifier_name, modality.extractor);
  classifier->fit(rows, labels, num_classes);
  return classifier;
}

// scores[m][i]: modality m's log-scores for training row i, from the classifier fitted without
// row i's inner fold.
ModalityScores held_out_scores(const std::string& classifier_name, const ActionData& action,
                               const TrainingRows& t, int num_classes, int num_folds) {
  ModalityScores scores(action.modalities.size(), std::vector<std::vector<double>>(t.rows.size()));
  for (std::size_t m = 0; m < action.modalities.size(); ++m)
    for (int f = 0; f < num_folds; ++f) {
      const auto classifier = fit_on(classifier_name, action.modalities[m], t, num_classes, f);
      for (std::size_t i = 0; i < t.rows.size(); ++i)
        if (t.fold[i] == f)
          scores[m][i] =
              classifier->score(action.modalities[m].rows[static_cast<std::size_t>(t.rows[i])])
                  .log_scores;
    }
  return scores;
}

int best_of(const std::vector<double>& scores) {
  return static_cast<int>(std::max_element(scores.begin(), scores.end()) - scores.begin());
}

// The held-out accuracy and NLL of each modality alone (at its fitted temperature) and fused.
void measure(ActionFit& fit, const ModalityScores& scores, const std::vector<int>& labels,
             const std::vector<int>& fused_decisions) {
  const auto n = static_cast<double>(labels.size());
  for (std::size_t m = 0; m < scores.size(); ++m) {
    std::vector<double> w(scores.size(), 0.0);
    w[m] = 1.0 / fit_temperature(scores[m], labels);
    int right = 0;
    for (std::size_t i = 0; i < labels.size(); ++i) right += best_of(scores[m][i]) == labels[i];
    fit.modality_accuracy.push_back(right / n);
    fit.modality_nll.push_back(fused_mean_nll(scores, labels, w));
  }
  int right = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) right += fused_decisions[i] == labels[i];
  fit.fused_accuracy = right / n;
}

// [fold] the table shrunk with `strength` from the decisions of every other inner fold: the
// table each fold's sequences are scored with when the tempering is fitted.
std::vector<Table> cross_fitted_tables(const TrainingRows& t, const std::vector<int>& decisions,
                                       const DatasetTask& task, int num_folds, double strength) {
  const std::size_t classes = task.classes.size();
  std::vector<Table> tables;
  for (int f = 0; f < num_folds; ++f) {
    std::vector<std::vector<double>> counts(classes, std::vector<double>(classes, 0.0));
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      if (t.fold[i] != f)
        counts[static_cast<std::size_t>(t.labels[i])][static_cast<std::size_t>(decisions[i])] +=
            1.0;
    tables.push_back(estimate_table(counts, task.classes,
                                    {TableEstimate::shrunk, 0.0, task.bin_of_class, strength})
                         .table);
  }
  return tables;
}

// Each inner-held-out session's sequence of fused decisions for this action.
std::vector<Sequence> sequences_of(const ActionData& action, const TrainingRows& t,
                                   const std::vector<int>& decisions) {
  std::map<int, Sequence> by_session;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    Sequence& s = by_session[action.rows[static_cast<std::size_t>(t.rows[i])].session];
    s.true_class = t.labels[i];
    s.table = t.fold[i];
    s.symbols.push_back(decisions[i]);
  }
  std::vector<Sequence> sequences;
  for (auto& [session, sequence] : by_session) sequences.push_back(std::move(sequence));
  return sequences;
}

// One action's fused held-out decisions: the class each training row was heard as, the calibrated
// probability of that class, and whether it was the row's own.
struct Decisions {
  std::vector<int> heard;
  std::vector<double> confidence;
  std::vector<bool> right;
};

// One action's inner-held-out performances as symbols (typicality.h): `cross_fitted` are the
// tables of the other inner folds' decisions, tempered here with the action's own beta.
HeldOutPerformances held_out(const ActionData& action, const TrainingRows& t,
                             const std::vector<int>& symbols,
                             const std::vector<Table>& cross_fitted, double beta) {
  HeldOutPerformances held{{}, t.fold, t.labels, symbols, {}};
  for (int row : t.rows) held.session.push_back(action.rows[static_cast<std::size_t>(row)].session);
  for (const Table& table : cross_fitted) held.cross_fitted.push_back(temper(table, beta));
  return held;
}

// The grades and the graded table (observation_grades.h), tempered for repeats as the label table
// is: each inner fold's graded sequences scored with the table of the other folds' decisions.
// Returns the graded held-out performances, for the share of objects unlike their class.
HeldOutPerformances grade(ActionCalibration& calibration, ActionFit& fit, const ActionData& action,
                          const TrainingRows& t, const Decisions& d, const Table& shrunk,
                          const std::vector<Table>& cross_fitted) {
  const int classes = static_cast<int>(shrunk.size());
  calibration.grades = fit_grades(d.confidence, d.right);
  const GradeCalibration& grades = *calibration.grades;
  std::vector<Table> graded_cross_fitted;
  for (std::size_t f = 0; f < cross_fitted.size(); ++f) {
    std::vector<double> confidence;
    std::vector<bool> right;
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      if (t.fold[i] != static_cast<int>(f)) {
        confidence.push_back(d.confidence[i]);
        right.push_back(d.right[i]);
      }
    graded_cross_fitted.push_back(
        graded_table(cross_fitted[f], fit_grades(confidence, right, grades.edges), classes));
  }
  std::vector<int> graded(t.rows.size());
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    graded[i] = graded_symbol(d.heard[i], grade_of(grades, d.confidence[i]), classes);
  fit.graded_temper = fit_temper(graded_cross_fitted, sequences_of(action, t, graded));
  calibration.graded_table = temper(graded_table(shrunk, grades, classes), fit.graded_temper);
  return held_out(action, t, graded, graded_cross_fitted, fit.graded_temper);
}

// [session] -> its inner fold, or -1 for sessions outside training.
std::vector<int> inner_folds(const FeatureSet& set, const DatasetTask& task,
                             std::span<const int> training, int& num_folds) {
  std::vector<Fold> folds;
  try {
    folds = make_folds(set, task, training);
  } catch (const InputError& e) {
    throw InputError(e.file(), e.line(),
                     "inner cross-validation within the training sessions: " + e.problem());
  }
  num_folds = static_cast<int>(folds.size());
  std::vector<int> fold_of(set.sessions.size(), -1);
  for (int f = 0; f < num_folds; ++f)
    for (int s : folds[static_cast<std::size_t>(f)].test_sessions)
      fold_of[static_cast<std::size_t>(s)] = f;
  return fold_of;
}

}  // namespace

// The confusion of the fused held-out decisions (symbols: the classes).
ConfusionMatrix confusion_of(const DatasetTask& task,
                             const std::vector<std::vector<double>>& counts) {
  ConfusionMatrix confusion = ConfusionMatrix::zeros(task.classes, task.classes);
  for (std::size_t k = 0; k < counts.size(); ++k)
    for (std::size_t o = 0; o < counts[k].size(); ++o)
      confusion.counts[k][o] = static_cast<int>(counts[k][o]);
  return confusion;
}

struct FeatureModelFitter {
  const FeatureSet& set;
  const DatasetTask& task;
  const std::string& classifier_name;
  std::vector<int> fold_of_session;
  int num_folds = 0;

  ObservationModel fit(const ProgressFn& progress) const {
    ModelDescription description;
    description.classifier_name = classifier_name;
    description.classes = task.classes;
    description.reject = false;
    description.dirichlet_alpha = 0.0;
    description.table_estimate = TableEstimate::shrunk;
    std::vector<ActionModel> per_action;
    std::vector<HeldOutPerformances> labels, graded;
    const int total = static_cast<int>(set.actions.size());
    for (int a = 0; a < total; ++a) {
      description.actions.push_back(set.actions[static_cast<std::size_t>(a)].name);
      per_action.push_back(fit_action(set.actions[static_cast<std::size_t>(a)], labels, graded));
      if (progress) progress("fit", a + 1, total);
    }
    description.atypical_share = fit_atypical_share(labels);
    description.graded_atypical_share = fit_atypical_share(graded);
    description.lookalike_share = fit_lookalike_share(labels);
    description.graded_lookalike_share = fit_lookalike_share(graded);
    return ObservationModel(std::move(description), std::move(per_action));
  }

  // Fits one action: its fusion, table and final classifiers. Appends its held-out performances,
  // as labels and as graded symbols, for the share of objects unlike their class.
  ActionModel fit_action(const ActionData& action, std::vector<HeldOutPerformances>& labels,
                         std::vector<HeldOutPerformances>& graded) const {
    const int num_classes = static_cast<int>(task.classes.size());
    const TrainingRows t = training_rows(task, action, fold_of_session);
    const ModalityScores scores =
        held_out_scores(classifier_name, action, t, num_classes, num_folds);
    const Fusion fusion = fit_fusion(scores, t.labels);
    Decisions d;
    std::vector<std::vector<double>> counts(task.classes.size(),
                                            std::vector<double>(task.classes.size(), 0.0));
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      std::vector<std::vector<double>> example(scores.size());
      for (std::size_t m = 0; m < scores.size(); ++m) example[m] = scores[m][i];
      const std::vector<double> fused = fuse(example, fusion.weights);
      d.heard.push_back(best_of(fused));
      d.confidence.push_back(softmax(fused, 1.0)[static_cast<std::size_t>(d.heard.back())]);
      d.right.push_back(d.heard.back() == t.labels[i]);
      counts[static_cast<std::size_t>(t.labels[i])][static_cast<std::size_t>(d.heard.back())] +=
          1.0;
    }
    ActionFit fit;
    measure(fit, scores, t.labels, d.heard);
    fit.fused_nll = fusion.mean_nll;
    const EstimatedTable shrunk =
        estimate_table(counts, task.classes, {TableEstimate::shrunk, 0.0, task.bin_of_class, {}});
    fit.shrinkage_strength = shrunk.strength;
    const std::vector<Table> cross_fitted =
        cross_fitted_tables(t, d.heard, task, num_folds, shrunk.strength);
    fit.temper = fit_temper(cross_fitted, sequences_of(action, t, d.heard));
    ActionModel model;
    model.weights = fusion.weights;
    model.calibration.action = action.name;
    model.calibration.reject_threshold = std::numeric_limits<double>::infinity();
    model.calibration.confusion = confusion_of(task, counts);
    model.calibration.table = temper(shrunk.table, fit.temper);
    labels.push_back(held_out(action, t, d.heard, cross_fitted, fit.temper));
    graded.push_back(grade(model.calibration, fit, action, t, d, shrunk.table, cross_fitted));
    model.calibration.fit = std::move(fit);
    for (const Modality& m : action.modalities)
      model.modalities.push_back({m.name, fit_on(classifier_name, m, t, num_classes, -1)});
    return model;
  }
};

ObservationModel fit_feature_model(const FeatureSet& set, const DatasetTask& task,
                                   std::span<const int> training_sessions,
                                   const FeatureModelOptions& options, const ProgressFn& progress) {
  std::vector<bool> has_class(task.classes.size(), false);
  for (int s : training_sessions)
    has_class[static_cast<std::size_t>(task.class_of_object[static_cast<std::size_t>(
        set.sessions.at(static_cast<std::size_t>(s)).object)])] = true;
  for (std::size_t c = 0; c < has_class.size(); ++c)
    if (!has_class[c])
      throw InputError(set.root, 0,
                       fmt::format("class '{}' has no training session", task.classes[c]));
  const std::string name = make_row_classifier(options.classifier)->name();  // checks the name
  FeatureModelFitter fitter{set, task, name, {}, 0};
  fitter.fold_of_session = inner_folds(set, task, training_sessions, fitter.num_folds);
  return fitter.fit(progress);
}

PerformanceReader::PerformanceReader(const ObservationModel& model, const std::string& action,
                                     const FeatureSet& set)
    : model_(&model), model_action_(model.action_index(action)), data_(set.action(action)) {
  if (model_action_ < 0)
    throw InputError(set.root, 0,
                     fmt::format("the model has no action '{}' (it was trained for: {})", action,
                                 fmt::join(model.actions(), ", ")));
  if (data_ == nullptr)
    throw InputError(set.root, 0, fmt::format("the data has no action '{}'", action));
  for (const ModalityModel& m : model.modalities(action)) {
    const Modality* column = nullptr;
    for (const Modality& candidate : data_->modalities)
      if (candidate.name == m.name) column = &candidate;
    if (column == nullptr)
      throw InputError(
          set.root, 0,
          fmt::format("action '{}' has no modality '{}', which the model needs", action, m.name));
    columns_.push_back(column);
  }
}

Prediction PerformanceReader::classify(int row) const {
  std::vector<std::span<const double>> rows;
  for (const Modality* column : columns_)
    rows.emplace_back(column->rows.at(static_cast<std::size_t>(row)));
  return model_->classify_rows(model_action_, rows);
}

int classify_row(const ObservationModel& model, int action, const FeatureSet& set, int row) {
  const ActionData& data = set.actions.at(static_cast<std::size_t>(action));
  std::vector<std::span<const double>> rows;
  for (const Modality& m : data.modalities)
    rows.emplace_back(m.rows.at(static_cast<std::size_t>(row)));
  return model.classify_rows(action, rows).best_class;
}

}  // namespace echoplan::perception
