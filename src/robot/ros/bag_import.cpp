#include "robot/ros/bag_import.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "common/error.h"
#include "robot/ros/bag_messages.h"
#include "signal/series.h"

namespace echoplan::robot {

namespace {

namespace fs = std::filesystem;

constexpr const char* kJointState = "sensor_msgs/JointState";
constexpr const char* kWrench = "geometry_msgs/WrenchStamped";
constexpr const char* kString = "std_msgs/String";

// Where in a bag an error is: "topic T message N" (N from 1, counted per topic).
std::string where(const std::string& topic, int index) {
  return fmt::format("topic {} message {}", topic, index);
}

// A name that can be a folder of the tree.
bool plain_name(const std::string& name) {
  return !name.empty() && name[0] != '.' && name.find_first_of("/\\,\"") == std::string::npos;
}

// A message's serialized bytes, decoded by the type it must be (`md5`: the layout it must have).
// InputError naming the bag, the topic and the message when either is wrong.
template <typename Decode>
auto decoded(const rosbag::MessageInstance& m, const char* type, const char* md5,
             const std::string& bag, const std::string& at, Decode decode) {
  if (m.getDataType() != type || m.getMD5Sum() != md5)
    throw InputError(bag, 0,
                     fmt::format("{}: a {} (MD5 {}), not the {} this reads", at, m.getDataType(),
                                 m.getMD5Sum(), type));
  std::vector<std::uint8_t> bytes(m.size());
  ros::serialization::OStream stream(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  m.write(stream);
  try {
    return decode(std::span<const std::uint8_t>(bytes));
  } catch (const InputError& e) {
    throw InputError(bag, 0, fmt::format("{}: {}", at, e.problem()));
  }
}

// One series topic as it is read: its type and channels (from its first message), how many
// messages it has had, and the samples of the performance under way.
struct TopicState {
  SeriesTopic spec;
  std::string type;
  std::vector<std::string> joints;  // JointState: the first message's names
  int messages = 0;
  signal::Series open;  // samples since the performance's start
};

// The values one message gives, in channel order.
std::vector<double> joint_values(const JointStateMessage& js, TopicState& state,
                                 const std::string& bag, int index) {
  const std::vector<double>& field = state.spec.field == "position"   ? js.position
                                     : state.spec.field == "velocity" ? js.velocity
                                                                      : js.effort;
  if (field.size() < js.name.size())
    throw InputError(bag, 0,
                     fmt::format("{}: {} {} values for {} joints", where(state.spec.topic, index),
                                 field.size(), state.spec.field, js.name.size()));
  std::vector<double> values;
  for (const std::string& joint : state.joints) {
    const auto at = std::find(js.name.begin(), js.name.end(), joint);
    if (at == js.name.end())
      throw InputError(
          bag, 0,
          fmt::format("{}: no joint '{}' (the topic's first message had {})",
                      where(state.spec.topic, index), joint, fmt::join(state.joints, ", ")));
    values.push_back(field[static_cast<std::size_t>(at - js.name.begin())]);
  }
  return values;
}

std::vector<double> wrench_values(const WrenchMessage& w, const std::string& field) {
  const double* f = w.force;
  const double* t = w.torque;
  if (field == "force") return {f[0], f[1], f[2]};
  if (field == "torque") return {t[0], t[1], t[2]};
  return {f[0], f[1], f[2], t[0], t[1], t[2]};
}

std::vector<std::string> wrench_channels(const std::string& field) {
  std::vector<std::string> force{"force_x", "force_y", "force_z"};
  const std::vector<std::string> torque{"torque_x", "torque_y", "torque_z"};
  if (field == "force") return force;
  if (field == "torque") return torque;
  force.insert(force.end(), torque.begin(), torque.end());
  return force;
}

// The first message of a topic fixes its type, field and channels.
void first_message(const rosbag::MessageInstance& m, TopicState& state, const std::string& bag) {
  state.type = m.getDataType();
  std::string& field = state.spec.field;
  if (state.type == kJointState) {
    if (field.empty()) field = "effort";
    if (field != "effort" && field != "position" && field != "velocity")
      throw InputError(bag, 0,
                       fmt::format("topic {} is a {}: its field is effort, position or velocity, "
                                   "not '{}'",
                                   state.spec.topic, kJointState, field));
    state.joints =
        decoded(m, kJointState, kJointStateMd5, bag, where(state.spec.topic, 1), decode_joint_state)
            .name;
    if (state.joints.empty())
      throw InputError(
          bag, 0, fmt::format("{}: a joint state naming no joint", where(state.spec.topic, 1)));
    state.open.channels = state.joints;
  } else if (state.type == kWrench) {
    if (field.empty()) field = "force";
    if (field != "force" && field != "torque" && field != "wrench")
      throw InputError(bag, 0,
                       fmt::format("topic {} is a {}: its field is force, torque or wrench, not "
                                   "'{}'",
                                   state.spec.topic, kWrench, field));
    state.open.channels = wrench_channels(field);
  } else {
    throw InputError(bag, 0,
                     fmt::format("topic {} is a {}, not a {} or {}", state.spec.topic, state.type,
                                 kJointState, kWrench));
  }
  state.open.values.resize(state.open.channels.size());
}

// A marker's words, or nothing when it is not one.
struct Marker {
  bool start = false;
  std::string object, action, session;
};
std::optional<Marker> parse_marker(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  if (words.size() == 1 && words[0] == "end") return Marker{};
  if (words.size() == 4 && words[0] == "start" && plain_name(words[1]) && plain_name(words[2]) &&
      plain_name(words[3]))
    return Marker{true, words[1], words[2], words[3]};
  return std::nullopt;
}

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

  void write(const Marker& m, const std::vector<TopicState>& topics) {
    const fs::path folder = root_ / m.object / m.action;
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) throw InputError(folder.string(), 0, "cannot create the folder: " + ec.message());
    const int index = counts_[{m.object, m.action}]++;
    std::string listed;
    for (const TopicState& t : topics) {
      const std::string relative =
          fmt::format("{}/{}/{:03d}.{}.csv", m.object, m.action, index, t.spec.modality);
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
    topics.push_back({s, "", {}, 0, {}});
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
  std::optional<Marker> open;
  double start_time = 0;
  int markers = 0;
  rosbag::View view(bag, rosbag::TopicQuery(names));
  for (const rosbag::MessageInstance& m : view) {
    const double t = m.getTime().toSec();
    if (m.getTopic() == options.marker_topic) {
      ++markers;
      const std::string at = where(options.marker_topic, markers);
      const std::string text = decoded(m, kString, kStringMd5, bag_path, at, decode_string);
      const std::optional<Marker> marker = parse_marker(text);
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
        for (TopicState& s : topics) {
          s.open.t.clear();
          for (auto& v : s.open.values) v.clear();
        }
        continue;
      }
      if (!open) throw InputError(bag_path, 0, fmt::format("{}: an end with no start", at));
      for (const TopicState& s : topics)
        if (s.open.samples() < 2)
          throw InputError(bag_path, 0,
                           fmt::format("{}: the performance ({} {} session {}) has {} samples of "
                                       "topic {}, fewer than 2",
                                       at, open->object, open->action, open->session,
                                       s.open.samples(), s.spec.topic));
      tree.write(*open, topics);
      ++summary.performances;
      if (progress) progress(bag_path, summary.performances);
      open.reset();
      continue;
    }
    for (TopicState& s : topics) {
      if (m.getTopic() != s.spec.topic) continue;
      ++s.messages;
      if (s.messages == 1) first_message(m, s, bag_path);
      if (m.getDataType() != s.type)
        throw InputError(bag_path, 0,
                         fmt::format("{}: a {} on a topic of {}", where(s.spec.topic, s.messages),
                                     m.getDataType(), s.type));
      if (!open) continue;
      const std::string at = where(s.spec.topic, s.messages);
      const std::vector<double> values =
          s.type == kJointState
              ? joint_values(
                    decoded(m, kJointState, kJointStateMd5, bag_path, at, decode_joint_state), s,
                    bag_path, s.messages)
              : wrench_values(
                    decoded(m, kWrench, kWrenchStampedMd5, bag_path, at, decode_wrench_stamped),
                    s.spec.field);
      s.open.t.push_back(t - start_time);
      for (std::size_t c = 0; c < values.size(); ++c) s.open.values[c].push_back(values[c]);
    }
  }
  if (open) ++summary.unfinished;
}

}  // namespace

SeriesTopic parse_series_topic(const std::string& text) {
  const auto eq = text.find('=');
  auto bad = [&](const std::string& problem) {
    throw InputError("", 0,
                     fmt::format("'{}': {} (expected MODALITY=TOPIC[:FIELD], e.g. "
                                 "effort=/joint_states:effort)",
                                 text, problem));
  };
  if (eq == std::string::npos) bad("no '='");
  SeriesTopic s;
  s.modality = text.substr(0, eq);
  std::string rest = text.substr(eq + 1);
  if (const auto colon = rest.rfind(':'); colon != std::string::npos) {
    s.field = rest.substr(colon + 1);
    rest = rest.substr(0, colon);
  }
  s.topic = rest;
  if (!plain_name(s.modality) || s.modality.find('.') != std::string::npos)
    bad("the modality must be a plain name");
  if (s.modality == "audio") bad("audio is not read from bags");
  if (s.topic.empty()) bad("no topic");
  return s;
}

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
