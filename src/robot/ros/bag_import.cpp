#include "robot/ros/bag_import.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>

#include "common/error.h"
#include "robot/ros/bag_messages.h"
#include "robot/ros/series_topic.h"
#include "signal/series.h"

namespace echoplan::robot {

namespace {

namespace fs = std::filesystem;

// Where in a bag an error is: "topic T message N" (N from 1, counted per topic).
std::string where(const std::string& topic, int index) {
  return fmt::format("topic {} message {}", topic, index);
}

// A message's type, MD5 sum and serialized bytes.
struct Serialized {
  std::string type, md5;
  std::vector<std::uint8_t> bytes;
};
Serialized serialized(const rosbag::MessageInstance& m) {
  Serialized s{m.getDataType(), m.getMD5Sum(), std::vector<std::uint8_t>(m.size())};
  ros::serialization::OStream stream(s.bytes.data(), static_cast<std::uint32_t>(s.bytes.size()));
  m.write(stream);
  return s;
}

// A marker's text. InputError naming the bag, the topic and the message when it is not a string.
std::string marker_text(const rosbag::MessageInstance& m, const std::string& bag,
                        const std::string& at) {
  const Serialized s = serialized(m);
  if (s.type != kStringType || s.md5 != kStringMd5)
    throw InputError(
        bag, 0,
        fmt::format("{}: a {} (MD5 {}), not the {} this reads", at, s.type, s.md5, kStringType));
  try {
    return decode_string(s.bytes);
  } catch (const InputError& e) {
    throw InputError(bag, 0, fmt::format("{}: {}", at, e.problem()));
  }
}

// One series topic as it is read: its reader and the samples of the performance under way.
struct TopicState {
  SeriesTopicReader reader;
  signal::Series open;  // samples since the performance's start
};

// The tree being written: its manifest and how many performances each (object, action) has.
class TreeWriter {
 public:
  explicit TreeWriter(const fs::path& root) : root_(root) {
    std::error_code ec;
    fs::create_directories(root_, ec);
    if (ec) throw InputError(root_.string(), 0, "cannot create the folder: " + ec.message());
    manifest_.open(root_ / "manifest.csv", std::ios::trunc);
    manifest_ << "file,object,action,session\n" << std::flush;
    if (!manifest_) throw InputError((root_ / "manifest.csv").string(), 0, "cannot write it");
  }

  void write(const PerformanceMarker& m, const std::vector<TopicState>& topics) {
    const fs::path folder = root_ / m.object / m.action;
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) throw InputError(folder.string(), 0, "cannot create the folder: " + ec.message());
    const int index = counts_[{m.object, m.action}]++;
    std::string listed;
    for (const TopicState& t : topics) {
      const std::string relative =
          fmt::format("{}/{}/{:03d}.{}.csv", m.object, m.action, index, t.reader.spec().modality);
      signal::write_series_csv((root_ / relative).string(), t.open);
      if (listed.empty()) listed = relative;
    }
    manifest_ << fmt::format("{},{},{},{}\n", listed, m.object, m.action, m.session) << std::flush;
  }

