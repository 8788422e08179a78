// `echoplan import-bag`: a robot's ROS 1 bag files (joint states, wrenches, audio, markers) as
// a recordings tree that `echoplan train` and a dataset world read (robot/ros/bag_import.h). Built
// when Debian's rosbag storage library is found (ECHOPLAN_HAVE_ROSBAG).
#include <fmt/core.h>

#include <memory>

#include "commands/commands.h"
#include "robot/ros/bag_import.h"

namespace echoplan::cli {

void add_import_bag_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "import-bag",
      "Cut a robot's ROS 1 bags into a recordings tree: every performance between a marker "
      "`start OBJECT ACTION SESSION` and the next `end` (std_msgs/String on --markers) becomes "
      "DIR/<object>/<action>/NNN.<modality>.csv, one file per --topic (sensor_msgs/JointState: "
      "effort, position or velocity; geometry_msgs/WrenchStamped: force, torque or wrench), times "
      "in seconds from the start as the bag recorded them, and with --audio the microphone's "
      "audio_common_msgs/AudioData as DIR/<object>/<action>/NNN.wav, listed in DIR/manifest.csv "
      "with their session (docs/feature-sets.md, \"Raw signals\").\n"
      "Example: echoplan import-bag run1.bag run2.bag -o tree --topic effort=/joint_states "
      "--topic force=/wrist/wrench:force --audio /audio/audio");
  struct Options {
    robot::BagImportOptions import;
    std::vector<std::string> topics;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("bags", opt->import.bags, "Bag files, read in order")->required();
  cmd->add_option("-o,--output", opt->import.output_dir,
                  "Folder to write (created; its manifest.csv is replaced)")
      ->required();
  cmd->add_option("--topic", opt->topics,
                  "MODALITY=TOPIC[:FIELD], once per modality (FIELD: effort, position, velocity "
                  "of a JointState, default effort; force, torque, wrench of a WrenchStamped, "
                  "default force)");
  cmd->add_option("--audio", opt->import.audio_topic,
                  "The robot's microphone topic (audio_common_msgs/AudioData, wave S16LE as "
                  "audio_capture publishes it): each performance's audio as NNN.wav");
  cmd->add_option("--audio-info", opt->import.audio_info_topic,
                  "Where the audio's format is (audio_common_msgs/AudioInfo); default: the "
                  "--audio topic + _info, where audio_capture publishes it");
  cmd->add_option("--markers", opt->import.marker_topic,
                  "The topic of the performance markers (std_msgs/String)")
      ->capture_default_str();
  cmd->callback([opt] {
    for (const std::string& t : opt->topics)
      opt->import.series.push_back(robot::parse_series_topic(t));
    const robot::BagImportSummary summary = robot::import_bags(
        opt->import,
        [](const std::string& bag, int done) { fmt::print(stderr, "[{}] {}\n", done, bag); });
    fmt::print("{} performances in {}; manifest: {}/manifest.csv\n", summary.performances,
               opt->import.output_dir, opt->import.output_dir);
    if (summary.unfinished > 0)
      fmt::print(stderr,
                 "echoplan: {} performance(s) started but not ended when their bag ended: not "
                 "written\n",
                 summary.unfinished);
  });
}

}  // namespace echoplan::cli
