// Drawing with gnuplot (Debian's gnuplot-nox): finding the program and running a script.
//
// Figures are written by gnuplot scripts rather than a plotting library linked in: gnuplot is one
// well-kept Debian package, draws PNG (cairo) and SVG, and the script is readable next to the
// figure.
#pragma once

#include <filesystem>
#include <string>

namespace echoplan::experiment {

// gnuplot on PATH; throws InputError saying which package to install when there is none.
std::filesystem::path find_gnuplot();

// Runs `script` (gnuplot commands) with gnuplot in `work_dir` (data files the script names live
// there). Returns false and sets `error` to gnuplot's stderr when it fails.
bool run_gnuplot(const std::string& script, const std::filesystem::path& work_dir,
                 std::string& error);

// A temporary folder removed, with its contents, when this object goes away.
class TemporaryFolder {
 public:
  explicit TemporaryFolder(const std::string& prefix);
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace echoplan::experiment
