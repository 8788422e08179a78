// Internal to perception: reading the model file's JSON with errors that name the file and the
// field.
//
// Every accessor takes the dotted path of the value ("per_action.strike.classifier.templates") and
// the source (the file name), and throws InputError(source, 0, "<path>: <problem>") when the value
// is missing, of the wrong type, of the wrong size, or not finite.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace echoplan::perception::json_fields {

// The member `key` of object `parent` (which must be an object).
const nlohmann::json& member(const nlohmann::json& parent, const std::string& key,
                             const std::string& path, const std::string& source);
// A finite number.
double number(const nlohmann::json& value, const std::string& path, const std::string& source);
// An integer in [min, max].
int integer(const nlohmann::json& value, long long min, long long max, const std::string& path,
            const std::string& source);
bool boolean(const nlohmann::json& value, const std::string& path, const std::string& source);
std::string string(const nlohmann::json& value, const std::string& path, const std::string& source);
// An array of finite numbers; `size` >= 0 requires exactly that many.
std::vector<double> numbers(const nlohmann::json& value, long long size, const std::string& path,
                            const std::string& source);
// An array of `rows` arrays of `cols` finite numbers (rows or cols < 0: any, but all rows alike),
// row-major.
std::vector<double> matrix(const nlohmann::json& value, long long rows, long long cols,
                           const std::string& path, const std::string& source);
// An array of non-empty, distinct strings; `size` >= 0 requires exactly that many.
std::vector<std::string> names(const nlohmann::json& value, long long size, const std::string& path,
                               const std::string& source);

// A row-major rows x cols matrix as an array of rows (the inverse of matrix()).
nlohmann::json rows_of(const std::vector<double>& values, std::size_t rows, std::size_t cols);

}  // namespace echoplan::perception::json_fields
