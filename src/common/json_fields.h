// The one way echoplan reads fields of a JSON document (a model file, a journal line, a campaign
// description), with errors that name the source and the field.
//
// Every accessor takes the dotted path of the value ("per_action.strike.classifier.templates",
// "step_log[3].reward") and the source, and throws InputError(source.file, source.line,
// "<path>: <problem>") when the value is missing, of the wrong type, of the wrong size, out of
// range, or not finite. Build paths with child() and element().
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace echoplan::json_fields {

// Where a document came from: a file, and its line when the document is one line of the file (a
// journal entry); line 0 when the whole file is the document. A file name converts to a source.
struct JsonSource {
  JsonSource(std::string file_name, int line_number = 0)
      : file(std::move(file_name)), line(line_number) {}
  JsonSource(const char* file_name) : file(file_name) {}
  std::string file;
  int line = 0;
};

// "path.key" ("key" at the top); "path[index]".
std::string child(const std::string& path, const std::string& key);
std::string element(const std::string& path, std::size_t index);

// The member `key` of object `parent` (which must be an object); `path` is the parent's path.
const nlohmann::json& member(const nlohmann::json& parent, const std::string& key,
                             const std::string& path, const JsonSource& source);
// The same for a member that may be absent: nullptr then.
const nlohmann::json* optional_member(const nlohmann::json& parent, const std::string& key,
                                      const std::string& path, const JsonSource& source);
// An array (of anything), to iterate with element() paths.
const nlohmann::json& array(const nlohmann::json& value, const std::string& path,
                            const JsonSource& source);

// A finite number.
double number(const nlohmann::json& value, const std::string& path, const JsonSource& source);
// An integer in [min, max].
int integer(const nlohmann::json& value, long long min, long long max, const std::string& path,
            const JsonSource& source);
// Any integer that fits 64 bits, signed or unsigned.
std::int64_t integer64(const nlohmann::json& value, const std::string& path,
                       const JsonSource& source);
std::uint64_t unsigned64(const nlohmann::json& value, const std::string& path,
                         const JsonSource& source);
bool boolean(const nlohmann::json& value, const std::string& path, const JsonSource& source);
std::string string(const nlohmann::json& value, const std::string& path, const JsonSource& source);

// An array of finite numbers; `size` >= 0 requires exactly that many.
std::vector<double> numbers(const nlohmann::json& value, long long size, const std::string& path,
                            const JsonSource& source);
// An array of int-sized integers; `size` >= 0 requires exactly that many.
std::vector<int> integers(const nlohmann::json& value, long long size, const std::string& path,
                          const JsonSource& source);
// An array of `rows` arrays of `cols` finite numbers (rows or cols < 0: any, but all rows alike),
// row-major.
std::vector<double> matrix(const nlohmann::json& value, long long rows, long long cols,
                           const std::string& path, const JsonSource& source);
// An array of strings (any, repeats allowed).
std::vector<std::string> strings(const nlohmann::json& value, const std::string& path,
                                 const JsonSource& source);
// An array of non-empty, distinct strings; `size` >= 0 requires exactly that many.
std::vector<std::string> names(const nlohmann::json& value, long long size, const std::string& path,
                               const JsonSource& source);

// A row-major rows x cols matrix as an array of rows (the inverse of matrix()).
nlohmann::json rows_of(const std::vector<double>& values, std::size_t rows, std::size_t cols);

}  // namespace echoplan::json_fields
