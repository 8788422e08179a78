#include "common/data_dir.h"

#include <cstdlib>
#include <vector>

#include "common/error.h"

namespace echoplan {

namespace {

// A shipped data folder is recognised by its contents, not only its name, so an unrelated
// share/echoplan (an old install, say) is not taken by mistake.
bool holds_data(const std::filesystem::path& dir) {
  std::error_code ec;
  return std::filesystem::is_directory(dir / "problems", ec) &&
         std::filesystem::is_directory(dir / "objects", ec);
}

std::vector<std::filesystem::path> candidates() {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  // Linux: the running executable, with symlinks resolved (an installed symlink in ~/bin still
  // finds the data next to the real binary).
  const std::filesystem::path exe = std::filesystem::canonical("/proc/self/exe", ec);
  if (!ec) {
    out.push_back(exe.parent_path().parent_path() / "share" / "echoplan");
    out.push_back(exe.parent_path() / "share" / "echoplan");
  }
  return out;
}

}  // namespace

std::filesystem::path shipped_data_dir() {
  if (const char* env = std::getenv("ECHOPLAN_DATA_DIR"); env != nullptr && *env != '\0') {
    if (!holds_data(env)) {
      throw InputError(env, 0,
                       "ECHOPLAN_DATA_DIR names a folder without problems/ and objects/; point it "
                       "at <prefix>/share/echoplan or unset it");
    }
    return env;
  }
  std::string looked;
  for (const auto& dir : candidates()) {
    if (holds_data(dir)) return dir;
    looked += (looked.empty() ? "" : ", ") + dir.string();
  }
  throw InputError(
      "echoplan's shipped data (problems/, objects/) not found (looked in: " +
      (looked.empty() ? std::string("nowhere, the executable's path is unknown") : looked) +
      "); set ECHOPLAN_DATA_DIR to <prefix>/share/echoplan or give the file's path");
}

std::string shipped_file(const std::string& relative) {
  const std::filesystem::path path = shipped_data_dir() / relative;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(path.string(), 0, "shipped file missing; reinstall echoplan or give a path");
  }
  return path.string();
}

}  // namespace echoplan
