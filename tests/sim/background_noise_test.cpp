// Background noise at an event-to-background ratio: the ratio kept for every kind of source, the
// seed's draws, and bad sources named.
#include "sim/background_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>

#include "audio/io.h"
#include "audio/levels.h"
#include "common/error.h"

namespace echoplan::sim {
namespace {

namespace fs = std::filesystem;

// A clip of `seconds` at 44.1 kHz, silent but for a tone of amplitude `a` at `hz` from `from_s`
// to `to_s`.
audio::AudioClip tone(double seconds, double a, double hz, double from_s, double to_s) {
  audio::AudioClip clip{44100, 1, std::vector<float>(static_cast<std::size_t>(seconds * 44100))};
  for (std::size_t i = 0; i < clip.samples.size(); ++i) {
    const double t = static_cast<double>(i) / 44100;
    if (t >= from_s && t < to_s)
      clip.samples[i] = static_cast<float>(a * std::sin(2 * std::numbers::pi * hz * t));
  }
  return clip;
}

// The RMS of what `mix` added to `clip`, over the whole clip.
double added_rms(const audio::AudioClip& clip, const audio::AudioClip& mixed) {
  double sum = 0.0;
  for (std::size_t i = 0; i < clip.samples.size(); ++i) {
    const double d = static_cast<double>(mixed.samples[i]) - clip.samples[i];
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(clip.samples.size()));
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "echoplan_background_noise" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Every kind of source is mixed at the ratio asked: the added noise's RMS is the event level over
// 10^(EBR/20).
TEST(BackgroundNoise, EverySourceIsMixedAtTheRatioAsked) {
  const fs::path dir = fresh_dir("ratio");
  // A recorded source at another rate and shorter than the clip: resampled and looped.
  audio::AudioClip hum = tone(0.3, 0.3, 120, 0.0, 0.3);
  hum = audio::resample(hum, 8000);
  audio::write_audio((dir / "hum.wav").string(), hum);
  const audio::AudioClip strike = tone(1.5, 0.05, 700, 0.4, 0.45);  // quiet: nothing clips
  const double event = audio::event_level(strike);
  for (const std::string& source :
       std::vector<std::string>{"white", "room", "motor", "coloured", (dir / "hum.wav").string()})
    for (double ebr : {12.0, 0.0, -6.0}) {
      const BackgroundNoise noise({source});
      Rng rng(3);
      const BackgroundNoise::Mixed mixed = noise.mix(strike, {ebr, ebr}, rng);
      EXPECT_EQ(mixed.source, source);
      EXPECT_EQ(mixed.ebr_db, ebr);
      EXPECT_NEAR(20 * std::log10(event / added_rms(strike, mixed.clip)), ebr, 0.01)
          << source << " at " << ebr;
    }
}

// Coloured noise draws a colour per recording: over 40 draws the added noise's correlation between
// neighbouring samples spans a rumble (a 100 Hz corner: near 1) to near-white (near 0), where the
// room's is one colour every time.
TEST(BackgroundNoise, ColouredNoiseDrawsAColourPerRecording) {
  const audio::AudioClip strike = tone(1.0, 0.05, 700, 0.4, 0.45);
  auto neighbour_correlation = [&](const audio::AudioClip& mixed) {
    double product = 0.0, power = 0.0;
    for (std::size_t i = 1; i < strike.samples.size(); ++i) {
      const double d0 = static_cast<double>(mixed.samples[i - 1]) - strike.samples[i - 1];
      const double d1 = static_cast<double>(mixed.samples[i]) - strike.samples[i];
      product += d0 * d1;
      power += d1 * d1;
    }
    return product / power;
  };
  for (const char* source : {"coloured", "room"}) {
    const BackgroundNoise noise({source});
    Rng rng(2);
    double lowest = 1.0, highest = -1.0;
    for (int i = 0; i < 40; ++i) {
      const double r = neighbour_correlation(noise.mix(strike, {0, 0}, rng).clip);
      lowest = std::min(lowest, r);
      highest = std::max(highest, r);
    }
    if (std::string(source) == "coloured") {
      EXPECT_LT(lowest, 0.5);
      EXPECT_GT(highest, 0.95);
    } else {
      EXPECT_LT(highest - lowest, 0.02);
    }
  }
}

TEST(BackgroundNoise, DrawsFollowTheRng) {
  const audio::AudioClip strike = tone(0.5, 0.5, 700, 0.1, 0.15);
  const BackgroundNoise noise({"white", "room"});
  Rng a(7), b(7), c(8);
  const auto first = noise.mix(strike, {-6, 12}, a);
  EXPECT_EQ(first.clip.samples, noise.mix(strike, {-6, 12}, b).clip.samples);
  EXPECT_NE(first.clip.samples, noise.mix(strike, {-6, 12}, c).clip.samples);
  // A range: every draw inside it, and not all the same.
  Rng d(1);
  double low = 60, high = -60;
  for (int i = 0; i < 50; ++i) {
    const double ebr = noise.mix(strike, {-6, 12}, d).ebr_db;
    low = std::min(low, ebr);
    high = std::max(high, ebr);
  }
  EXPECT_GE(low, -6.0);
  EXPECT_LE(high, 12.0);
  EXPECT_GT(high - low, 9.0);
  // A silent recording has no level to keep a ratio to: it stays silent.
  const audio::AudioClip silent = tone(0.5, 0.0, 700, 0.0, 0.5);
  EXPECT_EQ(noise.mix(silent, {0, 0}, d).clip.samples, silent.samples);
}

// Real speech as Debian ships it (asterisk-core-sounds-en-wav, installed by scripts/setup.sh): a
// folder of 8 kHz recordings, one drawn per mix, at the ratio asked.
TEST(BackgroundNoise, RealSpeechFromAFolderOfRecordings) {
  const fs::path speech = "/usr/share/asterisk/sounds/en_US_f_Allison";
  ASSERT_TRUE(fs::is_directory(speech)) << "scripts/setup.sh deps installs it";
  const BackgroundNoise noise({speech.string()});
  EXPECT_GT(noise.sources().size(), 100u);
  const audio::AudioClip strike = tone(1.5, 0.05, 700, 0.4, 0.45);  // quiet: nothing clips
  Rng rng(5);
  const auto mixed = noise.mix(strike, {0, 0}, rng);
  EXPECT_EQ(fs::path(mixed.source).parent_path(), speech);
  EXPECT_NEAR(20 * std::log10(audio::event_level(strike) / added_rms(strike, mixed.clip)), 0.0,
              0.01);
}

// Babble: a talker with gaps (a tone for half of every second), heard alone, leaves half of
// the clip quiet, so the level measured from the clip (audio/levels.h) is far above the ratio it
// was mixed at; sixteen of them at once fill the gaps and the measure comes near the truth. Each
// mix keeps the ratio asked, and names its first talker and how many others.
TEST(BackgroundNoise, BabbleOfManyTalkersFillsTheGapsOfOne) {
  const fs::path dir = fresh_dir("babble");
  audio::write_audio((dir / "talker.wav").string(), tone(1.0, 0.3, 230, 0.0, 0.5));
  const audio::AudioClip strike = tone(2.0, 0.05, 700, 0.4, 0.45);
  const double event = audio::event_level(strike);
  std::map<int, double> measured_minus_mixed;
  for (int talkers : {1, 16}) {
    const BackgroundNoise noise({(dir / "talker.wav").string()}, talkers);
    EXPECT_EQ(noise.talkers(), talkers);
    Rng rng(11);
    const BackgroundNoise::Mixed mixed = noise.mix(strike, {6, 6}, rng);
    EXPECT_EQ(mixed.source, talkers == 1 ? (dir / "talker.wav").string()
                                         : (dir / "talker.wav").string() + " and 15 others");
    EXPECT_NEAR(20 * std::log10(event / added_rms(strike, mixed.clip)), 6.0, 0.01);
    measured_minus_mixed[talkers] = audio::measured_ebr_db(mixed.clip) - 6.0;
  }
  EXPECT_GT(measured_minus_mixed[1], 20.0);  // the gaps: nearly the quiet clip's ratio
  EXPECT_LT(std::abs(measured_minus_mixed[16]), 6.0);
}

TEST(BackgroundNoise, BadSourcesAndRatiosAreNamed) {
  for (int talkers : {0, -1, BackgroundNoise::kMostTalkers + 1})
    EXPECT_THROW(BackgroundNoise({"white"}, talkers), InputError) << talkers;
  const fs::path dir = fresh_dir("bad");
  try {
    BackgroundNoise({(dir / "missing.wav").string()});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir / "missing.wav").string());
  }
  try {
    BackgroundNoise({dir.string()});  // a folder without recordings
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), dir.string());
  }
  EXPECT_THROW(BackgroundNoise({}), InputError);
  EXPECT_EQ(parse_ebr("6").low, 6.0);
  EXPECT_EQ(parse_ebr("-6:12").high, 12.0);
  for (const char* bad : {"", "x", "6:", "12:-6", "90", "1:2:3"})
    EXPECT_THROW(parse_ebr(bad), InputError) << bad;
}

}  // namespace
}  // namespace echoplan::sim
