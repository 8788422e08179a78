// The campaign's figures, PNG and SVG, drawn by gnuplot into DIR/figures:
//   belief_<arm>_<object>   the belief at each decision of each trial of a group (the report's
//   Fig. 5.1) templates               mean onset-aligned log-mel of each object and action in the
//   training set
//                           (the report's Figs. 3.1 and 3.2)
//   confusion_<arm>         heard class against the object in the world, per sensing action
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "audio/matrix.h"
#include "experiment/campaign_report.h"

namespace echoplan::experiment {

// The mean feature matrix of one object and action over its recordings.
struct TemplateMatrix {
  std::string object;
  std::string action;
  audio::FeatureMatrix mean;  // frames x mel bands
  double hop_seconds = 0.0;   // time between frames
  int recordings = 0;
};

// Mean log-mel (psf preset, mono) in a window of 5 frames before to 40 after each file's first
// onset, over DIR/<object>/<action>/*.wav, for each object and action that has recordings there.
std::vector<TemplateMatrix> template_matrices(const std::filesystem::path& recordings,
                                              const std::vector<std::string>& objects,
                                              const std::vector<std::string>& actions);

// One drawn figure: DIR/figures/<stem>.png and .svg.
struct Figure {
  std::string stem;
  std::string title;
  std::string caption;
};

// The data file gnuplot plots for one trial's belief panel: per step, "step p_0 p_1 ..." (the
// belief before the decision; particle counts when `belief_particles` > 0).
std::string belief_data(const std::vector<StepRecord>& steps, int belief_particles);

// The data file of one confusion panel: "column row count" per cell, rows outer.
std::string confusion_data(const ConfusionCounts& counts);

// Draws every figure with one gnuplot run per format; returns them in page order. Throws InputError
// when gnuplot is missing or fails.
std::vector<Figure> draw_figures(const std::filesystem::path& directory,
                                 const CampaignResults& results,
                                 const std::vector<TemplateMatrix>& templates);

}  // namespace echoplan::experiment
