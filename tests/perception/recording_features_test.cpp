// Tests of a recordings tree as a feature set: rows, sessions with and without the manifest's
// session column, and features equal to the pipeline's summary of each clip.
#include "perception/recording_features.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "../common/input_error_message.h"
#include "../common/test_folder.h"
#include "perception/summary_features.h"
#include "synthetic_sounds.h"

namespace echoplan::perception {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const std::vector<std::string> kObjects{"thud", "ring"};
const std::vector<std::string> kActions{"strike", "slide"};

// Two objects x two actions x two recordings (a.wav, b.wav), each a distinct synthetic strike.
class RecordingFeaturesTest : public TestFolder {
 protected:
  void SetUp() override {
    TestFolder::SetUp();
    unsigned seed = 1;
    for (std::size_t o = 0; o < kObjects.size(); ++o)
      for (const auto& action : kActions)
        for (const char* file : {"a.wav", "b.wav"}) {
          const fs::path path = dir_ / kObjects[o] / action / file;
          fs::create_directories(path.parent_path());
          test_sounds::StrikeOptions options;
          options.duration_s = 0.6;
          options.seed = seed++;
          options.detune = 0.01;
          audio::write_audio(path.string(),
                             test_sounds::strike(test_sounds::three_objects()[o], options));
        }
  }
  void write_manifest(bool with_sessions) {
    std::ofstream out(dir_ / "manifest.csv");
    out << "file,object,action" << (with_sessions ? ",session" : "") << "\n";
    for (const auto& object : kObjects)
      for (const auto& action : kActions)
        for (const char* file : {"a", "b"})
          out << object << "/" << action << "/" << file << ".wav," << object << "," << action
              << (with_sessions ? std::string(",") + file : "") << "\n";
  }
};

TEST_F(RecordingFeaturesTest, WithoutSessionsEachRecordingIsItsOwnSession) {
  const RecordingSet recordings = load_recording_set(dir_.string());
  const FeatureSet set = feature_set_from_recordings(recordings);
  EXPECT_EQ(set.objects, (std::vector<std::string>{"ring", "thud"}));
  ASSERT_EQ(set.actions.size(), 2u);
  EXPECT_EQ(set.actions[0].name, "slide");
  ASSERT_EQ(set.sessions.size(), 8u);
  EXPECT_EQ(set.sessions[0].name, "ring/slide/a.wav");
  const ActionData& slide = set.actions[0];
  ASSERT_EQ(slide.modalities.size(), 1u);
  const Modality& audio = slide.modalities[0];
  EXPECT_EQ(audio.name, "audio");
  EXPECT_EQ(audio.feature_names, summary_feature_names());
  ASSERT_EQ(audio.rows.size(), 4u);
  ASSERT_EQ(slide.rows.size(), 4u);
  EXPECT_EQ(slide.rows[2].object, 1);  // thud/slide/a.wav
  // The features are the pipeline's summary of that clip.
  ClipAnalyzer analyzer(AnalysisSettings{});
  ClipAnalysis analysis;
  const std::string path = (dir_ / "thud/slide/a.wav").string();
  analyzer.analyse(read_recording(path, 44100), path, analysis);
  const auto summary = summary_features(analysis);
  EXPECT_EQ(audio.rows[2], std::vector<double>(summary.begin(), summary.end()));
  EXPECT_NE(audio.rows[2], audio.rows[3]);
}

TEST_F(RecordingFeaturesTest, ManifestWithoutSessionColumn) {
  write_manifest(false);
  const FeatureSet set = feature_set_from_recordings(load_recording_set(dir_.string()));
  EXPECT_EQ(set.objects, kObjects);  // manifest order
  EXPECT_EQ(set.sessions.size(), 8u);
  EXPECT_EQ(set.sessions[1].name, "thud/strike/b.wav");
}

TEST_F(RecordingFeaturesTest, ManifestSessionColumnGroupsRecordingsAcrossActions) {
  write_manifest(true);
  const RecordingSet recordings = load_recording_set(dir_.string());
  EXPECT_EQ(recordings.recordings[1].session, "b");
  int calls = 0;
  const FeatureSet set =
      feature_set_from_recordings(recordings, {}, [&](const std::string&, int, int) { ++calls; });
  EXPECT_EQ(calls, 8);
  ASSERT_EQ(set.sessions.size(), 4u);  // (thud, a), (thud, b), (ring, a), (ring, b)
  EXPECT_EQ(set.sessions[2].object, 1);
  EXPECT_EQ(set.sessions[2].name, "a");
  const ActionData* slide = set.action("slide");
  ASSERT_NE(slide, nullptr);
  EXPECT_EQ(slide->rows[3].session, 3);  // ring, b
  EXPECT_EQ(set.action("strike")->rows[3].session, 3);
}

TEST_F(RecordingFeaturesTest, EmptySessionInTheManifestIsAnError) {
  write_manifest(true);
  std::ifstream in(dir_ / "manifest.csv");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  text.replace(text.find(",b\n"), 3, ",\n");  // line 3: thud/strike/b.wav
  std::ofstream(dir_ / "manifest.csv") << text;
  EXPECT_THAT(input_error_message([&] { load_recording_set(dir_.string()); }),
              HasSubstr((dir_ / "manifest.csv").string() + ":3: file 'thud/strike/b.wav' has an "
                                                           "empty session"));
}

}  // namespace
}  // namespace echoplan::perception
