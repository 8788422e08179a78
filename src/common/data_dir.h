// Where the files shipped with echoplan (problems/, objects/) are at run time.
//
// Never a path compiled in from the source tree: the binary looks relative to itself, so an
// installed or moved tree keeps working. In order:
//   1. $ECHOPLAN_DATA_DIR, when set (it must then hold the data);
//   2. <folder of the executable>/../share/echoplan   (installed: <prefix>/bin/echoplan);
//   3. <folder of the executable>/share/echoplan      (build tree: build/echoplan, where CMake
//   links
//      build/share/echoplan/<folder> to the source's folder, see cmake/EchoplanInstall.cmake).
// A program of your own that links the libraries finds the data through 1 or 2, or passes paths.
#pragma once

#include <filesystem>
#include <string>

namespace echoplan {

// The folder holding problems/ and objects/. Throws InputError naming the places it looked.
std::filesystem::path shipped_data_dir();

// shipped_data_dir() / relative, e.g. shipped_file("objects/catalogue.yaml"); throws InputError
// when that file is missing.
std::string shipped_file(const std::string& relative);

}  // namespace echoplan
