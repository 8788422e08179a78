// ROS 1 bag files as a recordings tree (docs/feature-sets.md, "Raw signals"): each performance's
// joint states and wrenches, cut between the markers that say when an action began and ended,
// written as DIR/<object>/<action>/NNN.<modality>.csv with a manifest, so `echoplan train` and a
// dataset world read a robot's bags as they read any recordings.
//
// Markers: std_msgs/String messages on one topic (default /echoplan/performance), each either
// `start OBJECT ACTION SESSION` or `end`. A performance is every message of a series topic received
// between its start and its end, inclusive; its times are seconds from its start. All times are
// the bag's record times (when rosbag received each message): the one clock markers, joint states
// and wrenches share, whatever their header stamps say.
//
// Series topics are read as series_topic.h says (the live observation node reads them the same
// way). Audio: the audio_common_msgs/AudioData chunks of a robot's microphone topic (as
// audio_capture publishes them: S16LE, format on its AudioInfo topic) received between the
// markers, written as the performance's NNN.wav.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "robot/ros/ros_protocol.h"
#include "robot/ros/series_topic.h"

namespace echoplan::robot {

struct BagImportOptions {
  std::vector<std::string> bags;  // read in this order; markers may not span two bags
  std::string output_dir;         // created; its manifest.csv is replaced
  std::string marker_topic = ros_names::kPerformanceTopic;
  std::vector<SeriesTopic> series;  // modalities distinct; at least one unless audio_topic is set
  std::string audio_topic;          // empty: no audio
  std::string audio_info_topic;     // its format; empty: audio_topic + "_info"
};

struct BagImportSummary {
  int performances = 0;  // written, each with one file per series topic (and its WAV)
  int unfinished = 0;    // started but not ended when a bag ended (not written)
};

// (bag, performances so far)
using BagProgress = std::function<void(const std::string&, int)>;

// Reads the bags and writes the tree. InputError naming the bag, the topic and the message index
// for: a bag that cannot be read, a topic with no messages or of another type, a marker that is
// not `start OBJECT ACTION SESSION` or `end` (or an end with no start, a start inside another), a
// joint state missing one of the first message's joints or with fewer values than names, a
// performance with fewer than two samples of a topic; for audio, no format on its info topic or
// one other than wave S16LE, a chunk that is not whole frames, a performance with no audio. Files
// appear atomically, the manifest row after them, so an interrupted import keeps every performance
// it finished.
BagImportSummary import_bags(const BagImportOptions& options, const BagProgress& progress);

}  // namespace echoplan::robot
