// What a classifier heard, per sensing action: counts of recordings of each object (rows) heard as
// each class (columns). The lab's counts (the final experiments' logs) are data in the campaign's
// reference file (`heard:`, format: experiments/chapter5_reference.yaml, docs/experiment.md); a
// simulated world's training set is heard by the same classifier (campaign.cpp) and the page shows
// the two side by side: is the simulated world as hard to hear as the lab?
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace YAML {
class Node;
}

namespace echoplan {
class YamlReader;
}

namespace echoplan::experiment {

// One action's counts: counts[row][column], rows the true objects, columns the classes heard.
struct HeardCounts {
  std::string action;
  std::vector<std::string> rows;
  std::vector<std::string> columns;
  std::vector<std::vector<int>> counts;

  // Recordings of `row` heard as themselves / all of them (0 when the row is not a column).
  int right(std::size_t row) const;
  // Recordings of `row` heard as `column` (0 when it is not a column).
  int heard_as(std::size_t row, const std::string& column) const;
  int total(std::size_t row) const;
};

// The lab's counts and the classifier to hear a simulated training set with.
struct HeardReference {
  std::string classifier;  // a perception classifier name, e.g. "report-template"
  std::string note;        // where the counts come from; may be empty
  std::vector<HeardCounts> actions;
};

// The reference file's `heard:` mapping: classifier, optional note, classes (the columns) and
// actions: {action: {object: [count per class]}}. Throws InputError naming the file and line.
HeardReference read_heard_reference(const YamlReader& f, const YAML::Node& node);

nlohmann::json to_json(const HeardCounts& counts);
nlohmann::json to_json(const HeardReference& reference);
// From to_json's output; throws InputError(source, 0, ...) naming the path of a bad field.
HeardCounts heard_counts_from_json(const nlohmann::json& j, const std::string& path,
                                   const std::string& source);
HeardReference heard_reference_from_json(const nlohmann::json& j, const std::string& source);

}  // namespace echoplan::experiment
