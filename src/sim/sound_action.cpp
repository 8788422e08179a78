#include "sim/sound_action.h"

#include <fmt/format.h>

#include "common/error.h"

namespace echoplan::sim {

const char* to_string(SoundAction action) {
  switch (action) {
    case SoundAction::slide:
      return "slide";
    case SoundAction::strike:
      return "strike";
  }
  return "unknown";
}

std::vector<std::string> sound_action_names() {
  std::vector<std::string> names;
  for (SoundAction a : kSoundActions) names.emplace_back(to_string(a));
  return names;
}

std::optional<SoundAction> find_sound_action(std::string_view name) {
  for (SoundAction a : kSoundActions)
    if (name == to_string(a)) return a;
  return std::nullopt;
}

SoundAction parse_sound_action(std::string_view name) {
  if (const auto action = find_sound_action(name)) return *action;
  throw InputError(
      "", 0,
      fmt::format("unknown action '{}' (known: {})", name, fmt::join(sound_action_names(), ", ")));
}

}  // namespace echoplan::sim
