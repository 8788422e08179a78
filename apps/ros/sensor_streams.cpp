#include "sensor_streams.h"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

#include "common/error.h"

namespace echoplan::ros_app {

namespace {

std::vector<std::string> topic_names(const std::vector<robot::SeriesTopic>& topics) {
  std::vector<std::string> names;
  for (const robot::SeriesTopic& t : topics) names.push_back(t.topic);
  return names;
}

}  // namespace

std::optional<std::vector<std::string>> words_param(ros::NodeHandle& priv, const char* name) {
  XmlRpc::XmlRpcValue value;
  if (!priv.getParam(name, value)) return std::nullopt;
  std::vector<std::string> words;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeString) {
    std::string text = static_cast<const std::string&>(value);
    std::replace(text.begin(), text.end(), ',', ' ');
    std::istringstream in(text);
    for (std::string w; in >> w;) words.push_back(w);
    return words;
  }
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray)
    throw InputError(fmt::format("~{}", name), 0,
                     "expected a list, or one text with its entries separated by commas");
  for (int i = 0; i < value.size(); ++i) {
    if (value[i].getType() != XmlRpc::XmlRpcValue::TypeString)
      throw InputError(fmt::format("~{}", name), 0, fmt::format("entry {} is not a text", i + 1));
    words.push_back(value[i]);
  }
  return words;
}

std::vector<robot::SeriesTopic> series_param(ros::NodeHandle& priv) {
  std::vector<robot::SeriesTopic> topics;
  for (const std::string& entry :
       words_param(priv, "series").value_or(std::vector<std::string>{})) {
    try {
      topics.push_back(robot::parse_series_topic(entry));
    } catch (const InputError& e) {
      throw InputError("~series", 0, e.problem());
    }
    for (std::size_t j = 0; j + 1 < topics.size(); ++j)
      if (topics[j].modality == topics.back().modality)
        throw InputError("~series", 0,
                         fmt::format("modality '{}' named twice", topics.back().modality));
  }
  return topics;
}

std::chrono::milliseconds seconds_param(ros::NodeHandle& priv, const char* name, double fallback) {
  double value = fallback;
  priv.param(name, value, fallback);
  if (!(value > 0))
    throw InputError(fmt::format("~{}", name), 0,
                     fmt::format("must be > 0 seconds, got {}", value));
  return std::chrono::duration_cast<std::chrono::milliseconds>(
      std::chrono::duration<double>(value));
}

SensorStreams::SensorStreams(ros::NodeHandle& node, std::vector<robot::SeriesTopic> topics,
                             const std::string& marker_topic)
    : topics_(std::move(topics)),
      marker_topic_(marker_topic),
      streams_(topic_names(topics_), marker_topic) {
  for (const robot::SeriesTopic& t : topics_) readers_.emplace_back(t);
  ros::SubscribeOptions markers;
  markers.initByFullCallbackType<const ros::MessageEvent<const robot::StringMessage>&>(
      marker_topic_, 64,
      [this](const ros::MessageEvent<const robot::StringMessage>& e) { on_marker(e); });
  markers.callback_queue = &queue_;
  markers.transport_hints = ros::TransportHints().tcpNoDelay();
  subs_.push_back(node.subscribe(markers));
  for (std::size_t i = 0; i < topics_.size(); ++i) {
    ros::SubscribeOptions o;
    // A joint state publisher at 1 kHz during a 2 s wait: the queue keeps every message.
    o.initByFullCallbackType<const ros::MessageEvent<const robot::RawMessage>&>(
        topics_[i].topic, 10000,
        [this, i](const ros::MessageEvent<const robot::RawMessage>& e) { on_message(i, e); });
    o.callback_queue = &queue_;
    o.transport_hints = ros::TransportHints().tcpNoDelay();
    subs_.push_back(node.subscribe(o));
    ROS_INFO("'%s' is read from %s, cut by the markers on %s", topics_[i].modality.c_str(),
             topics_[i].topic.c_str(), marker_topic_.c_str());
  }
  spinner_.emplace(1, &queue_);
  spinner_->start();
}

void SensorStreams::on_marker(const ros::MessageEvent<const robot::StringMessage>& event) {
  const double time = event.getReceiptTime().toSec();
  const std::string& text = event.getMessage()->data;
  const auto marker = robot::parse_performance_marker(text);
  std::string said;
  if (!marker)
    said = fmt::format("'{}' is not 'start OBJECT ACTION SESSION' or 'end'; ignored", text);
  else
    said = marker->start ? streams_.begin(marker->action, time) : streams_.end(time);
  if (!said.empty()) ROS_WARN("%s: %s", marker_topic_.c_str(), said.c_str());
}

void SensorStreams::on_message(std::size_t stream,
                               const ros::MessageEvent<const robot::RawMessage>& event) {
  const double time = event.getReceiptTime().toSec();
  robot::SeriesTopicReader& reader = readers_[stream];
  const ros::M_string& header = event.getConnectionHeader();
  const auto field = [&](const char* name) {
    const auto it = header.find(name);
    return it == header.end() ? std::string() : it->second;
  };
  try {
    const std::vector<double> values =
        reader.read(field("type"), field("md5sum"), event.getMessage()->bytes);
    streams_.add(stream, time, reader.channels(), values);
  } catch (const InputError& error) {
    const std::string problem = fmt::format("message {}: {}", reader.messages(), error.problem());
    ROS_WARN_THROTTLE(5, "%s: %s", topics_[stream].topic.c_str(), problem.c_str());
    streams_.bad_message(stream, time, problem);
  }
}

}  // namespace echoplan::ros_app
