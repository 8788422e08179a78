// Reference results: what another system reported for the same trials (the report's Tables 5.1
// and 5.3, or later the lab's own runs), shown beside a campaign's results. They are data, read
// from a YAML file the campaign names (`reference:`; format: experiments/chapter5_reference.yaml,
// docs/experiment.md), so comparing against another reference needs no code.
//
// A reference is matched to the campaign's summary by structure: a result per object (the
// campaign's trial groups, by the object the world holds) and optional totals over the original
// objects, the variants or all, each naming the objects it covers. The same reference stands beside
// every arm.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "experiment/heard_reference.h"

namespace echoplan::experiment {

// One reported result: trials, correct ones, mean discounted reward and mean steps.
struct ReferenceResult {
  int trials = 0;   // >= 1
  int correct = 0;  // <= trials
  double mean_discounted_reward = 0.0;
  double mean_steps = 0.0;
};

// A reported result over several objects; it stands beside a campaign total only when the total
// covers exactly these objects.
struct ReferenceTotal {
  std::vector<std::string> objects;  // in the file's order
  ReferenceResult result;
};

struct ReferenceResults {
  std::string source;  // the file it was read from
  std::string label;   // names the reference in column headings, e.g. "report"
  std::string note;    // a sentence for the page saying where the numbers come from; may be empty
  std::map<std::string, ReferenceResult> objects;  // by the object in the world
  std::optional<ReferenceTotal> original_objects;  // objects that play themselves
  std::optional<ReferenceTotal> variants;          // objects that play another
  std::optional<ReferenceTotal> all;
  // What the lab's classifier heard per action (`heard:`), shown beside a simulated world's
  // training set heard by the same classifier; none: no such comparison.
  std::optional<HeardReference> heard;
};

// Reads a reference file; throws InputError naming the file, the line and the problem.
ReferenceResults load_reference_results(const std::string& path);

// As load_reference_results, from text; `source` names it in messages.
ReferenceResults parse_reference_results(const std::string& yaml_text, const std::string& source);

// As JSON and back, for campaign.json (a merged or resumed run's report needs no reference file).
// Throws InputError(source, 0, ...) for bad JSON.
nlohmann::json to_json(const ReferenceResults& reference);
ReferenceResults reference_results_from_json(const nlohmann::json& j, const std::string& source);

}  // namespace echoplan::experiment
