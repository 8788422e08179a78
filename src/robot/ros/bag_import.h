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
// way). Audio in bags is not read here (record it with `echoplan record` or the ROS recorder).
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
  std::vector<SeriesTopic> series;  // at least one, modalities distinct
};

struct BagImportSummary {
  int performances = 0;  // written, each with one file per series topic
  int unfinished = 0;    // started but not ended when a bag ended (not written)
};

// (bag, performances so far)
using BagProgress = std::function<void(const std::string&, int)>;

// Reads the bags and writes the tree. InputError naming the bag, the topic and the message index
// for: a bag that cannot be read, a topic with no messages or of another type, a marker that is
// not `start OBJECT ACTION SESSION` or `end` (or an end with no start, a start inside another), a
// joint state missing one of the first message's joints or with fewer values than names, a
// performance with fewer than two samples of a topic. Files appear atomically, the manifest row
// after them, so an interrupted import keeps every performance it finished.
BagImportSummary import_bags(const BagImportOptions& options, const BagProgress& progress);

}  // namespace echoplan::robot
