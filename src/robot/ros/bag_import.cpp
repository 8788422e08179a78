#include "robot/ros/bag_import.h"

// First: its serializers for array fields must be declared before rosbag instantiates any message.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>

#include "audio/clip.h"
#include "audio/io.h"
#include "common/error.h"
#include "common/file_io.h"
#include "robot/ros/bag_messages.h"
#include "robot/ros/ros_messages.h"
#include "robot/ros/s16le_chunk.h"
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

// The audio topic as it is read: its format (from its info topic) and the samples of the
// performance under way.
struct AudioState {
  std::string topic;
  audio::AudioClip open;  // its rate and channels: the format; samples since the start
  int messages = 0;
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

  // Writes the performance's files (its WAV when `audio` has one) and lists it: by its WAV, or
  // without one by its first series.
  void write(const PerformanceMarker& m, const std::vector<TopicState>& topics,
             const std::optional<AudioState>& audio) {
    const fs::path folder = root_ / m.object / m.action;
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) throw InputError(folder.string(), 0, "cannot create the folder: " + ec.message());
    const int index = counts_[{m.object, m.action}]++;
    std::string listed;
    if (audio) {
      listed = fmt::format("{}/{}/{:03d}.wav", m.object, m.action, index);
      const fs::path partial = (root_ / listed).string() + ".part";
      audio::write_audio(partial.string(), audio->open);
      move_into_place(partial, root_ / listed);
    }
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
  if (o.series.empty() && o.audio_topic.empty())
    throw InputError("", 0,
                     "nothing to import: name at least one series topic (MODALITY=TOPIC[:FIELD]) "
                     "or an audio topic");
  for (std::size_t i = 0; i < o.series.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (o.series[i].modality == o.series[j].modality)
        throw InputError("", 0, fmt::format("modality '{}' named twice", o.series[i].modality));
}

// InputError naming the bag's topics unless `topic` has messages in it.
void require_topic(rosbag::Bag& bag, const std::string& bag_path, const std::string& topic,
                   const std::string& why = "") {
  if (rosbag::View(bag, rosbag::TopicQuery(topic)).size() > 0) return;
  std::vector<std::string> present;
  for (const rosbag::ConnectionInfo* c : rosbag::View(bag).getConnections())
    present.push_back(c->topic);
  throw InputError(bag_path, 0,
                   fmt::format("no messages on topic {}{} (the bag has: {})", topic, why,
                               fmt::join(present, ", ")));
}

// A message of type T, or InputError naming where it is and what it is instead.
template <typename T>
boost::shared_ptr<T> instance(const rosbag::MessageInstance& m, const std::string& bag,
                              const std::string& at) {
  boost::shared_ptr<T> message = m.instantiate<T>();
  if (!message)
    throw InputError(bag, 0,
                     fmt::format("{}: a {} (MD5 {}), not the {} this reads", at, m.getDataType(),
                                 m.getMD5Sum(), ros::message_traits::DataType<T>::value()));
  return message;
}

// The audio's format, from the first message on its info topic (audio_capture publishes it there,
// latched: record it with the audio). Only wave S16LE is read, as the listener reads it.
AudioState audio_format(rosbag::Bag& bag, const std::string& bag_path,
                        const BagImportOptions& options) {
  const std::string info_topic =
      options.audio_info_topic.empty() ? options.audio_topic + "_info" : options.audio_info_topic;
  require_topic(bag, bag_path, info_topic,
                fmt::format(", where the format of the audio on {} must be", options.audio_topic));
  rosbag::View info_view(bag, rosbag::TopicQuery(info_topic));
  const auto info =
      instance<audio_common_msgs::AudioInfo>(*info_view.begin(), bag_path, where(info_topic, 1));
  if (info->coding_format != "wave" || info->sample_format != "S16LE" || info->channels < 1 ||
      info->sample_rate < 1)
    throw InputError(bag_path, 0,
                     fmt::format("{}: the audio is {} {} at {} Hz x {}: only wave S16LE is read",
                                 where(info_topic, 1), info->coding_format, info->sample_format,
                                 info->sample_rate, info->channels));
  AudioState audio{options.audio_topic, {}, 0};
  audio.open.sample_rate = static_cast<int>(info->sample_rate);
  audio.open.channels = info->channels;
  return audio;
}

// One bag read front to back: each performance's series and audio between its markers.
class BagCutter {
 public:
  BagCutter(const std::string& bag_path, const BagImportOptions& options, TreeWriter& tree,
            BagImportSummary& summary, const BagProgress& progress)
      : bag_path_(bag_path),
        options_(options),
        tree_(tree),
        summary_(summary),
        progress_(progress) {
    try {
      bag_.open(bag_path, rosbag::bagmode::Read);
    } catch (const rosbag::BagException& e) {
      throw InputError(bag_path, 0, fmt::format("not a readable ROS 1 bag: {}", e.what()));
    }
    for (const SeriesTopic& s : options.series) topics_.push_back({SeriesTopicReader(s), {}});
    if (!options.audio_topic.empty()) audio_ = audio_format(bag_, bag_path, options);
  }

