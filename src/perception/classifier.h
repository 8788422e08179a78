// A classifier of one modality: a row classifier (row_classifier.h) and, for audio, the clip
// extractor (clip_extractor.h) that turns a clip into its row. The audio presets by name pair the
// two:
//   summary-lda           summary + lda-class-scaled   (the default)
//   summary-nearest-mean  summary + nearest-mean
//   report-template       onset-logfbank + template    (the report's classifier)
//   report-gaussian       centroid-rms + gaussian      (the report's first attempt)
//   grid-lda              spectrogram-grid + lda-class-scaled  (CY101's audio layout)
//   pcen-lda              pcen-summary + lda-class-scaled      (PCEN front end against noise)
// A modality whose rows are given (a feature set's haptic.csv, a feature topic) has a classifier
// without an extractor, named after its row classifier (make_modality_classifier).
#pragma once

#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "perception/clip_analysis.h"
#include "perception/clip_extractor.h"
#include "perception/row_classifier.h"

namespace echoplan::perception {

class Classifier final {
 public:
  // `extractor` may be null: rows are given, not computed from clips.
  Classifier(std::string name, const ClipExtractor* extractor, std::unique_ptr<RowClassifier> rows);

  // The preset name ("summary-lda", ...), or the row classifier's name when rows are given.
  const std::string& name() const { return name_; }
  // Null when rows are given.
  const ClipExtractor* extractor() const { return extractor_; }
  const RowClassifier& rows() const { return *rows_; }

  // The extractor's row of one analysed clip (a pure function of the clip, so training computes
  // it once per recording and cross-validation reuses it). InputError when rows are given.
  std::vector<double> embed(const ClipAnalysis& clip) const;
  void fit(std::span<const std::vector<double>> rows, std::span<const int> labels,
           int num_classes) {
    rows_->fit(rows, labels, num_classes);
  }
  int num_classes() const { return rows_->num_classes(); }
  ClassScores score(std::span<const double> row) const { return rows_->score(row); }
  // score(embed(clip)).
  ClassScores score_clip(const ClipAnalysis& clip) const { return score(embed(clip)); }
  // A new, unfitted classifier of the same kind and settings.
  std::unique_ptr<Classifier> clone_unfitted() const;
  // The row classifier's fit (the model file's "classifier" object of a modality).
  nlohmann::json save() const;
  void load(const nlohmann::json& fit, const std::string& source);

 private:
  std::string name_;
  const ClipExtractor* extractor_;
  std::unique_ptr<RowClassifier> rows_;
};

// The audio preset the commands use when none is named.
inline constexpr std::string_view kDefaultClassifier = "summary-lda";

// Names of every audio preset, default first.
std::vector<std::string> classifier_names();

// Earlier names of presets, each with its current name: "seed-template" and "seed-gaussian" (the
// report's two classifiers, named before "seed" was kept for random seeds). Model files, campaign
// files and scripts written with them keep working.
const std::map<std::string, std::string>& classifier_aliases();

// `name` is an audio preset or one of its aliases (else, perhaps, a row classifier).
bool is_audio_preset(std::string_view name);

// A new unfitted audio classifier, by preset name or alias (its name() is always the current one).
// Throws InputError listing the names for an unknown one.
std::unique_ptr<Classifier> make_classifier(std::string_view name);

// A new unfitted classifier of a modality computed from series (series_features.h) under the
// model's classifier `name`: that row classifier, or an audio preset's own row classifier (the
// preset's clip extractor has nothing to do with series). InputError for an unknown name.
std::unique_ptr<Classifier> make_series_classifier(std::string_view name);

// A new unfitted classifier of one modality by row classifier name, named after it, with the clip
// extractor `extractor` (empty: rows are given). InputError for an unknown name.
std::unique_ptr<Classifier> make_modality_classifier(std::string_view row_classifier,
                                                     std::string_view extractor = {});

}  // namespace echoplan::perception
