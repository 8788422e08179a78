// Whole files in and out, the one way the project does it: read a text file whole, and put a
// finished file in place so that a reader (or a run interrupted half-way) never sees half of it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace echoplan {

// The largest input file echoplan reads whole: a file from someone else cannot exhaust memory.
// Far above any problem, model, campaign or feature file a robot produces (the largest shipped
// input is under 1 MiB).
inline constexpr std::uintmax_t kMaxInputFileBytes = 512ull << 20;

// The whole text of the file at `path`; InputError(path, 0, "cannot open the <what>") if it cannot
// be read (also for a directory), and one saying so for a file over kMaxInputFileBytes.
std::string read_text_file(const std::string& path, const std::string& what);

// The entries of folder `dir` that are not hidden (no leading '.'), sorted by name, so every
// platform lists them in the same order. InputError naming `dir` when it cannot be listed.
std::vector<std::filesystem::path> visible_entries(const std::filesystem::path& dir);

// Moves the finished file `partial` onto `path` in one rename (atomic on one file system), so
// `path` is always either the old file or the whole new one. InputError naming `path` when it
// cannot.
void move_into_place(const std::filesystem::path& partial, const std::filesystem::path& path);

// Writes all of `text` to the open file descriptor `fd` (retrying short writes); InputError naming
// `path` when it fails.
void write_all(int fd, std::string_view text, const std::filesystem::path& path);

// Writes `text` to `path` through a temporary file beside it (`path`.part, flushed to disk, then
// move_into_place). InputError naming `path` when it cannot be written.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace echoplan
