// Internal to the audio module: lookups in the small (enum, name) tables that map command-line and
// file names to enums, so every such table behaves the same way.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <utility>

namespace echoplan::audio::detail {

template <typename Enum, std::size_t N>
using NameTable = std::array<std::pair<Enum, std::string_view>, N>;

// The name of `value` in `table` (the first entry's name if absent, which a complete table never
// is).
template <typename Enum, std::size_t N>
std::string_view name_of(const NameTable<Enum, N>& table, Enum value) {
  for (const auto& [known, name] : table)
    if (known == value) return name;
  return table.front().second;
}

// The enum named `name`, or nothing.
template <typename Enum, std::size_t N>
std::optional<Enum> value_named(const NameTable<Enum, N>& table, std::string_view name) {
  for (const auto& [value, known] : table)
    if (known == name) return value;
  return std::nullopt;
}

}  // namespace echoplan::audio::detail
