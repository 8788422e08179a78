#include "audio/io.h"

#include <fmt/format.h>
#include <samplerate.h>
#include <sndfile.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>

#include "common/error.h"

namespace echoplan::audio {
namespace {

struct SndfileCloser {
  void operator()(SNDFILE* file) const { sf_close(file); }
};
using SndfileHandle = std::unique_ptr<SNDFILE, SndfileCloser>;

// libsndfile's virtual I/O over a read-only memory buffer: lets the fuzzer and network callers
// decode without touching the file system.
struct MemoryFile {
  std::span<const std::uint8_t> bytes;
  sf_count_t position = 0;
};

sf_count_t memory_length(void* user) {
  return static_cast<sf_count_t>(static_cast<MemoryFile*>(user)->bytes.size());
}

sf_count_t memory_seek(sf_count_t offset, int whence, void* user) {
  auto* file = static_cast<MemoryFile*>(user);
  const auto size = static_cast<sf_count_t>(file->bytes.size());
  sf_count_t base = 0;
  if (whence == SEEK_CUR) base = file->position;
  if (whence == SEEK_END) base = size;
  const sf_count_t target = base + offset;
  if (target < 0) return -1;
  file->position = target;  // seeking past the end is allowed; reads there return 0 bytes
  return file->position;
}

sf_count_t memory_read(void* out, sf_count_t count, void* user) {
  auto* file = static_cast<MemoryFile*>(user);
  const auto size = static_cast<sf_count_t>(file->bytes.size());
  if (count <= 0 || file->position >= size) return 0;
  const sf_count_t n = std::min(count, size - file->position);
  std::memcpy(out, file->bytes.data() + file->position, static_cast<std::size_t>(n));
  file->position += n;
  return n;
}

sf_count_t memory_write(const void*, sf_count_t, void*) { return 0; }
sf_count_t memory_tell(void* user) { return static_cast<MemoryFile*>(user)->position; }

// Validates the header, decodes every frame as float and checks the samples; shared by the path and
// memory readers so both reject exactly the same inputs.
AudioClip decode(SNDFILE* file, const SF_INFO& info, const std::string& name,
                 const ReadOptions& options) {
  if (info.channels < 1) throw InputError(name, 0, "the file declares zero channels");
  if (info.channels > 256)
    throw InputError(name, 0,
                     fmt::format("the file declares {} channels (at most 256)", info.channels));
  if (info.samplerate < 1 || info.samplerate > 1'000'000)
    throw InputError(name, 0,
                     fmt::format("the file declares a sample rate of {} Hz (expected 1..1000000)",
                                 info.samplerate));
  const double max_frames = options.max_duration_seconds * info.samplerate;
  // SF_COUNT_MAX means "length unknown" (some streamed formats); the limit is then enforced while
  // decoding.
  if (info.frames != SF_COUNT_MAX && static_cast<double>(info.frames) > max_frames)
    throw InputError(name, 0,
                     fmt::format("the file is {:.1f} s long, more than the limit of {:.1f} s "
                                 "(ReadOptions::max_duration_seconds)",
                                 static_cast<double>(info.frames) / info.samplerate,
                                 options.max_duration_seconds));

  AudioClip clip;
  clip.sample_rate = info.samplerate;
  clip.channels = info.channels;
  // Decode in blocks: the header's frame count may lie (truncated data chunk), so trust only what
  // reads return, and stop at the duration limit whatever the header said.
  constexpr sf_count_t block_frames = 16384;
  std::vector<float> block(static_cast<std::size_t>(block_frames * info.channels));
  for (;;) {
    const sf_count_t got = sf_readf_float(file, block.data(), block_frames);
    if (got <= 0) break;
    clip.samples.insert(clip.samples.end(), block.begin(), block.begin() + got * info.channels);
    if (static_cast<double>(clip.frames()) > max_frames)
      throw InputError(name, 0,
                       fmt::format("the file holds more than the limit of {:.1f} s of audio",
                                   options.max_duration_seconds));
  }
  if (clip.samples.empty()) throw InputError(name, 0, "the file holds no audio frames");
  for (std::size_t i = 0; i < clip.samples.size(); ++i) {
    if (!std::isfinite(clip.samples[i]))
      throw InputError(name, 0,
                       fmt::format("sample {} of channel {} is not a finite number (NaN or Inf)",
                                   i / static_cast<std::size_t>(clip.channels),
                                   i % static_cast<std::size_t>(clip.channels)));
  }
  return convert_clip(clip, options, name);
}

std::string sndfile_problem(SNDFILE* file) {
  return fmt::format("cannot decode as audio ({})", sf_strerror(file));
}

}  // namespace

AudioClip read_audio(const std::string& path, const ReadOptions& options) {
  SF_INFO info{};
  SndfileHandle file(sf_open(path.c_str(), SFM_READ, &info));
  if (!file) throw InputError(path, 0, sndfile_problem(nullptr));
  return decode(file.get(), info, path, options);
}

AudioClip read_audio_memory(std::span<const std::uint8_t> bytes, const std::string& name,
                            const ReadOptions& options) {
  if (bytes.empty()) throw InputError(name, 0, "the file is empty");
  MemoryFile memory{bytes, 0};
  SF_VIRTUAL_IO io{memory_length, memory_seek, memory_read, memory_write, memory_tell};
  SF_INFO info{};
  SndfileHandle file(sf_open_virtual(&io, SFM_READ, &info, &memory));
  if (!file) throw InputError(name, 0, sndfile_problem(nullptr));
  return decode(file.get(), info, name, options);
}

AudioClip convert_clip(const AudioClip& clip, const ReadOptions& options, const std::string& name) {
  if (clip.channels < 1) throw InputError(name, 0, "the clip has zero channels");
  const std::size_t channels = static_cast<std::size_t>(clip.channels);
  const std::size_t frames = clip.frames();
  AudioClip out;
  out.sample_rate = clip.sample_rate;
  switch (options.channel_policy) {
    case ChannelPolicy::keep_all:
      out = clip;
      break;
    case ChannelPolicy::mean:
      out.channels = 1;
      out.samples.resize(frames);
      for (std::size_t f = 0; f < frames; ++f) {
        // Sum in double: the mean of many channels stays exact to float precision.
        double sum = 0.0;
        for (std::size_t c = 0; c < channels; ++c) sum += clip.samples[f * channels + c];
        out.samples[f] = static_cast<float>(sum / static_cast<double>(channels));
      }
      break;
    case ChannelPolicy::select:
      if (options.channel < 0 || options.channel >= clip.channels)
        throw InputError(
            name, 0,
            fmt::format("channel {} requested but the file has {} channel(s) (0-based)",
                        options.channel, clip.channels));
      out.channels = 1;
      out.samples.resize(frames);
      for (std::size_t f = 0; f < frames; ++f)
        out.samples[f] = clip.samples[f * channels + static_cast<std::size_t>(options.channel)];
      break;
  }
  if (options.target_sample_rate < 0)
    throw InputError(
        name, 0, fmt::format("target sample rate {} Hz is negative", options.target_sample_rate));
  if (options.target_sample_rate > 0 && options.target_sample_rate != out.sample_rate)
    out = resample(out, options.target_sample_rate);
  return out;
}

bool is_audio_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".wav" || ext == ".flac" || ext == ".aiff" || ext == ".aif";
}

