// A capture device without a sound card, for tests: a private ALSA configuration (selected with
// ALSA_CONFIG_PATH before PortAudio starts) whose capture devices are ALSA's `file` plugin reading
// raw 32-bit float PCM from files. Capture is not paced in real time and returns exactly the file's
// samples (shared reference: ros-and-audio-in-tests.md).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/rng.h"

namespace echoplan::robot::testing {

// Interleaved samples on a 16-bit grid (k / 32768), so a 16-bit WAV of them is exact too.
inline std::vector<float> grid_noise(std::size_t samples, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<float> out(samples);
  for (auto& s : out) s = static_cast<float>(static_cast<int>(rng() % 65536) - 32768) / 32768.0f;
  return out;
}

inline void write_raw_float(const std::filesystem::path& path, const std::vector<float>& samples) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(samples.data()),
            static_cast<std::streamsize>(samples.size() * sizeof(float)));
}

// One capture device per (name, raw file); the first is the default input. Writes DIR/asound.conf
// and points ALSA_CONFIG_PATH at it. Must run before the process first starts PortAudio.
inline void install_file_capture_devices(
    const std::filesystem::path& dir,
    const std::vector<std::pair<std::string, std::filesystem::path>>& devices) {
  std::ofstream conf(dir / "asound.conf");
  conf << "pcm.silent { type null }\n";
  for (const auto& [name, raw] : devices)
    conf << "pcm." << name << " { type file slave.pcm \"silent\" file \"/dev/null\" infile \""
         << raw.string() << "\" format \"raw\" }\n";
  conf << "pcm.!default { type asym capture.pcm \"" << devices.front().first
       << "\" playback.pcm \"silent\" }\n";
  conf.close();
  setenv("ALSA_CONFIG_PATH", (dir / "asound.conf").c_str(), 1);
}

}  // namespace echoplan::robot::testing
