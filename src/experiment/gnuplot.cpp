#include "experiment/gnuplot.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "common/error.h"

namespace echoplan::experiment {

namespace fs = std::filesystem;

fs::path find_gnuplot() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const fs::path candidate = fs::path(dirs.substr(start, end - start)) / "gnuplot";
    if (!candidate.parent_path().empty() && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    start = end + 1;
  }
  throw InputError(
      "gnuplot was not found on PATH; install it (Debian package gnuplot-nox, see "
      "scripts/setup.sh)");
}

bool run_gnuplot(const std::string& script, const fs::path& work_dir, std::string& error) {
  const fs::path gnuplot = find_gnuplot();
  const fs::path script_path = work_dir / "plot.gp";
  const fs::path error_path = work_dir / "gnuplot-stderr.txt";
  {
    std::ofstream out(script_path);
    out << script;
    if (!out) {
      error = "cannot write " + script_path.string();
      return false;
    }
  }
  const std::string command =
      fmt::format("cd '{}' && '{}' '{}' 2> '{}'", work_dir.string(), gnuplot.string(),
                  script_path.string(), error_path.string());
  if (std::system(command.c_str()) == 0) return true;
  std::ifstream in(error_path);
  error.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return false;
}

TemporaryFolder::TemporaryFolder(const std::string& prefix) {
  static std::atomic<int> counter{0};
  path_ = fs::temp_directory_path() / fmt::format("{}-{}-{}", prefix, ::getpid(), counter++);
  fs::create_directories(path_);
}

TemporaryFolder::~TemporaryFolder() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

}  // namespace echoplan::experiment
