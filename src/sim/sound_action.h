// The two sound-making actions the simulator performs, and their names across echoplan.
//
// An action's name is parsed once where it enters the simulator (the CLI, the dataset's options,
// the simulated world) and the enum is passed inward from there.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace echoplan::sim {

enum class SoundAction {
  slide,   // the fingertip pad pushes the object 5 cm along +x at the action's push speed
  strike,  // the hand lifts the object 5 cm and brings it down onto the table: one impact
};

inline constexpr std::array<SoundAction, 2> kSoundActions{SoundAction::slide, SoundAction::strike};

// "slide", "strike".
const char* to_string(SoundAction action);

// The names of kSoundActions, in order.
std::vector<std::string> sound_action_names();

// The action named `name`, or nothing for any other name.
std::optional<SoundAction> find_sound_action(std::string_view name);

// The action named `name`; throws InputError "unknown action '<name>' (known: slide, strike)".
SoundAction parse_sound_action(std::string_view name);

}  // namespace echoplan::sim
