#include "experiment/input_files.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/file_io.h"
#include "common/stable_hash.h"
#include "experiment/analysed_recordings.h"
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
      // Only where there is one, so the data of sets without series keeps its name.
      if (!m.series.empty()) text += m.series + '\n';
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

InputFiles::InputFiles(std::vector<std::filesystem::path> campaign_folders,
                       perception::SeriesChoices series)
    : campaign_folders_(std::move(campaign_folders)), series_(std::move(series)) {}

std::shared_ptr<const perception::FeatureSet> InputFiles::load(const std::string& folder,
                                                               const ProgressFn& progress) {
  if (campaign_folders_.empty() ||
      perception::data_kind(folder) != perception::DataKind::recordings)
    return std::make_shared<const perception::FeatureSet>(
        perception::load_data(folder, progress, series_));
  const perception::RecordingSet set = perception::load_recording_set(folder);
  // A kept analysis is this tree's only if its series were turned into rows the same way.
  std::string listing = recordings_listing(set);
  for (const auto& [modality, spec] : series_) listing += fmt::format(" {}={}", modality, spec);
  for (const std::filesystem::path& campaign : campaign_folders_)
    if (auto kept = read_analysed_recordings(campaign / kAnalysedRecordings, folder, listing))
      return std::make_shared<const perception::FeatureSet>(std::move(*kept));
  auto data = std::make_shared<const perception::FeatureSet>(
      perception::feature_set_from_recordings(set, {}, progress, "summary", series_));
  analysed_ = Analysed{folder, listing, data};
  return data;
}

std::shared_ptr<const perception::FeatureSet> InputFiles::data(const std::string& folder,
                                                               const ProgressFn& progress) {
  auto it = data_.find(folder);
  if (it == data_.end()) it = data_.emplace(folder, load(folder, progress)).first;
  return it->second;
}

void InputFiles::keep_analysed() const {
  if (!analysed_ || campaign_folders_.empty()) return;
  write_analysed_recordings(campaign_folders_.front() / kAnalysedRecordings, analysed_->folder,
                            analysed_->listing, *analysed_->data);
}

std::string InputFiles::fingerprint(const std::string& path) {
  return fmt::format("{:016x}", stable_hash(text(path)));
}

std::string InputFiles::data_fingerprint(const std::string& folder) {
  return fmt::format("{:016x}", stable_hash(data_text(*data(folder))));
}

}  // namespace echoplan::experiment
