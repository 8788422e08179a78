// End-to-end tests of `echoplan features` and `echoplan heatmap`: run the binary, check its output
// against the reference vectors and its exit status and message on bad input.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../common/source_dir.h"

namespace {

namespace fs = std::filesystem;
const std::string kInputs = echoplan::testing::source_dir() + "/tests/data/reference/audio/inputs/";
const std::string kExpected =
    echoplan::testing::source_dir() + "/tests/data/reference/audio/expected/";

struct CommandResult {
  int status = -1;
  std::string out, err;
};

CommandResult run(const std::string& args) {
  const fs::path dir =
      fs::temp_directory_path() / ("echoplan_cli_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string command = "'" + echoplan::testing::echoplan_binary() + "' " + args + " > '" +
                              (dir / "out").string() + "' 2> '" + (dir / "err").string() + "'";
  CommandResult r;
  const int raw = std::system(command.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  return r;
}

std::vector<std::vector<double>> parse_csv(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::stringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::stringstream cells(line);
    std::string cell;
    rows.emplace_back();
    while (std::getline(cells, cell, ',')) rows.back().push_back(std::stod(cell));
  }
  return rows;
}

TEST(FeaturesCommand, CsvIsTheReferenceMatrix) {
  // RMS is the feature least touched by float32 FFT error: the CLI's %.9g output must agree with
  // the reference to float32 output rounding (4 ulps relative). The library tests cover every
  // feature.
  const CommandResult r =
      run("features --preset librosa --feature rms " + kInputs + "pink_2s_44k_mono.wav");
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream ref_file(kExpected + "pink_2s_44k_mono/librosa_rms.csv");
  const auto expected = parse_csv(
      std::string((std::istreambuf_iterator<char>(ref_file)), std::istreambuf_iterator<char>()));
  const auto got = parse_csv(r.out);
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i].size(), 1u);
    EXPECT_NEAR(got[i][0], expected[i][0], 2.4e-7 * expected[i][0]);
  }
  const CommandResult logmel =
      run("features --preset psf --feature logmel " + kInputs + "real_cc0_cowbell.flac");
  ASSERT_EQ(logmel.status, 0) << logmel.err;
  const auto rows = parse_csv(logmel.out);
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.size(), 34u);  // shapes.json: psf_logfbank of the cowbell is 34 x 26
  EXPECT_EQ(rows[0].size(), 26u);
}

TEST(FeaturesCommand, JsonCarriesShapeAndValues) {
  const CommandResult r = run("features --preset librosa --feature mfcc --format json " + kInputs +
                              "chirp_1s_22k_mono.wav");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["frames"].get<int>(), 44);
  EXPECT_EQ(doc["columns"].get<int>(), 20);
  EXPECT_EQ(doc["values"].size(), 44u);
  EXPECT_EQ(doc["sample_rate"].get<int>(), 22050);
}

TEST(FeaturesCommand, SummaryNamesEveryFeature) {
  const CommandResult r = run("features " + kInputs + "impact_dull_44k_stereo.wav");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* word : {"rms", "zcr", "centroid", "bandwidth", "rolloff", "flatness", "flux",
                           "logmel", "mfcc", "onsets"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
  EXPECT_NE(r.out.find("zero crossings 29998"), std::string::npos)
      << r.out;  // global.json of this input
}

TEST(FeaturesCommand, BadInputExitsTwoWithTheFileAndProblem) {
  const CommandResult missing = run("features /nonexistent/a.wav");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("/nonexistent/a.wav: cannot decode as audio"), std::string::npos)
      << missing.err;
  const CommandResult preset = run("features --preset htk " + kInputs + "chirp_1s_22k_mono.wav");
  EXPECT_EQ(preset.status, 2);
  const CommandResult channel = run("features --channel 3 " + kInputs + "chirp_1s_22k_mono.wav");
  EXPECT_EQ(channel.status, 2);
  EXPECT_NE(channel.err.find("channel 3 requested"), std::string::npos) << channel.err;
}

TEST(HeatmapCommand, WritesSvgAndPngAndRejectsOtherExtensions) {
  const fs::path dir =
      fs::temp_directory_path() / ("echoplan_cli_heatmap_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const CommandResult svg =
      run("heatmap --preset librosa --feature mfcc -o " + (dir / "m.svg").string() + " " + kInputs +
          "impact_dull_44k_stereo.wav " + kInputs + "impact_mug_like_44k_stereo.wav");
  ASSERT_EQ(svg.status, 0) << svg.err;
  std::ifstream in(dir / "m.svg");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("mean mfcc (librosa) of 2 recordings"), std::string::npos);
  const CommandResult png = run("heatmap --onset-window 2 10 -o " + (dir / "m.png").string() + " " +
                                kInputs + "real_cc0_cowbell.flac");
  ASSERT_EQ(png.status, 0) << png.err;
  std::ifstream png_in(dir / "m.png", std::ios::binary);
  char magic[4] = {};
  png_in.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  const CommandResult jpg =
      run("heatmap -o " + (dir / "m.jpg").string() + " " + kInputs + "real_cc0_cowbell.flac");
  EXPECT_EQ(jpg.status, 2);
  EXPECT_NE(jpg.err.find("must end in .png or .svg"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
