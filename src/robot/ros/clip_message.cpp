#include "robot/ros/clip_message.h"

#include <fmt/format.h>

#include <cmath>

#include "common/error.h"

namespace echoplan::robot {
namespace {

audio::AudioClip make_clip(int sample_rate, int channels, const std::vector<float>& samples,
                           const std::string& source) {
  if (sample_rate < 1)
    throw InputError(source, 0, fmt::format("sample rate must be >= 1, got {}", sample_rate));
  if (channels < 1)
    throw InputError(source, 0, fmt::format("channels must be >= 1, got {}", channels));
  if (samples.size() % static_cast<std::size_t>(channels) != 0)
    throw InputError(source, 0,
                     fmt::format("{} samples are not a whole number of {}-channel frames",
                                 samples.size(), channels));
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (!std::isfinite(samples[i]))
      throw InputError(source, 0, fmt::format("sample {} is not finite", i));
  audio::AudioClip clip;
  clip.sample_rate = sample_rate;
  clip.channels = channels;
  clip.samples = samples;
  return clip;
}

}  // namespace

audio::AudioClip clip_from_message(const echoplan_ros::Clip& message, const std::string& source) {
  return make_clip(message.sample_rate, message.channels, message.samples, source);
}

audio::AudioClip clip_from_request(const echoplan_ros::Observe::Request& request,
                                   const std::string& source) {
  return make_clip(request.sample_rate, request.channels, request.samples, source);
}

void fill_message(const audio::AudioClip& clip, echoplan_ros::Clip& message) {
  message.sample_rate = clip.sample_rate;
  message.channels = clip.channels;
  message.samples = clip.samples;
}

void fill_request(const audio::AudioClip& clip, echoplan_ros::Observe::Request& request) {
  request.sample_rate = clip.sample_rate;
  request.channels = clip.channels;
  request.samples = clip.samples;
}

}  // namespace echoplan::robot
