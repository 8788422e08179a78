// A sensor's ROS topic as a series (signal/series.h): which topic gives which modality, how each
// of its messages becomes one sample, and the markers that say when a performance began and ended.
// The bag import (bag_import.h) and the live observation node read topics through this one reader,
// so a bag and a live stream of the same messages give the same series.
//
// Series topics: sensor_msgs/JointState (its effort, position or velocity: one channel per joint,
// named as the topic's first message names them) and geometry_msgs/WrenchStamped (its force:
// force_x, force_y, force_z; its torque: torque_x..; or the whole wrench: both).
// Markers: std_msgs/String messages, each `start OBJECT ACTION SESSION` or `end`.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "robot/ros/bag_messages.h"

namespace echoplan::robot {

// One modality and where it comes from: `effort=/joint_states:effort`.
struct SeriesTopic {
  std::string
      modality;  // the modality's name (a recordings tree's <name>.<modality>.csv; not "audio")
  std::string topic;
  std::string
      field;  // JointState: effort, position, velocity; WrenchStamped: force, torque, wrench
};

// Parses `MODALITY=TOPIC[:FIELD]` (FIELD defaults to effort for JointState, force for a wrench,
// decided when the topic's type is known). InputError naming the text when it is malformed.
SeriesTopic parse_series_topic(const std::string& text);

// A marker's words.
struct PerformanceMarker {
  bool start = false;  // false: `end`
  std::string object, action, session;
};
// The marker `text` says, or nothing when it is neither `start OBJECT ACTION SESSION` (plain
// names: no '/', ',', '"' or leading '.') nor `end`.
std::optional<PerformanceMarker> parse_performance_marker(const std::string& text);
// The text of a start marker. InputError when a name is not plain (it would not read back).
std::string start_marker_text(const std::string& object, const std::string& action,
                              const std::string& session);

// One series topic's messages as samples. The first message fixes the topic's type, its field
// (when the spec left it empty) and its channels; every later message must be of that type and
// carry every channel.
class SeriesTopicReader {
 public:
  explicit SeriesTopicReader(SeriesTopic spec);

  // The values of one message (its type, MD5 sum and serialized bytes) in channel order.
  // InputError("", 0, problem) for: a type that is neither series type (or not the first
  // message's), an MD5 sum of another layout, bytes that do not decode, a field its type does not
  // have, a joint state naming no joint (first message), one missing a joint of the first message,
  // or with fewer values than names. The problem reads after "topic T message N: ".
  std::vector<double> read(const std::string& type, const std::string& md5,
                           std::span<const std::uint8_t> bytes);

  const SeriesTopic& spec() const { return spec_; }
  // Empty until the first message was read.
  const std::vector<std::string>& channels() const { return channels_; }
  const std::string& type() const { return type_; }
  int messages() const { return messages_; }  // read() calls so far, failed ones included

 private:
  void first_message(const std::string& type, const std::string& md5,
                     std::span<const std::uint8_t> bytes);

  SeriesTopic spec_;
  std::string type_;
  std::vector<std::string> channels_;
  int messages_ = 0;
};

}  // namespace echoplan::robot
