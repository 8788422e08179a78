// Converting between AudioClip and the ROS messages that carry clips (Clip, Observe's request).
#pragma once

#include <string>

#include "audio/clip.h"
#include "robot/ros/ros_messages.h"

namespace echoplan::robot {

// The message's samples as a clip. Throws InputError naming `source` when the message is malformed
// (rate or channels < 1, samples not a whole number of frames, non-finite samples).
audio::AudioClip clip_from_message(const echoplan_ros::Clip& message, const std::string& source);
audio::AudioClip clip_from_request(const echoplan_ros::Observe::Request& request,
                                   const std::string& source);

// Fills the message's rate, channels and samples from `clip`.
void fill_message(const audio::AudioClip& clip, echoplan_ros::Clip& message);
void fill_request(const audio::AudioClip& clip, echoplan_ros::Observe::Request& request);

}  // namespace echoplan::robot
