#include "common/file_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/error.h"

namespace echoplan {

namespace fs = std::filesystem;

std::string read_text_file(const std::string& path, const std::string& what) {
  // A directory opens as a stream on Linux and reads as empty; say what is really wrong.
  std::error_code ec;
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec))
    throw InputError(path, 0, "not a regular file; expected the " + what);
  if (const std::uintmax_t size = fs::file_size(path, ec); !ec && size > kMaxInputFileBytes)
    throw InputError(path, 0,
                     "the " + what + " is " + std::to_string(size >> 20) +
                         " MiB; echoplan reads input files of at most " +
                         std::to_string(kMaxInputFileBytes >> 20) + " MiB");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the " + what);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<fs::path> visible_entries(const fs::path& dir) {
  std::vector<fs::path> entries;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (!it->path().filename().string().starts_with(".")) entries.push_back(it->path());
  if (ec) throw InputError(dir.string(), 0, "cannot list the folder: " + ec.message());
  std::sort(entries.begin(), entries.end());
  return entries;
}

void move_into_place(const fs::path& partial, const fs::path& path) {
  std::error_code error;
  fs::rename(partial, path, error);
  if (error)
    throw InputError(path.string(), 0,
                     "cannot move the finished file into place: " + error.message());
}

void write_all(int fd, std::string_view text, const fs::path& path) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw InputError(path.string(), 0, std::string("writing failed: ") + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
}

void write_file_atomically(const fs::path& path, const std::string& text) {
  const fs::path partial = path.string() + ".part";
  const int fd = ::open(partial.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    throw InputError(path.string(), 0, std::string("cannot write: ") + std::strerror(errno));
  try {
    write_all(fd, text, path);
  } catch (...) {
    ::close(fd);
    throw;
  }
  // On disk before the rename, so a crash leaves the old file or the whole new one.
  ::fsync(fd);
  ::close(fd);
  move_into_place(partial, path);
}

}  // namespace echoplan
