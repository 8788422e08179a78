// Reading and writing audio files (WAV, FLAC, anything libsndfile decodes) as AudioClips.
//
// Reading turns any sample format (8/16/24/32-bit integer, 32/64-bit float) into floats in [-1, 1),
// applies a channel policy (keep all, mean of channels, or one channel) and optionally resamples to
// a fixed rate with libsamplerate. Every problem with the file (missing, empty, truncated, not
// audio, zero channels, NaN/Inf samples, longer than the configured limit) throws
// echoplan::InputError naming the file. Writing encodes a clip as WAV or FLAC; integer encodings
// round each sample to the nearest step and clip to full scale, so read_audio(write_audio(x)) ==
// round(x * 2^(bits-1)) / 2^(bits-1) exactly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "audio/clip.h"

namespace echoplan::audio {

// What to do with the channels of a multi-channel file.
enum class ChannelPolicy {
  keep_all,  // keep every channel, interleaved (AudioClip::channels = file's channels)
  mean,      // average all channels into one (the usual choice for features)
  select,    // keep only channel ReadOptions::channel (0-based)
};

// How to read a file. Defaults: keep every channel at the file's own rate, at most 10 minutes of
// audio.
struct ReadOptions {
  ChannelPolicy channel_policy = ChannelPolicy::keep_all;
  int channel = 0;  // used when channel_policy == select; must be < the file's channels
  int target_sample_rate =
      0;  // Hz; 0 keeps the file's rate, otherwise resample (libsamplerate, best quality)
  // Files longer than this are rejected before any sample is decoded, so a huge or lying header can
  // never exhaust memory. 10 minutes at 48 kHz stereo is ~230 MB of floats.
  double max_duration_seconds = 600.0;
};

// Decodes `path`. Throws InputError(path, 0, problem) for every failure, including non-finite
// samples (a float WAV holding NaN or Inf is rejected rather than silently repaired). A file with
// zero frames is an error ("no audio frames"); pure silence is valid and returned as zeros.
AudioClip read_audio(const std::string& path, const ReadOptions& options = {});

// Decodes an in-memory file image (same formats and checks as read_audio). `name` is used in error
// messages in place of a path. Used by the fuzzer and by callers that receive audio over a network.
AudioClip read_audio_memory(std::span<const std::uint8_t> bytes, const std::string& name,
                            const ReadOptions& options = {});

// Applies a channel policy and optional resampling to a clip already in memory (what read_audio
// does after decoding). `name` is used in error messages.
AudioClip convert_clip(const AudioClip& clip, const ReadOptions& options, const std::string& name);

// Resamples every channel of `clip` to `target_rate` Hz with libsamplerate (SRC_SINC_BEST_QUALITY).
// The output has round(frames * target_rate / rate) frames. Returns the clip unchanged if rates
// match.
AudioClip resample(const AudioClip& clip, int target_rate);

// A file name read as audio (its extension, any case): .wav, .flac, .aiff, .aif.
bool is_audio_file(const std::string& path);

enum class FileFormat { wav, flac };
enum class SampleEncoding { pcm16, pcm24, float32 };  // float32 only for WAV (FLAC is integer only)

// How to write a file. Default: 16-bit PCM WAV.
struct WriteOptions {
  FileFormat format = FileFormat::wav;
  SampleEncoding encoding = SampleEncoding::pcm16;
};

// The format a file name implies: ".flac" -> flac, otherwise wav.
WriteOptions write_options_for(const std::string& path);

// Writes `clip` to `path`, replacing any existing file. Throws InputError(path, 0, problem) if the
// clip is malformed (channels < 1, sample_rate < 1, samples not a whole number of frames), if the
// encoding is not possible in the format (float32 FLAC), or if the file cannot be written.
void write_audio(const std::string& path, const AudioClip& clip, const WriteOptions& options = {});

}  // namespace echoplan::audio
