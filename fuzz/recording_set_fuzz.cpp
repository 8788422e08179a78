// libFuzzer target: arbitrary bytes as a recording set's manifest.csv (perception/recording_set.h),
// read beside a fixed folder of tiny real WAV files (two objects, one action, one file each), and
// every recording the set lists decoded. Bad input must end in echoplan::InputError; a set that
// loads must keep its invariants (every object has every action, every recording lies inside the
// folder). Anything else (a crash, a sanitizer report, another exception, a hang) is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "audio/io.h"
#include "common/error.h"
#include "perception/recording_set.h"

namespace {

namespace fs = std::filesystem;

// This process's scratch folder, made once (libFuzzer may exit without atexit handlers, so it stays
// in the temp folder; a few small files): DIR/{mug,cup}/strike/a.wav and DIR/mug/strike/b.wav.
const fs::path& scratch() {
  static const fs::path dir = [] {
    const fs::path d =
        fs::temp_directory_path() / ("echoplan_recording_set_fuzz_" + std::to_string(::getpid()));
    fs::remove_all(d);
    echoplan::audio::AudioClip clip;
    clip.sample_rate = 8000;
    clip.samples.assign(80, 0.25f);
    for (const char* file : {"mug/strike/a.wav", "mug/strike/b.wav", "cup/strike/a.wav"}) {
      fs::create_directories((d / file).parent_path());
      echoplan::audio::write_audio((d / file).string(), clip);
    }
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace echoplan::perception;
  const fs::path& dir = scratch();
  {
    std::ofstream out(dir / "manifest.csv", std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const RecordingSet set = load_recording_set(dir.string());
    const fs::path root = fs::weakly_canonical(dir);
    for (const auto& action : set.actions)
      if (set.of_action(action).size() < set.objects.size()) __builtin_trap();
    for (const Recording& recording : set.recordings) {
      const fs::path file = fs::weakly_canonical(recording.path);
      if (file.parent_path().parent_path().parent_path() != root) __builtin_trap();
      (void)read_recording(recording.path, 8000);
    }
  } catch (const echoplan::InputError&) {
    // A malformed manifest: the documented outcome.
  }
  return 0;
}
