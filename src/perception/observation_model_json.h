// The observation model file: one JSON document, read back with every field checked.
//
// Model file (JSON, format "echoplan-observation-model", version 1):
//   { "format", "version", "analysis": {sample_rate, preset, onset {...}, silence_rms},
//     "classifier": name, "classes": [...], "actions": [...], "reject": bool, "dirichlet_alpha",
//     "table_estimate": "counts" | "soft" (absent in files written before it existed: "counts"),
//     "per_action": { action: { "classifier": {fit}, "temperature", "reject_threshold",
//                               "confusion": [[counts]], "symbols": [...], "table": [[P(o|k)]] } }
//                               }
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "perception/observation_model.h"

namespace echoplan::perception {

inline constexpr int kModelFormatVersion = 1;

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
