#include "sim/background_noise.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "audio/io.h"
#include "audio/levels.h"
#include "common/error.h"
#include "sim/sim_config.h"
#include "sim/sound_noise.h"

namespace echoplan::sim {

namespace {

namespace fs = std::filesystem;

constexpr double kRoomCornerHz = 500.0;

double parse_db(const std::string& part, const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
  if (error != std::errc() || end != part.data() + part.size() || !(value >= -60 && value <= 60))
    throw InputError(fmt::format("EBR '{}': give a number of dB in [-60, 60], or LO:HI", text));
  return value;
}

double rms(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v * v;
  return x.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(x.size()));
}

// Built-in noise of `frames` at `rate`, unit RMS.
std::vector<double> builtin(const std::string& name, std::size_t frames, int rate, Rng& rng) {
  NoiseSource unit(rng);
  std::vector<double> out(frames);
  if (name == "room") {
    const std::vector<float> room = room_noise(frames, rate, kRoomCornerHz, 1.0, unit);
    std::copy(room.begin(), room.end(), out.begin());
  } else if (name == "motor") {
    // The simulated arm's motors running steadily (sim/sound_motor.h's band at the default
    // recording's centre and Q): another arm at work nearby, or this one's drives held on.
    const RecordingConfig defaults;
    BandPass band(defaults.motor_noise_hz, defaults.motor_noise_q, rate);
    for (double& x : out) x = band.filter(unit.next());
    const double level = rms(out);
    if (level > 0.0)
      for (double& x : out) x /= level;
  } else if (name == "coloured") {
    // A colour of its own per recording: the room's low-pass at a corner drawn from 100 Hz to
    // 10 kHz (log-uniform: a rumble to near-white), plus a band at a centre drawn from 150 Hz to
    // 5 kHz (log-uniform, Q 0.7 to 3) carrying a drawn share of the power (up to nine tenths): a
    // fan, a motor, a voice's formant. Trained on, it teaches what noise of any colour does,
    // rather than the few colours a room has (as random tables teach tables: random_tables.h).
    const double corner = std::exp(std::log(100.0) + uniform01(rng) * std::log(100.0));
    const double centre = std::exp(std::log(150.0) + uniform01(rng) * std::log(5000.0 / 150.0));
    const double q = 0.7 + uniform01(rng) * 2.3;
    const double band_share = 0.9 * uniform01(rng);
    const std::vector<float> low =
        room_noise(frames, rate, std::min(corner, 0.45 * rate), 1.0, unit);
    BandPass band(std::min(centre, 0.45 * rate), q, rate);
    std::vector<double> banded(frames);
    for (double& x : banded) x = band.filter(unit.next());
    const double band_level = rms(banded);
    for (std::size_t i = 0; i < frames; ++i)
      out[i] = std::sqrt(1.0 - band_share) * low[i] +
               (band_level > 0.0 ? std::sqrt(band_share) * banded[i] / band_level : 0.0);
    const double level = rms(out);
    if (level > 0.0)
      for (double& x : out) x /= level;
  } else {
    for (double& x : out) x = unit.next();
  }
  return out;
}

// `frames` of `source` (mono) at `rate`, from a drawn offset, looped.
std::vector<double> segment(const audio::AudioClip& source, std::size_t frames, int rate,
                            Rng& rng) {
  // Enough of the source at its own rate to cover the clip once resampled.
  const auto needed =
      static_cast<std::size_t>(std::ceil(static_cast<double>(frames) * source.sample_rate / rate)) +
      16;
  const std::size_t length = source.samples.size();
  const auto start = static_cast<std::size_t>(uniform01(rng) * static_cast<double>(length));
  audio::AudioClip piece{source.sample_rate, 1, std::vector<float>(needed)};
  for (std::size_t i = 0; i < needed; ++i) piece.samples[i] = source.samples[(start + i) % length];
  const audio::AudioClip at_rate = audio::resample(piece, rate);
  std::vector<double> out(frames, 0.0);
  for (std::size_t i = 0; i < frames && i < at_rate.samples.size(); ++i)
    out[i] = at_rate.samples[i];
  return out;
}

// The recordings of a folder, recursively, in name order.
std::vector<std::string> recordings_in(const fs::path& folder) {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file() && audio::is_audio_file(entry.path().string()))
      files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  if (files.empty())
    throw InputError(folder.string(), 0, "noise folder holds no recordings (.wav, .flac, .aiff)");
  return files;
}

}  // namespace

