#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <numeric>
#include <span>

#include "common/error.h"
#include "perception/dataset_folds.h"
#include "perception/fit_observation_model.h"
#include "perception/observation_table.h"
#include "perception/performance_reader.h"
#include "synthetic_feature_set.h"

namespace echoplan::perception {
namespace {

using test_features::SyntheticSpec;

FeatureSet synthetic(const SyntheticSpec& spec, const std::string& name) {
  const auto dir = test_features::fresh_folder(name);
  test_features::write_synthetic_feature_set(dir, spec);
  return load_feature_set(dir.string());
}

// The fused decisions of `model` on the rows of `fold`: fraction right.
double test_accuracy(const ObservationModel& model, const FeatureSet& set, const DatasetTask& task,
                     const Fold& fold, int action = 0) {
  int right = 0, total = 0;
  const ActionData& data = set.actions[static_cast<std::size_t>(action)];
  for (int r = 0; r < static_cast<int>(data.rows.size()); ++r) {
    const RowLabel& label = data.rows[static_cast<std::size_t>(r)];
    if (!std::binary_search(fold.test_sessions.begin(), fold.test_sessions.end(), label.session))
      continue;
    right += classify_row(model, action, set, r) == task.class_of_object[label.object];
    ++total;
  }
  return static_cast<double>(right) / total;
}

TEST(FitOnFeatureSets, WellSeparatedObjectsAreRecognisedAndTheTableSaysSo) {
  SyntheticSpec spec;
  spec.objects = 8;
  spec.modalities = {{"audio", 8, 10.0}};  // object means ~40 noise sd apart: near-certain
  const FeatureSet set = synthetic(spec, "fm_separated");
  const DatasetTask task = make_dataset_task(set, nullptr, HoldOut::session);
  const auto folds = make_folds(set, task);
  const ObservationModel model =
      fit_observation_model(set, task, training_sessions(set, folds[0]), session_fit_options());
  EXPECT_EQ(model.classes(), set.objects);
  EXPECT_EQ(model.calibration(set.actions[0].name).fit->fused_accuracy, 1.0);
  EXPECT_EQ(test_accuracy(model, set, task, folds[0]), 1.0);
  for (std::size_t c = 0; c < 8; ++c) {
    double sum = 0.0;
    for (double p : model.observation_table(set.actions[0].name)[c]) {
      EXPECT_GT(p, 0.0);
      sum += p;
    }
    EXPECT_NEAR(sum, 1.0, 1e-9);
    EXPECT_GT(model.observation_table(set.actions[0].name)[c][c], 0.8);
  }
}

TEST(FitOnFeatureSets, ANoiseModalityIsWeighedOutAndFusionIsNoWorseThanTheBestModality) {
  SyntheticSpec spec;
  spec.objects = 20;
  spec.modalities = {{"audio", 5, 1.0}, {"haptic", 20, 0.0}};  // haptic: pure noise
  const FeatureSet set = synthetic(spec, "fm_noise");
  const DatasetTask task = make_dataset_task(set, nullptr, HoldOut::session);
  const auto folds = make_folds(set, task);
  const ObservationModel model =
      fit_observation_model(set, task, training_sessions(set, folds[0]), session_fit_options());
  const ActionFit& fit = (*model.calibration(set.actions[0].name).fit);
  const auto& modalities = model.modalities(set.actions[0].name);
  ASSERT_EQ(modalities.size(), 2u);
  EXPECT_EQ(modalities[0].name, "audio");
  EXPECT_EQ(modalities[1].name, "haptic");
  const std::vector<double>& weights = model.weights(set.actions[0].name);
  EXPECT_LT(fit.modality_accuracy[1], 0.2);  // chance is 0.05
  EXPECT_GT(fit.modality_accuracy[0], 0.25);
  // Fitted on 80 held-out rows, the noise keeps a little weight (modality_fusion_test shows it
  // vanishing with 2000).
  EXPECT_LT(weights[1], 0.25 * weights[0]);
  EXPECT_LE(fit.fused_nll, fit.modality_nll[0] + 1e-9);
  EXPECT_GE(fit.fused_accuracy, fit.modality_accuracy[0] - 0.02);
}

TEST(FitOnFeatureSets, TemperingKeepsCorrelatedRepeatsFromBecomingOverconfident) {
  SyntheticSpec spec;
  spec.objects = 20;
  spec.repeats = 6;
  spec.session_sd = 1.5;  // a session's repeats share an offset as large as the noise
  spec.modalities = {{"audio", 4, 1.5}};
  const FeatureSet set = synthetic(spec, "fm_correlated");
  const DatasetTask task = make_dataset_task(set, nullptr, HoldOut::session);
  double tempered_nll = 0.0, untempered_nll = 0.0;
  double untempered_confidence = 0.0, tempered_confidence = 0.0, right = 0.0, n = 0.0;
  for (const Fold& fold : make_folds(set, task)) {
    const ObservationModel model =
        fit_observation_model(set, task, training_sessions(set, fold), session_fit_options());
    const double beta = (*model.calibration(set.actions[0].name).fit).temper;
    EXPECT_LT(beta, 0.7);
    // A session's offset is not a lookalike: the share fitted on the tempered tables mixes those.
    EXPECT_FALSE(model.lookalikes_untempered(ObservationKind::labels));
    const Table& tempered = model.observation_table(set.actions[0].name);
    const Table untempered = temper(tempered, 1.0 / beta);  // (p^b)^(1/b) renormalised = p
    for (int s : fold.test_sessions) {
      Sequence seq{task.class_of_object[set.sessions[s].object], {}};
      for (int r = 0; r < static_cast<int>(set.actions[0].rows.size()); ++r)
        if (set.actions[0].rows[r].session == s)
          seq.symbols.push_back(classify_row(model, 0, set, r));
      const std::vector<Sequence> one{seq};
      tempered_nll += sequence_nll(tempered, 1.0, one);
      untempered_nll += sequence_nll(untempered, 1.0, one);
      // Confidence in the most probable class, posterior = exp(-NLL) of each class.
      auto confidence = [&](const Table& t) {
        double best = 0.0;
        int best_class = 0;
        for (int c = 0; c < static_cast<int>(t.size()); ++c) {
          const double p = std::exp(-sequence_nll(t, 1.0, std::vector<Sequence>{{c, seq.symbols}}));
          if (p > best) best = p, best_class = c;
        }
        return std::pair{best, best_class};
      };
      const auto [u, guess] = confidence(untempered);
      untempered_confidence += u;
      tempered_confidence += confidence(tempered).first;
      right += guess == seq.true_class;
      n += 1.0;
    }
  }
  const double accuracy = right / n;
  EXPECT_LT(tempered_nll, untempered_nll);
  EXPECT_GT(untempered_confidence / n, accuracy + 0.1) << "untempered is overconfident";
  EXPECT_NEAR(tempered_confidence / n, accuracy, 0.1) << "tempered is calibrated";
}

// `set` with every performance heard twice: each row followed by an exact copy, marked as a noisy
// copy (RowLabel::noisy_copy) or not.
FeatureSet with_copies(const FeatureSet& set, bool marked) {
  FeatureSet copied = set;
  for (ActionData& action : copied.actions) {
    action.rows.clear();
    for (Modality& m : action.modalities) m.rows.clear();
  }
  for (std::size_t a = 0; a < set.actions.size(); ++a)
    for (std::size_t r = 0; r < set.actions[a].rows.size(); ++r)
      for (bool copy : {false, true}) {
        RowLabel row = set.actions[a].rows[r];
        row.noisy_copy = copy && marked;
        copied.actions[a].rows.push_back(row);
        for (std::size_t m = 0; m < set.actions[a].modalities.size(); ++m)
          copied.actions[a].modalities[m].rows.push_back(set.actions[a].modalities[m].rows[r]);
      }
  return copied;
}

// A noisy copy is the same performance heard again, not a repeat: tempering must not take a
// copy's agreement with its recording for the agreement of two performances. The tables are the
// same whether the copies are marked or not (they count every row); only the sequences differ.
// Marked, the copies form sequences of their own, the recordings' again, so the fitted temper is
// the one the recordings' sequences ask for. Taken as repeats, every sequence holds each symbol
// twice, which a temper of half (up to the tempered rows' normalisation) scores as the marked
// temper scores it once: the temper about halves.
TEST(FitOnFeatureSets, NoisyCopiesAreNotTakenForRepeats) {
  SyntheticSpec spec;
  spec.objects = 20;
  spec.repeats = 3;
  spec.modalities = {{"audio", 4, 1.5}};
  const FeatureSet set = synthetic(spec, "fm_copies");
  const DatasetTask task = make_dataset_task(set, nullptr, HoldOut::session);
  const Fold fold = make_folds(set, task)[0];
  const auto temper_of = [&](const FeatureSet& data) {
    return fit_observation_model(data, task, training_sessions(data, fold), session_fit_options())
        .calibration(set.actions[0].name)
        .fit->temper;
  };
  const double marked = temper_of(with_copies(set, true)),
               unmarked = temper_of(with_copies(set, false));
  EXPECT_NEAR(unmarked, marked / 2, 0.1 * marked) << marked;
}

TEST(FitOnFeatureSets, NovelObjectsAreRecognisedByTheirGroup) {
  SyntheticSpec spec;
  spec.objects = 20;
  spec.sessions = 2;
  spec.group_size = 5;
  spec.group_separation = 6.0;  // group means ~24 sd apart; objects within a group ~ 4 sd
  spec.modalities = {{"audio", 8, 1.0}};
  const auto dir = test_features::fresh_folder("fm_groups");
  test_features::write_synthetic_feature_set(dir, spec);
  const FeatureSet set = load_feature_set(dir.string());
  const ObjectGroups groups = load_groups((dir / "groups.csv").string());
  const DatasetTask task = make_dataset_task(set, &groups, HoldOut::object);
  const auto folds = make_folds(set, task);
  ASSERT_EQ(folds.size(), 5u);
  for (const char* classifier : {"lda", "nearest-neighbour"}) {
    double accuracy = 0.0;
    for (const Fold& fold : folds) {
      const ObservationModel model = fit_observation_model(set, task, training_sessions(set, fold),
                                                           session_fit_options(classifier));
      EXPECT_EQ(model.classes().size(), 4u);
      accuracy += test_accuracy(model, set, task, fold) / 5.0;
    }
    EXPECT_GT(accuracy, 0.95) << classifier;
  }
}

// Objects that look like another group in every behaviour (the stand-in of
// bench/honest_confidence.sh) give the model a share of lookalikes; the same set without them
// gives a much smaller one.
TEST(FitOnFeatureSets, ObjectsThatSoundLikeAnotherGroupInEveryBehaviourGiveALookalikeShare) {
  auto share = [](double lookalike, const char* name) {
    SyntheticSpec spec;
    spec.objects = 40;
    spec.group_size = 5;
    spec.sessions = 5;
    spec.actions = {"press", "shake", "squeeze", "tap"};
    spec.modalities = {{"audio", 6, 1.5}, {"haptic", 3, 1.0}};
    spec.group_separation = 1.5;
    spec.session_sd = 0.3;
    spec.lookalike_share = lookalike;
    spec.lookalike_pull = 0.6;
    const auto dir = test_features::fresh_folder(name);
    test_features::write_synthetic_feature_set(dir, spec);
    const FeatureSet set = load_feature_set(dir.string());
    const ObjectGroups groups = load_groups((dir / "groups.csv").string());
    const DatasetTask task = make_dataset_task(set, &groups, HoldOut::object);
    const ObservationModel model = fit_observation_model(
        set, task, training_sessions(set, make_folds(set, task).front()), session_fit_options());
    EXPECT_EQ(model.lookalike_share(ObservationKind::labels), model.description().lookalike_share);
    return std::array{model.lookalike_share(ObservationKind::labels),
                      model.lookalike_share(ObservationKind::graded)};
  };
  const auto typical = share(0.0, "fm_typical");
  const auto lookalike = share(0.25, "fm_lookalike");
  // Each share (labels, graded) is well above 0 with them and less than half that without.
  // Measured: 0.000 (graded 0.000) without; 0.124 (0.114) with a quarter of the objects pulled
  // towards another group.
  for (std::size_t i = 0; i < typical.size(); ++i) {
    EXPECT_GT(lookalike[i], 0.05) << i;
    EXPECT_LT(typical[i], lookalike[i] / 2) << i;
  }
}

TEST(FitOnFeatureSets, TrainingWithoutAClassIsAnError) {
  SyntheticSpec spec;
  spec.objects = 3;
  const FeatureSet set = synthetic(spec, "fm_missing");
  const DatasetTask task = make_dataset_task(set, nullptr, HoldOut::session);
  const std::vector<int> only_first_two{0, 1, 2, 5, 6, 7};  // object 2's sessions are 10-14
  EXPECT_THROW(fit_observation_model(set, task, only_first_two, session_fit_options()), InputError);
}

// The reject option is open to rows a sensor gave: one modality, cross-validated by performance
// (the recordings defaults, FitOptions{}). A row far from every class is `unknown`, the table has
// its column, and the set's own rows keep their classes.
TEST(FitOnFeatureSets, RowsASensorGaveCanBeRejectedAsUnknown) {
  SyntheticSpec spec;
  spec.objects = 4;
  spec.sessions = 4;
  spec.modalities = {{"haptic", 4, 6.0}};
  const FeatureSet set = synthetic(spec, "fm_reject");
  const DatasetTask task = make_dataset_task(set, nullptr, HoldOut::session);
  std::vector<int> all(set.sessions.size());
  std::iota(all.begin(), all.end(), 0);
  FitOptions options;
  options.classifier = "lda";
  const ObservationModel model = fit_observation_model(set, task, all, options);
  ASSERT_TRUE(model.reject());
  EXPECT_EQ(model.observation_symbols().back(), kUnknownSymbol);
  EXPECT_EQ(model.observation_table("strike").front().size(), 5u);  // 4 classes, unknown
  const ActionCalibration& c = model.calibration("strike");
  EXPECT_TRUE(std::isfinite(c.reject_threshold));
  EXPECT_NE(c.temperature, 1.0);  // fitted, not fusion's
  const std::vector<double> far(4, 1e4);
  const std::vector<std::span<const double>> rows{far};
  EXPECT_EQ(model.classify_rows(0, rows).label, kUnknownSymbol);
  int right = 0;
  for (int r = 0; r < static_cast<int>(set.actions[0].rows.size()); ++r)
    right += classify_row(model, 0, set, r) == set.actions[0].rows[r].object;
  EXPECT_EQ(right, static_cast<int>(set.actions[0].rows.size()));
  // Several modalities cannot share one reject threshold: the option is refused, naming the action.
  spec.modalities = {{"audio", 3, 6.0}, {"haptic", 3, 6.0}};
  const FeatureSet two = synthetic(spec, "fm_reject_two");
  try {
    fit_observation_model(two, make_dataset_task(two, nullptr, HoldOut::session), all, options);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("one modality per action, and 'strike' has 2"), std::string::npos)
        << e.problem();
  }
}

// Without fusion the modalities' scores are summed at weight 1 and one temperature calibrates
// them: on two informative modalities the summed decision is still right where each is, and the
// fusion weights, fitted instead, weigh both in.
TEST(FitOnFeatureSets, ModalitiesCanBeSummedUnderOneTemperatureInsteadOfFused) {
  SyntheticSpec spec;
  spec.objects = 10;
  spec.modalities = {{"audio", 5, 2.0}, {"haptic", 5, 2.0}};
  const FeatureSet set = synthetic(spec, "fm_summed");
  const DatasetTask task = make_dataset_task(set, nullptr, HoldOut::session);
  const auto folds = make_folds(set, task);
  FitOptions summed = session_fit_options();
  summed.fuse = false;
  const ObservationModel plain =
      fit_observation_model(set, task, training_sessions(set, folds[0]), summed);
  const ObservationModel fused =
      fit_observation_model(set, task, training_sessions(set, folds[0]), session_fit_options());
  EXPECT_EQ(plain.weights("strike"), (std::vector<double>{1.0, 1.0}));
  EXPECT_NE(plain.calibration("strike").temperature, 1.0);
  EXPECT_EQ(fused.calibration("strike").temperature, 1.0);
  for (double w : fused.weights("strike")) EXPECT_GT(w, 0.0);
  const ActionFit& fit = *plain.calibration("strike").fit;
  for (double alone : fit.modality_accuracy) EXPECT_GE(fit.fused_accuracy, alone);
}

TEST(FitOnFeatureSets, CombinationsWithoutMeaningAreRefused) {
  FitOptions temper_alone;
  temper_alone.temper = true;  // by performance: no sessions to temper over
  EXPECT_THROW(check_fit_options(temper_alone), InputError);
  FitOptions shrunk_rejecting;
  shrunk_rejecting.table = TableEstimate::shrunk;  // reject is on by default
  EXPECT_THROW(check_fit_options(shrunk_rejecting), InputError);
  FitOptions preset_on_rows = session_fit_options("summary-lda");
  SyntheticSpec spec;
  spec.objects = 3;
  const FeatureSet set = synthetic(spec, "fm_preset");
  std::vector<int> all(set.sessions.size());
  std::iota(all.begin(), all.end(), 0);
  try {
    fit_observation_model(set, make_dataset_task(set, nullptr, HoldOut::session), all,
                          preset_on_rows);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("is an audio preset over 'summary' rows of clips"),
              std::string::npos)
        << e.problem();
  }
  EXPECT_NO_THROW(check_fit_options(FitOptions{}));
  EXPECT_NO_THROW(check_fit_options(session_fit_options()));
}

