// What a campaign's report shows of its world besides the trials, worked out when the campaign is
// prepared and kept in the campaign's folder (report_inputs.json), so that rebuilding the report
// reads files only: it synthesises nothing, opens no recording and fits no model.
#pragma once

#include <filesystem>
#include <vector>

#include "experiment/campaign_figures.h"
#include "experiment/heard_reference.h"

namespace echoplan::experiment {

// The file's name in the campaign folder; `echoplan merge` copies it from the first shard.
inline constexpr const char* kReportInputs = "report_inputs.json";

struct ReportInputs {
  // A simulated world's training set (and the trials' variants) heard by the reference's
  // classifier (CampaignResults::heard); empty when the world has none.
  std::vector<HeardCounts> heard;
  // The training set's mean log-mel around each recording's onset, per object and action (the
  // page's templates figure); empty when the world has no training recordings.
  std::vector<TemplateMatrix> templates;
};

// Writes `inputs` as `directory`/report_inputs.json (atomically).
void write_report_inputs(const std::filesystem::path& directory, const ReportInputs& inputs);

// Reads `directory`/report_inputs.json; empty inputs when the folder has none (a world that shows
// nothing besides its trials). Throws InputError naming the file and field when it is malformed.
ReportInputs read_report_inputs(const std::filesystem::path& directory);

}  // namespace echoplan::experiment
