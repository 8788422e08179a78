// report_inputs.json, what a campaign's preparation leaves for its report: read back exactly as
// written (the templates' floats bit for bit, so a rebuilt page draws the same figures), nothing
// when the folder has none, and a damaged file refused with its name and the field.
#include "experiment/report_inputs.h"

#include <gtest/gtest.h>

#include <fstream>

#include "../common/test_folder.h"
#include "common/error.h"

namespace echoplan::experiment {
namespace {

using ReportInputsFile = TestFolder;

ReportInputs two_of_each() {
  ReportInputs inputs;
  inputs.heard = {{"strike", {"mug", "cup"}, {"mug", "cup"}, {{9, 1}, {2, 8}}},
                  {"slide", {"mug", "cup"}, {"mug", "cup"}, {{7, 3}, {0, 10}}}};
  TemplateMatrix t;
  t.object = "mug";
  t.action = "strike";
  t.hop_seconds = 512.0 / 44100.0;
  t.recordings = 3;
  t.mean.resize(2, 3);
  t.mean.values = {-1.0f / 3.0f, 0.1f, 1e-7f, -80.25f, 3.0e5f, 0.0f};
  inputs.templates = {t, t};
  inputs.templates[1].object = "cup";
  return inputs;
}

TEST_F(ReportInputsFile, ReadsBackWhatWasWritten) {
  const ReportInputs written = two_of_each();
  write_report_inputs(dir_, written);
  const ReportInputs read = read_report_inputs(dir_);
  ASSERT_EQ(read.heard.size(), 2u);
  EXPECT_EQ(read.heard[1].action, "slide");
  EXPECT_EQ(read.heard[1].rows, written.heard[1].rows);
  EXPECT_EQ(read.heard[1].counts, written.heard[1].counts);
  ASSERT_EQ(read.templates.size(), 2u);
  EXPECT_EQ(read.templates[1].object, "cup");
  EXPECT_EQ(read.templates[0].recordings, 3);
  EXPECT_EQ(read.templates[0].hop_seconds, written.templates[0].hop_seconds);
  EXPECT_EQ(read.templates[0].mean.rows, 2u);
  EXPECT_EQ(read.templates[0].mean.cols, 3u);
  EXPECT_EQ(read.templates[0].mean.values, written.templates[0].mean.values);
}

TEST_F(ReportInputsFile, NoFileIsNothingToShow) {
  const ReportInputs read = read_report_inputs(dir_);
  EXPECT_TRUE(read.heard.empty());
  EXPECT_TRUE(read.templates.empty());
}

// The message of reading a report_inputs.json holding `text`.
std::string error_reading(const std::filesystem::path& dir, const std::string& text) {
  std::ofstream(dir / kReportInputs) << text;
  try {
    read_report_inputs(dir);
  } catch (const InputError& e) {
    return e.file() + ": " + e.problem();
  }
  return "no error";
}

TEST_F(ReportInputsFile, ADamagedFileNamesItselfAndTheField) {
  const std::string file = (dir_ / kReportInputs).string();
  EXPECT_EQ(error_reading(dir_, "{\"heard\": [], \"templ"), file + ": is not JSON");
  const std::string no_templates = error_reading(dir_, "{\"heard\": []}");
  EXPECT_EQ(no_templates.substr(0, file.size()), file);
  EXPECT_NE(no_templates.find("templates"), std::string::npos) << no_templates;
  // Six values promised, five given.
  const std::string short_mean =
      error_reading(dir_,
                    "{\"heard\": [], \"templates\": [{\"object\": \"mug\", \"action\": \"strike\", "
                    "\"hop_seconds\": 0.01, \"recordings\": 2, \"frames\": 2, \"bands\": 3, "
                    "\"mean\": [1, 2, 3, 4, 5]}]}");
  EXPECT_NE(short_mean.find("templates[0].mean"), std::string::npos) << short_mean;
}

}  // namespace
}  // namespace echoplan::experiment
