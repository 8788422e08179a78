// Tests of audio/io.h: round trips through libsndfile, channel policies, resampling, and every kind
// of bad file the reader must reject with an InputError naming the file.
#include "audio/io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>

#include "../common/source_dir.h"
#include "common/error.h"

namespace echoplan::audio {
namespace {

namespace fs = std::filesystem;

const std::string kInputs = echoplan::testing::source_dir() + "/tests/data/reference/audio/inputs/";

fs::path temp_path(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("echoplan_io_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

void write_bytes(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

AudioClip sine_clip(int rate, int channels, int frames, double hz) {
  AudioClip clip;
  clip.sample_rate = rate;
  clip.channels = channels;
  clip.samples.resize(static_cast<std::size_t>(frames * channels));
  for (int f = 0; f < frames; ++f)
    for (int c = 0; c < channels; ++c)
      clip.samples[static_cast<std::size_t>(f * channels + c)] =
          static_cast<float>(0.5 * std::sin(2 * std::numbers::pi * hz * f / rate + c));
  return clip;
}

// Succeeds when `fn` throws an InputError whose file is `file` and whose message contains
// `fragment`.
template <typename Fn>
::testing::AssertionResult throws_input_error(Fn fn, const std::string& file,
                                              const std::string& fragment) {
  try {
    fn();
  } catch (const InputError& e) {
    if (e.file() != file)
      return ::testing::AssertionFailure()
             << "InputError names '" << e.file() << "', not '" << file << "'";
    if (std::string(e.what()).find(fragment) == std::string::npos)
      return ::testing::AssertionFailure()
             << "InputError '" << e.what() << "' lacks '" << fragment << "'";
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "expected InputError containing '" << fragment << "', nothing thrown";
}

// 16-bit PCM quantises to 1/32768; a round trip may be off by half a step (plus float rounding).
constexpr double kPcm16Step =
    1.0 / 32768.0;  // exact: writing rounds to nearest, reading divides by 2^15

TEST(AudioIo, Pcm16WavRoundTripKeepsShapeAndSamplesToHalfAStep) {
  const AudioClip clip = sine_clip(44100, 2, 4410, 440.0);
  const auto path = temp_path("round.wav").string();
  write_audio(path, clip);
  const AudioClip back = read_audio(path);
  EXPECT_EQ(back.sample_rate, 44100);
  EXPECT_EQ(back.channels, 2);
  ASSERT_EQ(back.samples.size(), clip.samples.size());
  for (std::size_t i = 0; i < clip.samples.size(); ++i)
    EXPECT_NEAR(back.samples[i], clip.samples[i], 0.5 * kPcm16Step);
}

TEST(AudioIo, FlacRoundTripIsLossless) {
  // FLAC is lossless over the 16-bit samples, so a FLAC round trip equals a WAV round trip exactly.
  const AudioClip clip = sine_clip(22050, 1, 3000, 1000.0);
  const auto wav = temp_path("a.wav").string();
  const auto flac = temp_path("a.flac").string();
  write_audio(wav, clip);
  write_audio(flac, clip, write_options_for(flac));
  EXPECT_EQ(write_options_for(flac).format, FileFormat::flac);
  const auto bytes = read_bytes(flac);
  ASSERT_GE(bytes.size(), 4u);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "fLaC");
  EXPECT_EQ(read_audio(flac).samples, read_audio(wav).samples);
}

TEST(AudioIo, Float32WavRoundTripIsExact) {
  const AudioClip clip = sine_clip(48000, 3, 100, 300.0);
  const auto path = temp_path("f.wav").string();
  write_audio(path, clip, {FileFormat::wav, SampleEncoding::float32});
  EXPECT_EQ(read_audio(path).samples, clip.samples);
  EXPECT_TRUE(throws_input_error(
      [&] {
        write_audio(temp_path("f.flac").string(), clip,
                    {FileFormat::flac, SampleEncoding::float32});
      },
      temp_path("f.flac").string(), "integer"));
}

// Writes mono 44.1 kHz `samples` with `options` and reads them back.
std::vector<float> round_trip(const std::vector<float>& samples, const std::string& name,
                              const WriteOptions& options = {}) {
  AudioClip clip;
  clip.samples = samples;
  const auto path = temp_path(name).string();
  write_audio(path, clip, options);
  return read_audio(path).samples;
}

TEST(AudioIo, WriteClipsOutOfRangeSamplesToFullScale) {
  const std::vector<float> back = round_trip({2.0f, -2.0f, 0.25f}, "clip.wav");
  EXPECT_NEAR(back[0], 32767.0 / 32768.0, 1e-7);
  EXPECT_FLOAT_EQ(back[1], -1.0f);
  EXPECT_FLOAT_EQ(back[2], 0.25f);
}

TEST(AudioIo, HalfStepsRoundToEvenInEveryIntegerEncoding) {
  // Writing rounds half a step to the even neighbour (as std::nearbyint does): 0.5 -> 0,
  // 1.5 -> 2, 2.5 -> 2, -0.5 -> 0, -1.5 -> -2; 32767.6 steps round up to 32768, which 16 bits
  // clip to their top code 32767 and 24 bits store as is.
  const auto steps = [](float step) {
    std::vector<float> v;
    for (double k : {0.5, 1.5, 2.5, -0.5, -1.5, 32767.6}) v.push_back(static_cast<float>(k * step));
    return v;
  };
  const float step16 = std::ldexp(1.0f, -15), step24 = std::ldexp(1.0f, -23);
  const std::vector<float> even16{0, 2 * step16, 2 * step16, 0, -2 * step16, 32767 * step16};
  EXPECT_EQ(round_trip(steps(step16), "even16.wav"), even16);
  EXPECT_EQ(round_trip(steps(step16), "even16.flac", {FileFormat::flac, SampleEncoding::pcm16}),
            even16);
  const std::vector<float> even24{0, 2 * step24, 2 * step24, 0, -2 * step24, 32768 * step24};
  EXPECT_EQ(round_trip(steps(step24), "even24.wav", {FileFormat::wav, SampleEncoding::pcm24}),
            even24);
}

TEST(AudioIo, IntegerPcmIsDividedByTwoToTheBitsMinusOne) {
  // 16384 must read as exactly 0.5 and -32768 as -1; in 24 bits, one step is 2^-23.
  const std::vector<float> exact{0.5f, -1.0f, 0.0f};
  EXPECT_EQ(round_trip(exact, "exact.wav"), exact);
  const float step24 = std::ldexp(1.0f, -23);
  const std::vector<float> fine{3 * step24, -step24, 0.75f};
  EXPECT_EQ(round_trip(fine, "fine.wav", {FileFormat::wav, SampleEncoding::pcm24}), fine);
  EXPECT_EQ(round_trip(fine, "fine.flac", {FileFormat::flac, SampleEncoding::pcm24}), fine);
  // The same values in 16 bits round to the nearest 2^-15 step: 3 * 2^-23 and -2^-23 become 0.
  EXPECT_EQ(round_trip(fine, "coarse.wav"), (std::vector<float>{0.0f, 0.0f, 0.75f}));
}

TEST(AudioIo, MeanPolicyAveragesChannelsAndSelectPicksOne) {
  const AudioClip stereo = read_audio(kInputs + "impact_dull_44k_stereo.wav");
  ASSERT_EQ(stereo.channels, 2);
  const AudioClip mean =
      read_audio(kInputs + "impact_dull_44k_stereo.wav", {.channel_policy = ChannelPolicy::mean});
  const AudioClip right = read_audio(kInputs + "impact_dull_44k_stereo.wav",
                                     {.channel_policy = ChannelPolicy::select, .channel = 1});
  ASSERT_EQ(mean.channels, 1);
  ASSERT_EQ(mean.frames(), stereo.frames());
  for (std::size_t f = 0; f < stereo.frames(); f += 97) {
    EXPECT_FLOAT_EQ(mean.samples[f], 0.5f * (stereo.samples[2 * f] + stereo.samples[2 * f + 1]));
    EXPECT_EQ(right.samples[f], stereo.samples[2 * f + 1]);
  }
  EXPECT_TRUE(throws_input_error(
      [&] {
        read_audio(kInputs + "impact_dull_44k_stereo.wav",
                   {.channel_policy = ChannelPolicy::select, .channel = 2});
      },
      kInputs + "impact_dull_44k_stereo.wav", "channel 2 requested"));
}

TEST(AudioIo, ReadsFlacReferenceInputs) {
  const AudioClip clip = read_audio(kInputs + "real_cc0_cowbell.flac");
  EXPECT_GT(clip.frames(), 1000u);
  EXPECT_GT(clip.sample_rate, 0);
}

TEST(AudioIo, ResamplingPreservesASineAndSetsLength) {
  // A 440 Hz sine resampled 44.1 -> 16 kHz keeps its frequency: compare with the analytic sine at
  // the new rate away from the edges (sinc filter transients). Best-quality SRC has ~ -97 dB
  // stopband; 1e-3 absolute covers its passband ripple at 440 Hz.
  const AudioClip clip = sine_clip(44100, 1, 44100, 440.0);
  const AudioClip out = convert_clip(clip, {.target_sample_rate = 16000}, "sine");
  EXPECT_EQ(out.sample_rate, 16000);
  ASSERT_EQ(out.frames(), 16000u);
  for (int f = 1000; f < 15000; f += 37)
    EXPECT_NEAR(out.samples[static_cast<std::size_t>(f)],
                0.5 * std::sin(2 * std::numbers::pi * 440.0 * f / 16000), 1e-3);
}

TEST(AudioIo, PureSilenceIsValidAndReadAsZeros) {
  AudioClip silence;
  silence.samples.assign(1000, 0.0f);
  const auto path = temp_path("silence.wav").string();
  write_audio(path, silence);
  const AudioClip back = read_audio(path);
  EXPECT_EQ(back.samples, silence.samples);
}

TEST(AudioIo, MissingEmptyAndNonAudioFilesAreInputErrors) {
  EXPECT_TRUE(throws_input_error([] { read_audio("/nonexistent/x.wav"); }, "/nonexistent/x.wav",
                                 "cannot decode"));
  const auto empty = temp_path("empty.wav");
  write_bytes(empty, {});
  EXPECT_TRUE(
      throws_input_error([&] { read_audio(empty.string()); }, empty.string(), "cannot decode"));
  EXPECT_TRUE(throws_input_error([] { read_audio_memory({}, "mem", {}); }, "mem", "empty"));
  const auto text = temp_path("text.wav");
  const std::string words =
      "this is not a sound file, just some words that go on for a while......";
  write_bytes(text, std::vector<std::uint8_t>(words.begin(), words.end()));
  EXPECT_TRUE(
      throws_input_error([&] { read_audio(text.string()); }, text.string(), "cannot decode"));
}

TEST(AudioIo, TruncatedHeaderIsAnInputErrorAndTruncatedDataReadsWhatIsThere) {
  const auto bytes = read_bytes(kInputs + "chirp_1s_22k_mono.wav");
  const std::vector<std::uint8_t> header_only(bytes.begin(), bytes.begin() + 20);
  EXPECT_TRUE(throws_input_error([&] { read_audio_memory(header_only, "cut.wav"); }, "cut.wav",
                                 "cannot decode"));
  // Header intact but the data chunk cut after 1000 bytes (500 16-bit frames): the reader returns
  // what is there instead of trusting the header's length.
  std::size_t data_offset = 0;
  for (std::size_t i = 12; i + 8 <= bytes.size(); ++i)
    if (std::memcmp(bytes.data() + i, "data", 4) == 0) {
      data_offset = i + 8;
      break;
    }
  ASSERT_GT(data_offset, 0u);
  const std::vector<std::uint8_t> cut(bytes.begin(),
                                      bytes.begin() + static_cast<long>(data_offset + 1000));
  const AudioClip clip = read_audio_memory(cut, "cut.wav");
  EXPECT_EQ(clip.frames(), 500u);
  const std::vector<std::uint8_t> no_data(bytes.begin(),
                                          bytes.begin() + static_cast<long>(data_offset));
  EXPECT_TRUE(
      throws_input_error([&] { read_audio_memory(no_data, "nodata.wav"); }, "nodata.wav", ""));
}

// Builds a minimal canonical WAV header (44 bytes) with arbitrary fields, for headers no encoder
// writes.
std::vector<std::uint8_t> wav_bytes(std::uint16_t format_tag, std::uint16_t channels,
                                    std::uint32_t rate, std::uint16_t bits,
                                    const std::vector<std::uint8_t>& data) {
  std::vector<std::uint8_t> out;
  auto put = [&](std::uint64_t value, int n) {
    for (int i = 0; i < n; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
  };
  auto tag = [&](const char* s) {
    put(static_cast<std::uint64_t>(std::uint8_t(s[0])) | std::uint64_t(std::uint8_t(s[1])) << 8 |
            std::uint64_t(std::uint8_t(s[2])) << 16 | std::uint64_t(std::uint8_t(s[3])) << 24,
        4);
  };
  const std::uint16_t block = static_cast<std::uint16_t>(channels * bits / 8);
  tag("RIFF");
  put(36 + data.size(), 4);
  tag("WAVE");
  tag("fmt ");
  put(16, 4);
  put(format_tag, 2);
  put(channels, 2);
  put(rate, 4);
  put(rate * block, 4);
  put(block, 2);
  put(bits, 2);
  tag("data");
  put(data.size(), 4);
  out.insert(out.end(), data.begin(), data.end());
  return out;
}

TEST(AudioIo, ZeroChannelHeaderIsAnInputError) {
  const auto bytes = wav_bytes(1, 0, 44100, 16, std::vector<std::uint8_t>(64, 0));
  EXPECT_TRUE(throws_input_error([&] { read_audio_memory(bytes, "zero.wav"); }, "zero.wav", ""));
}

TEST(AudioIo, NonFiniteFloatSamplesAreInputErrors) {
  for (float bad :
       {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    std::vector<float> samples = {0.1f, 0.2f, bad, 0.3f};
    std::vector<std::uint8_t> data(samples.size() * 4);
    std::memcpy(data.data(), samples.data(), data.size());
    const auto bytes = wav_bytes(3, 1, 8000, 32, data);  // format tag 3 = IEEE float
    EXPECT_TRUE(throws_input_error([&] { read_audio_memory(bytes, "nan.wav"); }, "nan.wav",
                                   "sample 2 of channel 0 is not a finite"));
  }
}

TEST(AudioIo, FilesLongerThanTheLimitAreRejectedBeforeDecoding) {
  const AudioClip clip = sine_clip(8000, 1, 8000 * 3, 100.0);
  const auto path = temp_path("long.wav").string();
  write_audio(path, clip);
  EXPECT_TRUE(throws_input_error([&] { read_audio(path, {.max_duration_seconds = 2.0}); }, path,
                                 "limit of 2.0 s"));
  EXPECT_EQ(read_audio(path, {.max_duration_seconds = 3.0}).frames(), 24000u);
  // A header that claims ~6.8 hours (the maximum 32-bit data size) over 100 real bytes: only the 50
  // frames present are decoded, nothing is allocated for the claimed length.
  auto bytes = wav_bytes(1, 1, 44100, 16, std::vector<std::uint8_t>(100, 0));
  for (int i = 0; i < 4; ++i) bytes[40 + static_cast<std::size_t>(i)] = 0xFF;
  EXPECT_EQ(read_audio_memory(bytes, "huge.wav").frames(), 50u);
}

TEST(AudioIo, MalformedClipsCannotBeWritten) {
  AudioClip clip;
  clip.channels = 2;
  clip.samples = {0.1f, 0.2f, 0.3f};
  EXPECT_TRUE(throws_input_error([&] { write_audio(temp_path("bad.wav").string(), clip); },
                                 temp_path("bad.wav").string(), "whole number"));
  clip.channels = 0;
  EXPECT_TRUE(throws_input_error([&] { write_audio(temp_path("bad.wav").string(), clip); },
                                 temp_path("bad.wav").string(), "0 channels"));
  EXPECT_TRUE(throws_input_error(
      [&] { write_audio("/nonexistent/dir/x.wav", sine_clip(8000, 1, 10, 1.0)); },
      "/nonexistent/dir/x.wav", "cannot open"));
}

}  // namespace
}  // namespace echoplan::audio
