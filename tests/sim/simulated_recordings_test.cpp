#include "sim/simulated_recordings.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "audio/io.h"
#include "common/error.h"
#include "shipped_catalogue.h"
#include "sim/recording.h"

namespace echoplan::sim {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Dataset, WritesEveryPairAndAManifestThatReproducesEachFile) {
  const fs::path dir = fs::temp_directory_path() / "echoplan_dataset_test";
  fs::remove_all(dir);
  SimulatedRecordingsOptions options;
  options.objects = {"coffee_mug", "plastic_cup"};
  options.per_pair = 2;
  options.seed = 99;
  options.output_dir = dir.string();
  std::atomic<bool> stop{false};
  int calls = 0;
  const SimulatedRecordingsSummary s = write_simulated_recordings(
      shipped_catalogue(), SimConfig{}, options,
      [&](const std::string&, int done, int total) {
        ++calls;
        EXPECT_EQ(total, 8);
        EXPECT_EQ(done, calls);
      },
      stop);
  EXPECT_EQ(s.written, 8);
  EXPECT_FALSE(s.interrupted);
  const auto rows = lines_of(dir / "manifest.csv");
  ASSERT_EQ(rows.size(), 9u);
  EXPECT_EQ(rows[0].rfind("file,object,action,seed,collision,duration_s,impacts,impact_speed,", 0),
            0u)
      << rows[0];
  // The session column comes last: recording i of each action of an object is session i + 1.
  EXPECT_TRUE(rows[0].ends_with(",session")) << rows[0];
  EXPECT_TRUE(rows[1].ends_with(",1")) << rows[1];
  EXPECT_TRUE(rows[2].ends_with(",2")) << rows[2];
  EXPECT_TRUE(fs::exists(dir / "plastic_cup/strike/001.wav"));
  EXPECT_TRUE(fs::exists(dir / "coffee_mug/slide/000.wav"));

  // Row 1 is coffee_mug/slide/000.wav: its seed re-synthesizes the same samples.
  std::stringstream row(rows[1]);
  std::string file, object, action, seed;
  std::getline(row, file, ',');
  std::getline(row, object, ',');
  std::getline(row, action, ',');
  std::getline(row, seed, ',');
  EXPECT_EQ(file, "coffee_mug/slide/000.wav");
  EXPECT_EQ(std::stoull(seed), clip_seed(99, "coffee_mug", "slide", 0));
  SimulatedRobot robot(shipped_catalogue(), object, SimConfig{});
  SoundRenderer recorder(robot.object(), robot.table(), SimConfig{});
  Rng rng(std::stoull(seed));
  const auto again = simulate_recording(robot, recorder, parse_sound_action(action), rng).clip;
  // Written the same way, the re-synthesized clip is the same file byte for byte.
  const fs::path again_path = dir / "again.wav";
  audio::write_audio(again_path.string(), again);
  EXPECT_EQ(file_bytes(dir / file), file_bytes(again_path));
  fs::remove_all(dir);
}

TEST(Dataset, StoppingKeepsFinishedFilesAndTheirRows) {
  const fs::path dir = fs::temp_directory_path() / "echoplan_dataset_stop_test";
  fs::remove_all(dir);
  SimulatedRecordingsOptions options;
  options.objects = {"paper_base"};
  options.actions = {"strike"};
  options.per_pair = 5;
  options.output_dir = dir.string();
  options.threads = 1;  // one clip in progress at a time: stopping after the 2nd leaves exactly 2
  std::atomic<bool> stop{false};
  const SimulatedRecordingsSummary s = write_simulated_recordings(
      shipped_catalogue(), SimConfig{}, options,
      [&](const std::string&, int done, int) { stop = done == 2; }, stop);
  EXPECT_TRUE(s.interrupted);
  EXPECT_EQ(s.written, 2);
  EXPECT_EQ(lines_of(dir / "manifest.csv").size(), 3u);
  EXPECT_TRUE(fs::exists(dir / "paper_base/strike/001.wav"));
  EXPECT_FALSE(fs::exists(dir / "paper_base/strike/002.wav"));
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    EXPECT_NE(entry.path().extension(), ".part");
  fs::remove_all(dir);
}

TEST(Dataset, TwoThreadsWriteTheSameFilesAsOne) {
  std::vector<std::string> manifests;
  std::vector<std::string> first_files;
  for (int threads : {1, 2}) {
    const fs::path dir =
        fs::temp_directory_path() / ("echoplan_dataset_threads_" + std::to_string(threads));
    fs::remove_all(dir);
    SimulatedRecordingsOptions options;
    options.objects = {"plastic_cup", "coffee_mug"};
    options.actions = {"strike"};
    options.per_pair = 2;
    options.output_dir = dir.string();
    options.threads = threads;
    std::atomic<bool> stop{false};
    EXPECT_EQ(write_simulated_recordings(shipped_catalogue(), SimConfig{}, options, nullptr, stop)
                  .written,
              4);
    std::ifstream in(dir / "manifest.csv");
    manifests.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    std::string bytes;
    for (const char* f : {"plastic_cup/strike/000.wav", "coffee_mug/strike/001.wav"}) {
      std::ifstream wav(dir / f, std::ios::binary);
      bytes += std::string(std::istreambuf_iterator<char>(wav), std::istreambuf_iterator<char>());
    }
    first_files.push_back(bytes);
    fs::remove_all(dir);
  }
  EXPECT_EQ(manifests[0], manifests[1]);
  EXPECT_EQ(first_files[0], first_files[1]);
  EXPECT_FALSE(first_files[0].empty());
}

TEST(Dataset, UnknownNamesFailBeforeAnyFileIsWritten) {
  const fs::path dir = fs::temp_directory_path() / "echoplan_dataset_bad_test";
  fs::remove_all(dir);
  SimulatedRecordingsOptions options;
  options.output_dir = dir.string();
  std::atomic<bool> stop{false};
  options.objects = {"teapot"};
  EXPECT_THROW(write_simulated_recordings(shipped_catalogue(), SimConfig{}, options, nullptr, stop),
               InputError);
  options.objects = {"coffee_mug"};
  options.actions = {"juggle"};
  EXPECT_THROW(write_simulated_recordings(shipped_catalogue(), SimConfig{}, options, nullptr, stop),
               InputError);
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
}  // namespace echoplan::sim