 private:
  fs::path root_;
  std::ofstream manifest_;
  std::map<std::pair<std::string, std::string>, int> counts_;
};

// Checks the options before any file is read.
void check_options(const BagImportOptions& o) {
  if (o.bags.empty()) throw InputError("", 0, "no bag files to import");
  if (o.series.empty())
    throw InputError("", 0, "no series topics: name at least one (MODALITY=TOPIC[:FIELD])");
  for (std::size_t i = 0; i < o.series.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (o.series[i].modality == o.series[j].modality)
        throw InputError("", 0, fmt::format("modality '{}' named twice", o.series[i].modality));
}

// Reads one bag into `tree`, performance by performance.
void import_bag(const std::string& bag_path, const BagImportOptions& options, TreeWriter& tree,
                BagImportSummary& summary, const BagProgress& progress) {
  rosbag::Bag bag;
  try {
    bag.open(bag_path, rosbag::bagmode::Read);
  } catch (const rosbag::BagException& e) {
    throw InputError(bag_path, 0, fmt::format("not a readable ROS 1 bag: {}", e.what()));
  }
  std::vector<TopicState> topics;
  std::vector<std::string> names{options.marker_topic};
  for (const SeriesTopic& s : options.series) {
    topics.push_back({SeriesTopicReader(s), {}});
    names.push_back(s.topic);
  }
  for (const std::string& topic : names) {
    rosbag::View one(bag, rosbag::TopicQuery(topic));
    if (one.size() == 0) {
      std::vector<std::string> present;
      for (const rosbag::ConnectionInfo* c : rosbag::View(bag).getConnections())
        present.push_back(c->topic);
      throw InputError(bag_path, 0,
                       fmt::format("no messages on topic {} (the bag has: {})", topic,
                                   fmt::join(present, ", ")));
    }
  }
  std::optional<PerformanceMarker> open;
  double start_time = 0;
  int markers = 0;
  rosbag::View view(bag, rosbag::TopicQuery(names));
  for (const rosbag::MessageInstance& m : view) {
    const double t = m.getTime().toSec();
    if (m.getTopic() == options.marker_topic) {
      ++markers;
      const std::string at = where(options.marker_topic, markers);
      const std::string text = marker_text(m, bag_path, at);
      const std::optional<PerformanceMarker> marker = parse_performance_marker(text);
      if (!marker)
        throw InputError(
            bag_path, 0,
            fmt::format("{}: '{}' is not 'start OBJECT ACTION SESSION' or 'end'", at, text));
      if (marker->start) {
        if (open)
          throw InputError(bag_path, 0,
                           fmt::format("{}: a start inside the performance begun before it", at));
        open = marker;
        start_time = t;
        for (TopicState& s : topics) s.open = {};
        continue;
      }
      if (!open) throw InputError(bag_path, 0, fmt::format("{}: an end with no start", at));
      for (const TopicState& s : topics)
        if (s.open.samples() < 2)
          throw InputError(bag_path, 0,
                           fmt::format("{}: the performance ({} {} session {}) has {} samples of "
                                       "topic {}, fewer than 2",
                                       at, open->object, open->action, open->session,
                                       s.open.samples(), s.reader.spec().topic));
      tree.write(*open, topics);
      ++summary.performances;
      if (progress) progress(bag_path, summary.performances);
      open.reset();
      continue;
    }
    for (TopicState& s : topics) {
      if (m.getTopic() != s.reader.spec().topic) continue;
      const std::string at = where(s.reader.spec().topic, s.reader.messages() + 1);
      const Serialized message = serialized(m);
      std::vector<double> values;
      try {
        values = s.reader.read(message.type, message.md5, message.bytes);
      } catch (const InputError& e) {
        throw InputError(bag_path, 0, fmt::format("{}: {}", at, e.problem()));
      }
      if (!open) continue;
      if (s.open.channels.empty()) {
        s.open.channels = s.reader.channels();
        s.open.values.resize(s.open.channels.size());
      }
      s.open.t.push_back(t - start_time);
      for (std::size_t c = 0; c < values.size(); ++c) s.open.values[c].push_back(values[c]);
    }
  }
  if (open) ++summary.unfinished;
}

}  // namespace

BagImportSummary import_bags(const BagImportOptions& options, const BagProgress& progress) {
  check_options(options);
  TreeWriter tree(options.output_dir);
  BagImportSummary summary;
  for (const std::string& bag : options.bags) {
    try {
      import_bag(bag, options, tree, summary, progress);
    } catch (const rosbag::BagException& e) {
      throw InputError(bag, 0, fmt::format("cannot read the bag: {}", e.what()));
    }
  }
  return summary;
}

}  // namespace echoplan::robot