  void read() {
    std::vector<std::string> names{options_.marker_topic};
    for (const SeriesTopic& s : options_.series) names.push_back(s.topic);
    if (audio_) names.push_back(audio_->topic);
    for (const std::string& topic : names) require_topic(bag_, bag_path_, topic);
    for (const rosbag::MessageInstance& m : rosbag::View(bag_, rosbag::TopicQuery(names))) {
      if (m.getTopic() == options_.marker_topic) {
        on_marker(m);
        continue;
      }
      if (audio_ && m.getTopic() == audio_->topic) on_audio(m);
      for (TopicState& s : topics_)
        if (m.getTopic() == s.reader.spec().topic) on_series(m, s);
    }
    if (open_) ++summary_.unfinished;
  }

 private:
  void on_marker(const rosbag::MessageInstance& m) {
    const std::string at = where(options_.marker_topic, ++markers_);
    const std::string text = marker_text(m, bag_path_, at);
    const std::optional<PerformanceMarker> marker = parse_performance_marker(text);
    if (!marker)
      throw InputError(
          bag_path_, 0,
          fmt::format("{}: '{}' is not 'start OBJECT ACTION SESSION' or 'end'", at, text));
    if (!marker->start) return end(at);
    if (open_)
      throw InputError(bag_path_, 0,
                       fmt::format("{}: a start inside the performance begun before it", at));
    open_ = marker;
    start_time_ = m.getTime().toSec();
    for (TopicState& s : topics_) s.open = {};
    if (audio_) audio_->open.samples.clear();
  }

  void end(const std::string& at) {
    if (!open_) throw InputError(bag_path_, 0, fmt::format("{}: an end with no start", at));
    const std::string performance = fmt::format("the performance ({} {} session {})", open_->object,
                                                open_->action, open_->session);
    for (const TopicState& s : topics_)
      if (s.open.samples() < 2)
        throw InputError(bag_path_, 0,
                         fmt::format("{}: {} has {} samples of topic {}, fewer than 2", at,
                                     performance, s.open.samples(), s.reader.spec().topic));
    if (audio_ && audio_->open.samples.empty())
      throw InputError(
          bag_path_, 0,
          fmt::format("{}: {} has no audio on topic {}", at, performance, audio_->topic));
    tree_.write(*open_, topics_, audio_);
    ++summary_.performances;
    if (progress_) progress_(bag_path_, summary_.performances);
    open_.reset();
  }

  void on_series(const rosbag::MessageInstance& m, TopicState& s) {
    const std::string at = where(s.reader.spec().topic, s.reader.messages() + 1);
    const Serialized message = serialized(m);
    std::vector<double> values;
    try {
      values = s.reader.read(message.type, message.md5, message.bytes);
    } catch (const InputError& e) {
      throw InputError(bag_path_, 0, fmt::format("{}: {}", at, e.problem()));
    }
    if (!open_) return;
    if (s.open.channels.empty()) {
      s.open.channels = s.reader.channels();
      s.open.values.resize(s.open.channels.size());
    }
    s.open.t.push_back(m.getTime().toSec() - start_time_);
    for (std::size_t c = 0; c < values.size(); ++c) s.open.values[c].push_back(values[c]);
  }

  void on_audio(const rosbag::MessageInstance& m) {
    const std::string at = where(audio_->topic, ++audio_->messages);
    const auto chunk = instance<audio_common_msgs::AudioData>(m, bag_path_, at);
    if (!open_) return;
    const ChunkOutcome outcome =
        append_s16le_chunk(chunk->data, audio_->open.channels,
                           std::numeric_limits<std::size_t>::max(), audio_->open.samples);
    if (outcome.misaligned)
      throw InputError(bag_path_, 0,
                       fmt::format("{}: {} bytes, not a whole number of S16LE frames of {} "
                                   "channel(s)",
                                   at, chunk->data.size(), audio_->open.channels));
  }

  const std::string bag_path_;
  const BagImportOptions& options_;
  TreeWriter& tree_;
  BagImportSummary& summary_;
  const BagProgress& progress_;
  rosbag::Bag bag_;
  std::vector<TopicState> topics_;
  std::optional<AudioState> audio_;
  std::optional<PerformanceMarker> open_;
  double start_time_ = 0;
  int markers_ = 0;
};

}  // namespace

BagImportSummary import_bags(const BagImportOptions& options, const BagProgress& progress) {
  check_options(options);
  TreeWriter tree(options.output_dir);
  BagImportSummary summary;
  for (const std::string& bag : options.bags) {
    try {
      BagCutter(bag, options, tree, summary, progress).read();
    } catch (const rosbag::BagException& e) {
      throw InputError(bag, 0, fmt::format("cannot read the bag: {}", e.what()));
    }
  }
  return summary;
}

}  // namespace echoplan::robot