AudioClip resample(const AudioClip& clip, int target_rate) {
  if (target_rate < 1)
    throw InputError(fmt::format("resample: target rate {} Hz must be positive", target_rate));
  if (clip.sample_rate < 1)
    throw InputError(fmt::format("resample: source rate {} Hz must be positive", clip.sample_rate));
  if (target_rate == clip.sample_rate) return clip;
  const double ratio = static_cast<double>(target_rate) / clip.sample_rate;
  // libsamplerate accepts ratios in [1/256, 256]; outside that the request is not meaningful audio.
  if (ratio < 1.0 / 256.0 || ratio > 256.0)
    throw InputError(
        fmt::format("resample: ratio {} -> {} Hz is outside libsamplerate's 1/256..256",
                    clip.sample_rate, target_rate));
  const std::size_t frames_in = clip.frames();
  const auto frames_out =
      static_cast<std::size_t>(std::llround(static_cast<double>(frames_in) * ratio));
  AudioClip out;
  out.sample_rate = target_rate;
  out.channels = clip.channels;
  out.samples.assign(frames_out * static_cast<std::size_t>(clip.channels), 0.0f);
  if (frames_in == 0 || frames_out == 0) return out;
  SRC_DATA data{};
  data.data_in = clip.samples.data();
  data.input_frames = static_cast<long>(frames_in);
  data.data_out = out.samples.data();
  data.output_frames = static_cast<long>(frames_out);
  data.src_ratio = ratio;
  data.end_of_input = 1;
  const int status = src_simple(&data, SRC_SINC_BEST_QUALITY, clip.channels);
  if (status != 0)
    throw InputError(fmt::format("resample: libsamplerate failed: {}", src_strerror(status)));
  // src_simple may generate a frame or so fewer than requested; the tail stays zero so lengths are
  // exact.
  return out;
}

