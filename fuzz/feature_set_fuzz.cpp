// libFuzzer target: arbitrary bytes as one modality file of a feature set
// (DIR/<action>/<modality>.csv, perception/feature_set.h), loaded alone and beside a fixed valid
// sibling (so the row comparison runs too), and as a groups file. Bad input must end in
// echoplan::InputError; anything else (a crash, a sanitizer report, another exception, a hang) is
// a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/error.h"
#include "perception/feature_set.h"

namespace {

namespace fs = std::filesystem;

// This process's scratch folder, made once (libFuzzer may exit without atexit handlers, so it stays
// in the temp folder; a few small files): DIR/strike/ holds the modality files.
const fs::path& scratch() {
  static const fs::path dir = [] {
    const fs::path d =
        fs::temp_directory_path() / ("echoplan_feature_set_fuzz_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d / "strike");
    return d;
  }();
  return dir;
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

void load(const fs::path& dir) {
  try {
    const echoplan::perception::FeatureSet set =
        echoplan::perception::load_feature_set(dir.string());
    for (const auto& action : set.actions)
      for (const auto& modality : action.modalities)
        if (modality.rows.size() != action.rows.size()) __builtin_trap();
  } catch (const echoplan::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const fs::path& dir = scratch();
  fs::remove(dir / "strike" / "a.csv");
  write(dir / "strike" / "b.csv", text);
  load(dir);
  write(dir / "strike" / "a.csv", "object,session,x\nmug,1,0.5\ncup,1,2\n");
  load(dir);
  try {
    (void)echoplan::perception::load_groups((dir / "strike" / "b.csv").string());
  } catch (const echoplan::InputError&) {
  }
  return 0;
}
