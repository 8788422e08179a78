// The observation model file: one JSON document, read back with every field checked.
//
// One file for every model, whatever its data (JSON, format "echoplan-observation-model",
// version 2):
//   { "format", "version", "analysis": {sample_rate, preset, onset {...}, silence_rms},
//     "classifier": an audio preset (make_classifier) or a row classifier (row_classifier_names),
//     "classes": [...], "actions": [...], "reject": bool, "dirichlet_alpha",
//     "table_estimate": "counts" | "soft" | "shrunk",
//     "per_action": { action: {
//         "modalities": [ {"name", "extractor": clip extractor or null, "classifier": {fit},
//                          "series": series features spec (only for a modality of series)} ],
//         "weights": [one per modality], "temperature", "reject_threshold" (null without reject),
//         "symbols": [...], "confusion": [[counts]], "table": [[P(o|k)]],
//         "fit": {modality_accuracy, modality_nll, fused_accuracy, fused_nll,
//                 shrinkage_strength, temper, graded_temper} (models fitted on sessions only),
//         "grades": {"edges": [2 ascending confidences], "given_right": [3], "given_wrong": [3],
//                    "table": [[P(graded symbol|k)]]} (observation_grades.h) } } }
// A file without "grades" (written before graded observations existed) loads and serves labels.
// Version 1 files (one audio classifier per action: per_action.<action>.classifier, no modalities
// or weights; table_estimate absent before it existed: counts) still load, as one "audio" modality
// of weight 1.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "perception/observation_model.h"

namespace echoplan::perception {

inline constexpr int kModelFormatVersion = 2;

nlohmann::json observation_model_to_json(const ObservationModel& model);
// Throws InputError(source, 0, "<field>: <problem>") for a malformed document or a wrong version.
ObservationModel observation_model_from_json(const nlohmann::json& doc, const std::string& source);

// Reads the model file. Errors name the file: missing, not JSON (with the byte offset), truncated,
// wrong format or version, or a field out of shape.
ObservationModel load_observation_model(const std::string& path);
// Parses a model file's text; `source` names it in errors. What load_observation_model does after
// reading.
ObservationModel parse_observation_model(const std::string& text, const std::string& source);
// Writes the model file atomically: an interrupted save never leaves half a model.
void save_observation_model(const ObservationModel& model, const std::string& path);

}  // namespace echoplan::perception
