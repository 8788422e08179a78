#include "commands/feature_options.h"

#include <fmt/format.h>

#include <charconv>

#include "audio/io.h"
#include "common/error.h"

namespace echoplan::cli {

void add_feature_options(CLI::App& cmd, FeatureOptions& options) {
  cmd.add_option("--preset", options.preset,
                 "Feature preset: psf (python_speech_features: 25/10 ms frames, 26 log "
                 "filterbanks, 13 MFCC) or\n"
                 "librosa (librosa 0.11 defaults: 2048/512 frames, 128 dB mels, 20 MFCC)")
      ->check(CLI::IsMember({"psf", "librosa"}))
      ->capture_default_str();
  cmd.add_option(
         "--feature", options.feature,
         "Feature: logmel (psf: logfbank; librosa: dB mel spectrogram), mfcc, centroid, rms, zcr,\n"
         "bandwidth, rolloff, flatness, flux")
      ->check(CLI::IsMember({"logmel", "mfcc", "centroid", "rms", "zcr", "bandwidth", "rolloff",
                             "flatness", "flux"}));
  cmd.add_option("--channel", options.channel,
                 "Channels: mean (average them) or a 0-based channel index")
      ->capture_default_str();
  cmd.add_option("--resample", options.resample_hz,
                 "Resample to this rate in Hz before analysis (0: keep the file's rate)")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
}

audio::AudioClip read_for_features(const FeatureOptions& options, const std::string& path) {
  audio::ReadOptions read;
  read.target_sample_rate = options.resample_hz;
  if (options.channel == "mean") {
    read.channel_policy = audio::ChannelPolicy::mean;
  } else {
    int channel = -1;
    const char* begin = options.channel.data();
    const char* end = begin + options.channel.size();
    const auto [ptr, ec] = std::from_chars(begin, end, channel);
    if (ec != std::errc() || ptr != end || channel < 0)
      throw InputError(fmt::format("--channel '{}' must be 'mean' or a channel index 0, 1, ...",
                                   options.channel));
    read.channel_policy = audio::ChannelPolicy::select;
    read.channel = channel;
  }
  return audio::read_audio(path, read);
}

}  // namespace echoplan::cli
