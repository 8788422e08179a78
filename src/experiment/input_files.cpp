#include "experiment/input_files.h"

#include <fmt/format.h>

#include "common/file_io.h"
#include "common/stable_hash.h"
#include "perception/recording_features.h"

namespace echoplan::experiment {

namespace {

// The loaded data as one text: every name and value in the data's own order.
std::string data_text(const perception::FeatureSet& data) {
  std::string text;
  for (const std::string& object : data.objects) text += object + '\n';
  for (const perception::Session& s : data.sessions)
    text += fmt::format("{} {}\n", s.object, s.name);
  for (const perception::ActionData& action : data.actions) {
    text += action.name + '\n';
    for (const perception::RowLabel& row : action.rows)
      text += fmt::format("{} {}\n", row.object, row.session);
    for (const perception::Modality& m : action.modalities) {
      text += fmt::format("{} {} {}\n", m.name, m.extractor, fmt::join(m.feature_names, ","));
      for (const std::vector<double>& row : m.rows)
        text += fmt::format("{}\n", fmt::join(row, ","));
    }
  }
  return text;
}

}  // namespace

const std::string& InputFiles::text(const std::string& path) {
  auto it = texts_.find(path);
  if (it == texts_.end()) it = texts_.emplace(path, read_text_file(path, "file")).first;
  return it->second;
}

std::shared_ptr<const pomdp::Problem> InputFiles::problem(const std::string& path) {
  auto it = problems_.find(path);
  if (it == problems_.end())
    it =
        problems_
            .emplace(path,
                     std::make_shared<const pomdp::Problem>(pomdp::parse_problem(text(path), path)))
            .first;
  return it->second;
}

std::shared_ptr<const perception::FeatureSet> InputFiles::data(const std::string& folder,
                                                               const ProgressFn& progress) {
  auto it = data_.find(folder);
  if (it == data_.end())
    it = data_
             .emplace(folder, std::make_shared<const perception::FeatureSet>(
                                  perception::load_data(folder, progress)))
             .first;
  return it->second;
}

std::string InputFiles::fingerprint(const std::string& path) {
  return fmt::format("{:016x}", stable_hash(text(path)));
}

std::string InputFiles::data_fingerprint(const std::string& folder) {
  return fmt::format("{:016x}", stable_hash(data_text(*data(folder))));
}

}  // namespace echoplan::experiment