EbrRange parse_ebr(const std::string& text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) {
    const double db = parse_db(text, text);
    return {db, db};
  }
  const EbrRange range{parse_db(text.substr(0, colon), text),
                       parse_db(text.substr(colon + 1), text)};
  if (range.low > range.high)
    throw InputError(fmt::format("EBR '{}': the range's low end is above its high end", text));
  return range;
}

const std::vector<std::string>& builtin_noise_names() {
  static const std::vector<std::string> names{"white", "room", "motor", "coloured"};
  return names;
}

BackgroundNoise::BackgroundNoise(const std::vector<std::string>& sources, int talkers)
    : talkers_(talkers) {
  if (sources.empty()) throw InputError("background noise: name at least one source");
  if (talkers < 1 || talkers > kMostTalkers)
    throw InputError(
        fmt::format("background noise: talkers must be 1 to {} (people heard at once), "
                    "not {}",
                    kMostTalkers, talkers));
  const auto& builtins = builtin_noise_names();
  for (const std::string& source : sources) {
    if (std::find(builtins.begin(), builtins.end(), source) != builtins.end()) {
      names_.push_back(source);
      recordings_.emplace_back();
      continue;
    }
    std::error_code error;
    if (!fs::exists(source, error))
      throw InputError(source, 0,
                       fmt::format("noise source is neither a file, a folder nor built-in ({})",
                                   fmt::join(builtins, ", ")));
    const std::vector<std::string> files =
        fs::is_directory(source, error) ? recordings_in(source) : std::vector{source};
    for (const std::string& file : files) {
      audio::ReadOptions options;
      options.channel_policy = audio::ChannelPolicy::mean;
      names_.push_back(file);
      recorded_.push_back(recordings_.size());
      recordings_.push_back(audio::read_audio(file, options));
    }
  }
}

void BackgroundNoise::add_other_talkers(std::vector<double>& noise, int rate, Rng& rng) const {
  for (int t = 1; t < talkers_; ++t) {
    const std::size_t which = recorded_[std::min(
        recorded_.size() - 1, static_cast<std::size_t>(uniform01(rng) * recorded_.size()))];
    const std::vector<double> other = segment(recordings_[which], noise.size(), rate, rng);
    // Each talker at the level of its own recording, as people talk: the loud and the soft.
    for (std::size_t i = 0; i < noise.size(); ++i) noise[i] += other[i];
  }
}

BackgroundNoise::Mixed BackgroundNoise::mix(const audio::AudioClip& recording, const EbrRange& ebr,
                                            Rng& rng) const {
  const auto which =
      std::min(names_.size() - 1, static_cast<std::size_t>(uniform01(rng) * names_.size()));
  Mixed mixed{recording, names_[which], ebr.low + uniform01(rng) * (ebr.high - ebr.low)};
  const std::size_t frames = recording.frames();
  const bool recorded = !recordings_[which].samples.empty();
  std::vector<double> noise = recorded
                                  ? segment(recordings_[which], frames, recording.sample_rate, rng)
                                  : builtin(names_[which], frames, recording.sample_rate, rng);
  if (recorded && talkers_ > 1) {
    add_other_talkers(noise, recording.sample_rate, rng);
    mixed.source += fmt::format(" and {} others", talkers_ - 1);
  }
  const double event = audio::event_level(recording), level = rms(noise);
  if (event <= 0.0 || level <= 0.0) return mixed;
  const double gain = event / std::pow(10.0, mixed.ebr_db / 20.0) / level;
  const auto channels = static_cast<std::size_t>(recording.channels);
  for (std::size_t f = 0; f < frames; ++f)
    for (std::size_t c = 0; c < channels; ++c) {
      float& x = mixed.clip.samples[f * channels + c];
      x = static_cast<float>(std::clamp(x + gain * noise[f], -1.0, 1.0));
    }
  return mixed;
}

}  // namespace echoplan::sim