// The scale of the largest recorded set: 100 objects x 9 behaviours x 5 sessions, two modalities
// of 50 features, one fold fitted. How long it takes is a benchmark figure (docs/BENCHMARKS.md),
// not asserted here: a loaded machine or a sanitizer build would make a time limit flaky.
TEST(FitOnFeatureSets, OneFoldAtFullScaleFits) {
  SyntheticSpec spec;
  spec.objects = 100;
  spec.actions = {"a1", "a2", "a3", "a4", "a5", "a6", "a7", "a8", "a9"};
  spec.modalities = {{"audio", 50, 0.5}, {"haptic", 50, 0.3}};
  const FeatureSet set = synthetic(spec, "fm_scale");
  const DatasetTask task = make_dataset_task(set, nullptr, HoldOut::session);
  const auto folds = make_folds(set, task);
  const auto start = std::chrono::steady_clock::now();
  const ObservationModel model =
      fit_observation_model(set, task, training_sessions(set, folds[0]), session_fit_options());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("one fold, 100 objects x 9 actions x 4 training sessions x 2 x 50 features: %.2f s\n",
              seconds);
  EXPECT_EQ(model.actions().size(), 9u);
  for (const std::string& action : model.actions())
    EXPECT_EQ(model.observation_table(action).size(), 100u) << action;
}

}  // namespace
}  // namespace echoplan::perception
