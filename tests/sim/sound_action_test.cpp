#include "sim/sound_action.h"

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"

namespace echoplan::sim {
namespace {

TEST(SoundAction, NamesParseBackToTheirAction) {
  for (SoundAction a : kSoundActions) EXPECT_EQ(parse_sound_action(to_string(a)), a);
  EXPECT_EQ(sound_action_names(), (std::vector<std::string>{"slide", "strike"}));
}

TEST(SoundAction, UnknownNameIsAnInputErrorListingTheKnownOnes) {
  EXPECT_FALSE(find_sound_action("juggle").has_value());
  EXPECT_FALSE(find_sound_action("Strike").has_value());
  try {
    parse_sound_action("juggle");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown action 'juggle' (known: slide, strike)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace echoplan::sim
