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
// Series topics: sensor_msgs/JointState (its effort, position or velocity: one channel per joint,
// named as the first message names them) and geometry_msgs/WrenchStamped (its force: force_x,
// force_y, force_z; its torque: torque_x..; or the whole wrench: both). Audio in bags is not read
// here (record it with `echoplan record` or the ROS recorder).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace echoplan::robot {

// One modality of the tree and where it comes from: `effort=/joint_states:effort`.
struct SeriesTopic {
  std::string modality;  // the files' <modality> (not "audio")
  std::string topic;
  std::string
      field;  // JointState: effort, position, velocity; WrenchStamped: force, torque, wrench
};

// Parses `MODALITY=TOPIC[:FIELD]` (FIELD defaults to effort for JointState, force for a wrench,
// decided when the topic's type is known). InputError naming the text when it is malformed.
SeriesTopic parse_series_topic(const std::string& text);

struct BagImportOptions {
  std::vector<std::string> bags;  // read in this order; markers may not span two bags
  std::string output_dir;         // created; its manifest.csv is replaced
  std::string marker_topic = "/echoplan/performance";
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
