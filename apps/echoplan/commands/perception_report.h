// Printing what `echoplan train` and `echoplan evaluate` measured: accuracy and a confusion matrix
// per action.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "perception/calibration.h"

namespace echoplan::cli {

// "0.917 (11 of 12)": the share heard right among the model's classes, and the counts.
std::string accuracy_text(const perception::ConfusionMatrix& confusion);

// "<title>: accuracy 0.917 (11 of 12)" then the matrix, rows = true object, columns = reported
// symbol.
void print_confusion(const std::string& title, const perception::ConfusionMatrix& confusion);

// {"accuracy", "objects", "symbols", "confusion"}.
nlohmann::json confusion_json(const perception::ConfusionMatrix& confusion);

}  // namespace echoplan::cli
