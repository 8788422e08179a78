// `echoplan train --recipe sessions`: recorded data (a feature set, or a recordings tree turned
// into one) fitted into the observation model on all its sessions (perception/feature_model.h),
// the model file and the planning problem of it written for the user (docs/feature-sets.md,
// "echoplan train --data").
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "loop/dataset_problem.h"

namespace echoplan::cli {

struct DatasetTrainFlags {
  std::string data;         // DIR (set by train from its --data)
  std::string out;          // the model file (set by train from its --out); may be empty
  std::string problem_out;  // set by train from its --problem-out; required without `out`
  std::string groups;       // optional groups file
  std::string hold_out;     // "session" (default) or "object"
  std::string classifier = "lda";
  std::string costs;  // optional costs file (behaviour,cost): rewards.costs once the data is read
  loop::TaskRewards rewards;
};

// Adds --groups, --hold-out, --feature-classifier, the --reward-* options and --costs to `cmd`.
void add_dataset_train_options(CLI::App& cmd, DatasetTrainFlags& flags);

// Loads, fits, prints the held-out accuracies and writes the model and the problem. InputError for
// bad input (neither --out nor --problem-out, a DIR that is neither kind of data, a groups file
// that misses an object, too few sessions or objects for the hold-out, a bad costs file).
void train_dataset(DatasetTrainFlags flags);

}  // namespace echoplan::cli
