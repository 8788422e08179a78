// libFuzzer target: arbitrary bytes as the body of the ROS messages echoplan reads off the wire
// (robot/ros/ros_messages.h's deserializers), and the audio ones on into what the nodes make of
// them: echoplan_ros/Clip and Observe's request through clip_from_message / clip_from_request, and
// audio_common_msgs/AudioData through the S16LE chunk decoder (robot/ros/s16le_chunk.h) at a
// channel count and frame limit taken from the first two bytes. A body that does not hold the
// message must end in roscpp's StreamOverrunException (roscpp then drops the message) and a bad
// clip in echoplan::InputError; anything else (a crash, a sanitizer report, another exception, a
// hang, an allocation beyond the message's size) is a bug. No ROS master is involved.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/error.h"
#include "robot/ros/clip_message.h"
#include "robot/ros/ros_messages.h"
#include "robot/ros/s16le_chunk.h"

namespace {

// Deserializes `body` into `message` as roscpp does for a received message; false when the body is
// too short for what it announces.
template <typename Message>
bool decode(std::vector<std::uint8_t>& body, Message& message) {
  try {
    ros::serialization::IStream stream(body.data(), static_cast<std::uint32_t>(body.size()));
    ros::serialization::deserialize(stream, message);
    return true;
  } catch (const ros::serialization::StreamOverrunException&) {
    return false;
  }
}

void check_clip(const echoplan::audio::AudioClip& clip, std::size_t samples) {
  if (clip.channels < 1 || clip.sample_rate < 1 || clip.samples.size() != samples ||
      clip.samples.size() % static_cast<std::size_t>(clip.channels) != 0)
    __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace echoplan::robot;
  std::vector<std::uint8_t> body(data, data + size);
  try {
    echoplan_ros::Clip clip;
    if (decode(body, clip)) check_clip(clip_from_message(clip, "fuzz"), clip.samples.size());
  } catch (const echoplan::InputError&) {
  }
  try {
    echoplan_ros::Observe::Request request;
    if (decode(body, request))
      check_clip(clip_from_request(request, "fuzz"), request.samples.size());
  } catch (const echoplan::InputError&) {
  }
  echoplan_ros::Observe::Response response;
  (void)decode(body, response);
  echoplan_ros::FeatureRow row;
  (void)decode(body, row);

  audio_common_msgs::AudioData chunk;
  if (size >= 2 && decode(body, chunk)) {
    const int channels = 1 + data[0] % 8;
    const std::size_t max_frames = 1 + data[1];
    std::vector<float> samples;
    for (int i = 0; i < 3; ++i) {
      const ChunkOutcome outcome = append_s16le_chunk(chunk.data, channels, max_frames, samples);
      const std::size_t frames = samples.size() / static_cast<std::size_t>(channels);
      if (samples.size() % static_cast<std::size_t>(channels) != 0 || frames > max_frames ||
          outcome.limit_reached != (frames == max_frames) ||
          outcome.misaligned != (chunk.data.size() % (2 * static_cast<std::size_t>(channels)) != 0))
        __builtin_trap();
      if (outcome.limit_reached) break;
    }
  }
  return 0;
}