WriteOptions write_options_for(const std::string& path) {
  WriteOptions options;
  const auto dot = path.rfind('.');
  if (dot != std::string::npos) {
    std::string ext = path.substr(dot + 1);
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext == "flac") options.format = FileFormat::flac;
  }
  return options;
}

void write_audio(const std::string& path, const AudioClip& clip, const WriteOptions& options) {
  if (clip.channels < 1)
    throw InputError(path, 0, fmt::format("cannot write a clip with {} channels", clip.channels));
  if (clip.sample_rate < 1)
    throw InputError(path, 0, fmt::format("cannot write a clip at {} Hz", clip.sample_rate));
  if (clip.samples.size() % static_cast<std::size_t>(clip.channels) != 0)
    throw InputError(path, 0,
                     fmt::format("{} samples are not a whole number of {}-channel frames",
                                 clip.samples.size(), clip.channels));
  int major = options.format == FileFormat::flac ? SF_FORMAT_FLAC : SF_FORMAT_WAV;
  int subtype = SF_FORMAT_PCM_16;
  if (options.encoding == SampleEncoding::pcm24) subtype = SF_FORMAT_PCM_24;
  if (options.encoding == SampleEncoding::float32) {
    if (options.format == FileFormat::flac)
      throw InputError(path, 0, "FLAC stores integer samples only; use pcm16 or pcm24");
    subtype = SF_FORMAT_FLOAT;
  }
  SF_INFO info{};
  info.samplerate = clip.sample_rate;
  info.channels = clip.channels;
  info.format = major | subtype;
  if (!sf_format_check(&info))
    throw InputError(path, 0,
                     fmt::format("libsndfile cannot write {} channels at {} Hz in this format",
                                 clip.channels, clip.sample_rate));
  SndfileHandle file(sf_open(path.c_str(), SFM_WRITE, &info));
  if (!file)
    throw InputError(path, 0, fmt::format("cannot open for writing ({})", sf_strerror(nullptr)));
  const auto frames = static_cast<sf_count_t>(clip.frames());
  sf_count_t written = 0;
  if (options.encoding == SampleEncoding::float32) {
    written = sf_writef_float(file.get(), clip.samples.data(), frames);
  } else {
    // Quantise here rather than in libsndfile so that writing is the exact inverse of reading
    // (integer / 2^(bits-1)): round to nearest, clip to the integer range. libsndfile 1.2's own
    // float->int path truncates, which would bias every sample by up to one step. 16-bit goes
    // through libsndfile's short interface (stored as is), 24-bit through its int interface, whose
    // top 24 bits are the sample.
    const bool pcm16 = options.encoding == SampleEncoding::pcm16;
    const double scale = pcm16 ? 32768.0 : 8388608.0;
    // Round half to even, as std::nearbyint in the default rounding mode, without its library
    // call per sample: std::lrint becomes one instruction (cvtsd2si) under -fno-math-errno.
    // Clipping before rounding gives the same integers as after (the bounds are integers).
    auto quantise = [&](float sample) {
      return static_cast<int>(
          std::lrint(std::clamp(static_cast<double>(sample) * scale, -scale, scale - 1.0)));
    };
    if (pcm16) {
      std::vector<short> quantised(clip.samples.size());
      for (std::size_t i = 0; i < clip.samples.size(); ++i)
        quantised[i] = static_cast<short>(quantise(clip.samples[i]));
      written = sf_writef_short(file.get(), quantised.data(), frames);
    } else {
      std::vector<int> quantised(clip.samples.size());
      for (std::size_t i = 0; i < clip.samples.size(); ++i)
        quantised[i] = quantise(clip.samples[i]) * (1 << 8);
      written = sf_writef_int(file.get(), quantised.data(), frames);
    }
  }
  if (written != frames)
    throw InputError(path, 0, fmt::format("write failed ({})", sf_strerror(file.get())));
}

}  // namespace echoplan::audio
