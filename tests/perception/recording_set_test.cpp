// Tests of the recording-set loader: layouts, the manifest, and every malformed folder's error.
#include "perception/recording_set.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "common/error.h"
#include "synthetic_sounds.h"

namespace echoplan::perception {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

void write_clip(const fs::path& path) {
  fs::create_directories(path.parent_path());
  audio::AudioClip clip;
  clip.sample_rate = 8000;
  clip.samples.assign(800, 0.1f);
  audio::write_audio(path.string(), clip);
}

void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// Expects load_recording_set(dir) to throw an InputError whose message holds every fragment.
void expect_error(const fs::path& dir, const std::vector<std::string>& fragments) {
  try {
    load_recording_set(dir.string());
    ADD_FAILURE() << "no error for " << dir;
  } catch (const InputError& e) {
    for (const auto& f : fragments) EXPECT_THAT(std::string(e.what()), HasSubstr(f));
  }
}

class RecordingSetTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test_sounds::fresh_dir("set");
    for (const char* object : {"mug", "cup"})
      for (const char* action : {"strike", "slide"})
        for (const char* file : {"b.wav", "a.wav"}) write_clip(dir_ / object / action / file);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(RecordingSetTest, WithoutManifestEverythingIsSortedByName) {
  const RecordingSet set = load_recording_set(dir_.string());
  EXPECT_EQ(set.objects, (std::vector<std::string>{"cup", "mug"}));
  EXPECT_EQ(set.actions, (std::vector<std::string>{"slide", "strike"}));
  ASSERT_EQ(set.recordings.size(), 8u);
  EXPECT_EQ(set.recordings[0].path, (dir_ / "cup/slide/a.wav").string());
  EXPECT_EQ(set.recordings[1].path, (dir_ / "cup/slide/b.wav").string());
  EXPECT_EQ(set.recordings[2].object, "mug");
  EXPECT_EQ(set.of_action("strike").size(), 4u);
  EXPECT_EQ(set.object_index("mug"), 1);
  EXPECT_EQ(set.object_index("bowl"), -1);
}

TEST_F(RecordingSetTest, ManifestOrderWins) {
  std::string manifest = "file,object,action,seed\n";
  for (const char* object : {"mug", "cup"})
    for (const char* action : {"strike", "slide"})
      for (const char* file : {"b.wav", "a.wav"})
        manifest +=
            std::string(object) + "/" + action + "/" + file + "," + object + "," + action + ",7\n";
  write_text(dir_ / "manifest.csv", manifest);
  const RecordingSet set = load_recording_set(dir_.string());
  EXPECT_EQ(set.objects, (std::vector<std::string>{"mug", "cup"}));
  EXPECT_EQ(set.actions, (std::vector<std::string>{"strike", "slide"}));
  EXPECT_EQ(set.recordings[0].path, (dir_ / "mug/strike/b.wav").string());
}

// `echoplan add-noise` and a campaign's noisy twins name each recording's noise source: a named
// one is a noisy copy, "none" or an empty cell a recording as made.
TEST_F(RecordingSetTest, TheNoiseColumnMarksNoisyCopies) {
  write_text(dir_ / "manifest.csv",
             "file,object,action,session,ebr_db,noise\n"
             "mug/strike/a.wav,mug,strike,1,,none\n"
             "mug/strike/b.wav,mug,strike,1,6.5,/speech/one.wav\n"
             "mug/slide/a.wav,mug,slide,1,,\n"
             "mug/slide/b.wav,mug,slide,1,0,white\n"
             "cup/strike/a.wav,cup,strike,2,,none\n"
             "cup/strike/b.wav,cup,strike,2,,none\n"
             "cup/slide/a.wav,cup,slide,2,,none\n"
             "cup/slide/b.wav,cup,slide,2,,none\n");
  std::vector<bool> copies;
  for (const Recording& r : load_recording_set(dir_.string()).recordings)
    copies.push_back(r.noisy_copy);
  // Grouped by action (strike, slide), then object (mug, cup), in manifest order.
  EXPECT_EQ(copies, (std::vector<bool>{false, true, false, false, false, true, false, false}));
}

TEST_F(RecordingSetTest, SessionsBySurfaceAreTheTablesInTheirNamesOrder) {
  write_text(dir_ / "manifest.csv",
             "file,object,action,session,surface\n"
             "mug/strike/b.wav,mug,strike,1,steel\nmug/strike/a.wav,mug,strike,2,oak\n"
             "cup/strike/b.wav,cup,strike,1,oak\ncup/strike/a.wav,cup,strike,2,steel\n"
             "mug/slide/b.wav,mug,slide,1,steel\nmug/slide/a.wav,mug,slide,2,oak\n"
             "cup/slide/b.wav,cup,slide,1,oak\ncup/slide/a.wav,cup,slide,2,steel\n");
  const RecordingSet set = load_recording_set(dir_.string());
  EXPECT_EQ(set.recordings[0].surface, "steel");
  EXPECT_EQ(set.recordings[0].session, "1");
  const RecordingSet by_table = sessions_by_surface(set);
  std::vector<std::string> seen;
  for (const Recording& r : by_table.recordings) {
    EXPECT_EQ(r.session, r.surface);
    seen.push_back(fs::path(r.path).lexically_relative(dir_).generic_string());
  }
  // Grouped by action and object as the set is, then by table name.
  EXPECT_EQ(seen,
            (std::vector<std::string>{"mug/strike/a.wav", "mug/strike/b.wav", "cup/strike/b.wav",
                                      "cup/strike/a.wav", "mug/slide/a.wav", "mug/slide/b.wav",
                                      "cup/slide/b.wav", "cup/slide/a.wav"}));
}

TEST_F(RecordingSetTest, SessionsBySurfaceNeedEveryObjectOnEveryTable) {
  const auto error_of = [&](const std::string& manifest) {
    write_text(dir_ / "manifest.csv", manifest);
    try {
      sessions_by_surface(load_recording_set(dir_.string()));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::string rows;
  for (const char* object : {"mug", "cup"})
    for (const char* action : {"strike", "slide"})
      rows += fmt::format("{0}/{1}/a.wav,{0},{1},1\n{0}/{1}/b.wav,{0},{1},2\n", object, action);
  EXPECT_THAT(error_of("file,object,action,session\n" + rows),
              HasSubstr("names no table: holding out a table needs the manifest's 'surface'"));
  std::string one_table, missing;
  for (const char* object : {"mug", "cup"})
    for (const char* action : {"strike", "slide"}) {
      one_table +=
          fmt::format("{0}/{1}/a.wav,{0},{1},oak\n{0}/{1}/b.wav,{0},{1},oak\n", object, action);
      const std::string second =
          std::string(object) == "cup" && std::string(action) == "slide" ? "oak" : "steel";
      missing += fmt::format("{0}/{1}/a.wav,{0},{1},oak\n{0}/{1}/b.wav,{0},{1},{2}\n", object,
                             action, second);
    }
  EXPECT_THAT(error_of("file,object,action,surface\n" + one_table),
              HasSubstr("every recording is on one table (oak)"));
  EXPECT_THAT(error_of("file,object,action,surface\n" + missing),
              HasSubstr("no recording of 'cup' with action 'slide' on table 'steel'"));
}

TEST_F(RecordingSetTest, MissingOrNotAFolder) {
  expect_error(dir_ / "nope", {"nope", "does not exist"});
  write_text(dir_ / "file.txt", "x");
  expect_error(dir_ / "file.txt", {"file.txt", "not a folder"});
}

// As in a feature set, files beside the object folders (a groups file, a README) are ignored.
TEST_F(RecordingSetTest, FilesBesideTheObjectFoldersAreIgnored) {
  const RecordingSet before = load_recording_set(dir_.string());
  write_text(dir_ / "README.md", "x");
  write_text(dir_ / "groups.csv", "object,group\nmug,ceramic\n");
  const RecordingSet after = load_recording_set(dir_.string());
  EXPECT_EQ(after.objects, before.objects);
  EXPECT_EQ(after.recordings.size(), before.recordings.size());
}

TEST_F(RecordingSetTest, FileWhereAnActionFolderBelongs) {
  write_text(dir_ / "mug/notes.txt", "x");
  expect_error(dir_, {"mug/notes.txt", "folder per action"});
}

TEST_F(RecordingSetTest, NotARecording) {
  write_text(dir_ / "mug/strike/notes.txt", "x");
  expect_error(dir_, {"mug/strike/notes.txt", "not a recording"});
}

TEST_F(RecordingSetTest, HiddenFilesAreSkipped) {
  write_text(dir_ / "mug/strike/.DS_Store", "x");
  EXPECT_EQ(load_recording_set(dir_.string()).recordings.size(), 8u);
}

TEST_F(RecordingSetTest, EmptyClassFolder) {
  fs::create_directories(dir_ / "bowl/strike");
  expect_error(dir_, {"bowl/strike", "no recordings"});
}

TEST_F(RecordingSetTest, ActionForOneObjectOnly) {
  write_clip(dir_ / "mug/shake/a.wav");
  expect_error(dir_, {"cup/shake", "every object needs recordings for every action"});
}

TEST_F(RecordingSetTest, ManifestProblemsNameTheLine) {
  write_text(dir_ / "manifest.csv", "file,object\nmug/strike/a.wav,mug\n");
  expect_error(dir_, {"manifest.csv:1", "'action'"});
  write_text(dir_ / "manifest.csv", "file,object,action\nmug/strike/zzz.wav,mug,strike\n");
  expect_error(dir_, {"manifest.csv:2", "zzz.wav", "does not exist"});
  write_text(dir_ / "manifest.csv", "file,object,action\nmug/strike/a.wav,cup,strike\n");
  expect_error(dir_, {"manifest.csv:2", "not inside its folder cup/strike/"});
  write_text(dir_ / "manifest.csv", "file,object,action\nmug/strike/a.wav,mug\n");
  expect_error(dir_, {"manifest.csv:2", "2 cells"});
  write_text(dir_ / "manifest.csv", "file,object,action\nmug/strike/a.wav,mug,strike\n");
  expect_error(dir_, {"not listed in manifest.csv"});
}

// A manifest row could name a file outside the set through an object or action of "..", "" or
// with a '/' in it: the recordings here, plus a sibling folder's under object "../<sibling>".
TEST_F(RecordingSetTest, ManifestRowsCannotLeaveTheSet) {
  const std::string sibling = dir_.filename().string() + "_outside";
  std::string manifest = "file,object,action\n";
  for (const std::string& folder : {std::string("mug"), std::string("cup"), "../" + sibling})
    for (const char* action : {"strike", "slide"}) {
      write_clip(dir_ / folder / action / "a.wav");
      manifest += folder + "/" + action + "/a.wav," + folder + "," + action + "\n";
    }
  for (const char* object : {"mug", "cup"})
    for (const char* action : {"strike", "slide"})
      manifest += std::string(object) + "/" + action + "/b.wav," + object + "," + action + "\n";
  write_text(dir_ / "manifest.csv", manifest);
  expect_error(dir_, {"manifest.csv:6", "'../" + sibling + "' is not a folder name"});
  fs::remove_all(dir_.parent_path() / sibling);
  write_text(dir_ / "manifest.csv", "file,object,action\n/tmp/a.wav,,tmp\n");
  expect_error(dir_, {"manifest.csv:2", "'' is not a folder name"});
  write_text(dir_ / "manifest.csv", "file,object,action\n./strike/a.wav,.,strike\n");
  expect_error(dir_, {"manifest.csv:2", "'.' is not a folder name"});
}

// A performance's series beside its audio file belong to it; a tree of series alone needs no audio.
TEST_F(RecordingSetTest, SeriesBesideARecordingAreItsSignals) {
  for (const char* object : {"mug", "cup"})
    for (const char* action : {"strike", "slide"})
      for (const char* name : {"a", "b"})
        for (const char* modality : {"force", "effort"})
          write_text(dir_ / object / action / fmt::format("{}.{}.csv", name, modality),
                     "t,x\n0,1\n");
  const RecordingSet set = load_recording_set(dir_.string());
  ASSERT_EQ(set.recordings.size(), 8u);
  const Recording& first = set.recordings[0];
  EXPECT_EQ(first.path, (dir_ / "cup/slide/a.wav").string());
  EXPECT_TRUE(first.audio);
  ASSERT_EQ(first.series.size(), 2u);
  EXPECT_EQ(first.series[0].modality, "effort");
  EXPECT_EQ(first.series[0].path, (dir_ / "cup/slide/a.effort.csv").string());
  EXPECT_EQ(first.series[1].modality, "force");
}

TEST(RecordingSetSeries, ATreeOfSeriesAloneListsEachPerformanceOnce) {
  const fs::path dir = test_sounds::fresh_dir("series-only");
  for (const char* object : {"mug", "cup"})
    for (const char* name : {"1", "2"}) {
      write_text(dir / object / "lift" / fmt::format("{}.effort.csv", name), "t,j1\n0,1\n");
      write_text(dir / object / "lift" / fmt::format("{}.force.csv", name), "t,fz\n0,1\n");
    }
  RecordingSet set = load_recording_set(dir.string());
  ASSERT_EQ(set.recordings.size(), 4u);
  EXPECT_FALSE(set.recordings[0].audio);
  EXPECT_EQ(set.recordings[0].path, (dir / "cup/lift/1.effort.csv").string());
  EXPECT_EQ(set.recordings[0].series.size(), 2u);
  // A manifest lists each performance by any one of its series.
  write_text(dir / "manifest.csv",
             "file,object,action,session\nmug/lift/1.force.csv,mug,lift,s1\n"
             "mug/lift/2.effort.csv,mug,lift,s2\ncup/lift/1.effort.csv,cup,lift,s1\n"
             "cup/lift/2.force.csv,cup,lift,s2\n");
  set = load_recording_set(dir.string());
  ASSERT_EQ(set.recordings.size(), 4u);
  EXPECT_EQ(set.recordings[0].object, "mug");
  EXPECT_EQ(set.recordings[0].session, "s1");
  EXPECT_EQ(set.recordings[0].series.size(), 2u);
  write_text(dir / "manifest.csv",
             "file,object,action\nmug/lift/1.force.csv,mug,lift\nmug/lift/1.effort.csv,mug,lift\n");
  expect_error(dir, {"manifest.csv:3", "listed twice"});
  fs::remove_all(dir);
}

TEST_F(RecordingSetTest, BadSeriesFilesAreNamed) {
  write_text(dir_ / "mug/strike/a.csv", "t,x\n0,1\n");
  expect_error(dir_, {"mug/strike/a.csv", "<name>.<modality>.csv"});
  fs::remove(dir_ / "mug/strike/a.csv");
  write_text(dir_ / "mug/strike/a.audio.csv", "t,x\n0,1\n");
  expect_error(dir_, {"a.audio.csv", "'audio'"});
  fs::remove(dir_ / "mug/strike/a.audio.csv");
  write_clip(dir_ / "mug/strike/a.flac");
  expect_error(dir_, {"second audio file named 'a'"});
  fs::remove(dir_ / "mug/strike/a.flac");
  // One performance of an action with a series the others lack.
  write_text(dir_ / "mug/strike/a.effort.csv", "t,x\n0,1\n");
  expect_error(dir_, {"audio, effort", "every performance of an action needs the same signals"});
  // The manifest names the audio file of a performance that has one.
  write_text(dir_ / "manifest.csv", "file,object,action\nmug/strike/a.effort.csv,mug,strike\n");
  expect_error(dir_, {"manifest.csv:2", "list the audio file"});
}

TEST(ReadRecording, MixesChannelsAndResamples) {
  const auto dir = test_sounds::fresh_dir("read");
  audio::AudioClip stereo;
  stereo.sample_rate = 22050;
  stereo.channels = 2;
  for (int i = 0; i < 22050; ++i) {
    stereo.samples.push_back(0.5f);
    stereo.samples.push_back(-0.25f);
  }
  audio::write_audio((dir / "s.flac").string(), stereo, {.format = audio::FileFormat::flac});
  const audio::AudioClip clip = read_recording((dir / "s.flac").string(), 44100);
  EXPECT_EQ(clip.channels, 1);
  EXPECT_EQ(clip.sample_rate, 44100);
  EXPECT_EQ(clip.frames(), 44100u);
  EXPECT_NEAR(clip.samples[22050], 0.125f, 1e-3);
  EXPECT_THROW(read_recording((dir / "missing.wav").string(), 44100), InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace echoplan::perception
