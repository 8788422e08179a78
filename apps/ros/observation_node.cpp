// echoplan_observation: the original system's observation service node. Serves Observe: the action
// performed and what was sensed of it in; the trained model's class, per-class probabilities and
// unknown flag out (robot::ClassifierService over the model file).
//
// What is sensed of a performance depends on the model's modalities for the action:
//   - computed from clips (audio): the request's clip, its samples or a WAV file the node can read;
//   - given by another sensor (a model trained on a feature set's haptic.csv: no clip extractor):
//     rows the robot publishes on /echoplan/features (echoplan_ros/FeatureRow: behaviour,
//     modality, values), one message per sensor of each performance. A request for action A takes,
//     per such modality of A, the one row of (A, modality) that arrived since the previous request
//     was answered, waiting up to ~feature_wait_s for rows not there yet
//     (robot/performance_rows.h says why that window is the performance's, and what is an error).
//     A request needs no clip unless A also has a clip modality.
//   - computed from a sensor's stream (a model trained on a recordings tree's series, whose
//     modality keeps its series features), when ~series names the stream's topic: the node
//     subscribes to each such topic (sensor_msgs/JointState, geometry_msgs/WrenchStamped; read as
//     robot/ros/series_topic.h says) and to the markers the planner publishes around each sensing
//     action (/echoplan/performance), cuts each stream between a performance's start and end
//     (robot/performance_streams.h) and computes the modality's features from that series, as
//     training and replay computed them from the recorded one.
// An action whose modalities are all computed from clips is served exactly as before the feature
// topic existed; the node subscribes to the feature topic only when the model has sensor
// modalities read as rows, and to streams only when ~series names them.
//
// Private parameters:
//   ~model           the trained observation model (`echoplan train --out`), required
//   ~feature_wait_s  how long a request waits for a performance's sensor rows (2)
//   ~series          MODALITY=TOPIC[:FIELD] entries (as `echoplan import-bag --topic`): the
//                    modalities computed from streams; a list (launch files) or one text with
//                    commas, e.g. _series:=effort=/joint_states,force=/wrist/wrench:force
//                    (default: none)
//   ~marker_topic    where the performance markers come from (/echoplan/performance)
//   ~series_wait_s   how long a request waits for its performance's end marker (2)
//
// A request the model cannot serve (no classifier for the action, an unreadable or too short clip)
// gets an answer with `error` set, so the caller learns why; the node keeps serving. A performance
// that could not be sensed (a sensor row that did not come in time, a stream that stopped, a joint
// missing from a message, too few samples) is answered with `error` and `transient` set: the
// planner skips that observation and re-plans.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "audio/io.h"
#include "common/error.h"
#include "node_main.h"
#include "perception/observation_model.h"
#include "robot/classifier_service.h"
#include "robot/performance_rows.h"
#include "robot/performance_streams.h"
#include "robot/ros/clip_message.h"
#include "robot/ros/master_watch.h"
#include "robot/ros/raw_message.h"
#include "robot/ros/ros_messages.h"
#include "robot/ros/ros_protocol.h"
#include "robot/ros/series_topic.h"
#include "robot/ros/string_message.h"
#include "robot/transient_error.h"
#include "signal/series_features.h"

namespace {

namespace names = echoplan::robot::ros_names;
using echoplan::robot::HeardObservation;

using echoplan::robot::SeriesTopic;

// A modality computed from a stream: which stream it reads, and its features.
struct StreamedModality {
  std::string modality;
  std::size_t stream = 0;  // index into the ~series topics
  echoplan::signal::SeriesFeatures features;
};

// The robot's sensor streams and the planner's performance markers, cut into performances on a
// queue and thread of their own (so that a request waiting for its end marker does not block
// them), in the order they arrived.
class SensorStreams {
 public:
  SensorStreams(ros::NodeHandle& node, const echoplan::perception::ObservationModel& model,
                std::vector<SeriesTopic> topics, const std::string& marker_topic, double wait_s)
      : marker_topic_(marker_topic),
        wait_(std::chrono::duration_cast<std::chrono::milliseconds>(
            std::chrono::duration<double>(wait_s))),
        streams_(topic_names(topics), marker_topic) {
    for (SeriesTopic& t : topics) readers_.emplace_back(std::move(t));
    match_model(model);
    subscribe(node);
  }

  // Whether `modality` of `action` is computed from a stream.
  bool streamed(const std::string& action, const std::string& modality) const {
    const auto it = by_action_.find(action);
    return it != by_action_.end() &&
           std::any_of(it->second.begin(), it->second.end(),
                       [&](const StreamedModality& m) { return m.modality == modality; });
  }

  // The rows of `action`'s streamed modalities, by modality, from the performance that ended last.
  // TransientError when that performance could not be sensed (robot/performance_streams.h).
  std::map<std::string, std::vector<double>> rows(const std::string& action) {
    std::map<std::string, std::vector<double>> out;
    const auto it = by_action_.find(action);
    if (it == by_action_.end()) return out;
    std::vector<std::size_t> wanted;
    for (const StreamedModality& m : it->second) wanted.push_back(m.stream);
    try {
      const std::vector<echoplan::signal::Series> series = streams_.take(action, wanted, wait_);
      for (std::size_t k = 0; k < series.size(); ++k) {
        const StreamedModality& m = it->second[k];
        out[m.modality] = m.features.extract(series[k], readers_[m.stream].spec().topic);
      }
    } catch (const echoplan::InputError& e) {
      throw echoplan::robot::TransientError(e.what());
    }
    return out;
  }

 private:
  static std::vector<std::string> topic_names(const std::vector<SeriesTopic>& topics) {
    std::vector<std::string> names;
    for (const SeriesTopic& t : topics) names.push_back(t.topic);
    return names;
  }

  // Which action reads which stream, checked against the model: every ~series modality must be
  // one the model computes from a series, and each name it once.
  void match_model(const echoplan::perception::ObservationModel& model) {
    std::vector<bool> used(readers_.size(), false);
    for (std::size_t i = 0; i < readers_.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (readers_[i].spec().modality == readers_[j].spec().modality)
          throw echoplan::InputError(
              "~series", 0, fmt::format("modality '{}' named twice", readers_[i].spec().modality));
    for (const std::string& action : model.actions())
      for (const echoplan::perception::ModalityModel& m : model.modalities(action))
        for (std::size_t i = 0; i < readers_.size(); ++i) {
          if (readers_[i].spec().modality != m.name) continue;
          if (m.series.empty())
            throw echoplan::InputError(
                "~series", 0,
                fmt::format("the model does not compute '{}' of '{}' from a series (it was "
                            "trained on {}): leave it out of ~series",
                            m.name, action,
                            m.classifier->extractor() ? "clips" : "rows given by the robot"));
          by_action_[action].push_back(
              {m.name, i, echoplan::signal::parse_series_features(m.series)});
          used[i] = true;
        }
    for (std::size_t i = 0; i < readers_.size(); ++i)
      if (!used[i])
        throw echoplan::InputError(
            "~series", 0,
            fmt::format("no action of the model reads a '{}' series", readers_[i].spec().modality));
  }

  void subscribe(ros::NodeHandle& node) {
    ros::SubscribeOptions markers;
    markers.initByFullCallbackType<const ros::MessageEvent<const echoplan::robot::StringMessage>&>(
        marker_topic_, 64,
        [this](const ros::MessageEvent<const echoplan::robot::StringMessage>& e) { on_marker(e); });
    markers.callback_queue = &queue_;
    markers.transport_hints = ros::TransportHints().tcpNoDelay();
    subs_.push_back(node.subscribe(markers));
    for (std::size_t i = 0; i < readers_.size(); ++i) {
      ros::SubscribeOptions o;
      // A joint state publisher at 1 kHz during a 2 s wait: the queue keeps every message.
      o.initByFullCallbackType<const ros::MessageEvent<const echoplan::robot::RawMessage>&>(
          readers_[i].spec().topic, 10000,
          [this, i](const ros::MessageEvent<const echoplan::robot::RawMessage>& e) {
            on_message(i, e);
          });
      o.callback_queue = &queue_;
      o.transport_hints = ros::TransportHints().tcpNoDelay();
      subs_.push_back(node.subscribe(o));
      ROS_INFO("'%s' is computed from %s (%s)", readers_[i].spec().modality.c_str(),
               readers_[i].spec().topic.c_str(), marker_topic_.c_str());
    }
    spinner_.emplace(1, &queue_);
    spinner_->start();
  }

  void on_marker(const ros::MessageEvent<const echoplan::robot::StringMessage>& event) {
    const double time = event.getReceiptTime().toSec();
    const std::string& text = event.getMessage()->data;
    const auto marker = echoplan::robot::parse_performance_marker(text);
    std::string said;
    if (!marker)
      said = fmt::format("'{}' is not 'start OBJECT ACTION SESSION' or 'end'; ignored", text);
    else
      said = marker->start ? streams_.begin(marker->action, time) : streams_.end(time);
    if (!said.empty()) ROS_WARN("%s: %s", marker_topic_.c_str(), said.c_str());
  }

  void on_message(std::size_t stream,
                  const ros::MessageEvent<const echoplan::robot::RawMessage>& e) {
    const double time = e.getReceiptTime().toSec();
    echoplan::robot::SeriesTopicReader& reader = readers_[stream];
    const ros::M_string& header = e.getConnectionHeader();
    const auto field = [&](const char* name) {
      const auto it = header.find(name);
      return it == header.end() ? std::string() : it->second;
    };
    try {
      const std::vector<double> values =
          reader.read(field("type"), field("md5sum"), e.getMessage()->bytes);
      streams_.add(stream, time, reader.channels(), values);
    } catch (const echoplan::InputError& error) {
      const std::string problem = fmt::format("message {}: {}", reader.messages(), error.problem());
      ROS_WARN_THROTTLE(5, "%s: %s", reader.spec().topic.c_str(), problem.c_str());
      streams_.bad_message(stream, time, problem);
    }
  }

  std::vector<echoplan::robot::SeriesTopicReader> readers_;
  std::map<std::string, std::vector<StreamedModality>> by_action_;
  std::string marker_topic_;
  std::chrono::milliseconds wait_;
  echoplan::robot::PerformanceStreams streams_;
  ros::CallbackQueue queue_;
  std::vector<ros::Subscriber> subs_;
  std::optional<ros::AsyncSpinner> spinner_;
};

// What the node reads besides the model.
struct NodeSettings {
  double feature_wait_s = 2.0;
  std::vector<SeriesTopic> series;
  std::string marker_topic = names::kPerformanceTopic;
  double series_wait_s = 2.0;
};

class ObservationNode {
 public:
  ObservationNode(ros::NodeHandle& node,
                  std::shared_ptr<const echoplan::perception::ObservationModel> model,
                  const NodeSettings& settings)
      : service_(std::move(model)),
        feature_wait_(std::chrono::duration_cast<std::chrono::milliseconds>(
            std::chrono::duration<double>(settings.feature_wait_s))) {
    if (!settings.series.empty())
      streams_.emplace(node, service_.model(), settings.series, settings.marker_topic,
                       settings.series_wait_s);
    // The sensor modalities not computed from streams come as rows on the feature topic.
    std::map<std::string, std::vector<std::string>> sensors;
    for (const std::string& action : service_.model().actions())
      for (const std::string& m : service_.sensor_modalities(action))
        if (!streams_ || !streams_->streamed(action, m)) sensors[action].push_back(m);
    if (!sensors.empty()) {
      for (const auto& [action, modalities] : sensors)
        ROS_INFO("'%s' is observed from %s rows on %s", action.c_str(),
                 fmt::format("{}", fmt::join(modalities, ", ")).c_str(), names::kFeatureTopic);
      rows_.emplace(std::move(sensors), names::kFeatureTopic);
      // Rows must keep arriving while a request waits for them on the service's thread, so the
      // subscription has a queue and a thread of its own.
      ros::SubscribeOptions options = ros::SubscribeOptions::create<echoplan_ros::FeatureRow>(
          names::kFeatureTopic, 64,
          [this](const echoplan_ros::FeatureRow::ConstPtr& row) { on_row(row); }, ros::VoidPtr(),
          &feature_queue_);
      options.transport_hints = ros::TransportHints().tcpNoDelay();
      feature_sub_ = node.subscribe(options);
      feature_spinner_.emplace(1, &feature_queue_);
      feature_spinner_->start();
    }
    server_ = node.advertiseService(names::kObserveService, &ObservationNode::observe, this);
    watch_.emplace(std::vector<std::string>{server_.getService()});
  }

 private:
  bool observe(echoplan_ros::Observe::Request& request, echoplan_ros::Observe::Response& response) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      const HeardObservation heard = service_.sensor_modalities(request.action).empty()
                                         ? observe_clip(request)
                                         : observe_performance(request);
      response.label = heard.label;
      response.unknown = heard.unknown;
      response.probability = heard.probability;
      response.grade = heard.grade;
      response.level_grade = heard.level_grade;
      response.distance = heard.distance;
      for (const auto& [name, p] : heard.probabilities) {
        response.classes.push_back(name);
        response.probabilities.push_back(p);
      }
    } catch (const echoplan::robot::TransientError& e) {
      response.error = e.what();
      response.transient = true;
      ROS_WARN("observe '%s': %s", request.action.c_str(), e.what());
      return true;
    } catch (const std::exception& e) {
      response.error = e.what();
      ROS_ERROR("observe '%s': %s", request.action.c_str(), e.what());
      return true;
    }
    ROS_INFO(
        "%s: heard %s (p %.2f%s) in %.2f ms", request.action.c_str(), response.label.c_str(),
        response.probability, response.unknown ? ", unknown" : "",
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    return true;
  }

  static echoplan::audio::AudioClip request_clip(const echoplan_ros::Observe::Request& request) {
    return !request.samples.empty()
               ? echoplan::robot::clip_from_request(request, names::kObserveService)
           : !request.clip_path.empty()
               ? echoplan::audio::read_audio(request.clip_path)
               : throw echoplan::InputError(names::kObserveService, 0,
                                            "the request holds no samples and no clip_path");
  }

  // An action heard from its clip alone.
  HeardObservation observe_clip(const echoplan_ros::Observe::Request& request) {
    return service_.observe(request_clip(request), request.action);
  }

  // An action with sensor modalities: the rows of those computed from streams (the performance
  // that ended last), the others' from the feature topic, a clip only if the action also has a
  // modality computed from clips. A performance that could not be sensed is a TransientError.
  HeardObservation observe_performance(const echoplan_ros::Observe::Request& request) {
    const std::string& action = request.action;
    const std::vector<std::string> sensors = service_.sensor_modalities(action);
    std::map<std::string, std::vector<double>> streamed;
    if (streams_) streamed = streams_->rows(action);
    std::vector<std::vector<double>> given;
    if (streamed.size() < sensors.size()) given = take_rows(action);
    std::vector<std::vector<double>> rows;
    std::size_t next_given = 0;
    for (const std::string& m : sensors) {
      const auto it = streamed.find(m);
      rows.push_back(it != streamed.end() ? std::move(it->second)
                                          : std::move(given.at(next_given++)));
    }
    const bool needs_clip = service_.model().modalities(action).size() > sensors.size();
    std::optional<echoplan::audio::AudioClip> clip;
    if (needs_clip) clip = request_clip(request);
    return service_.observe_performance(action, rows, clip ? &*clip : nullptr);
  }

  // The rows of `action`'s modalities that come from the feature topic.
  std::vector<std::vector<double>> take_rows(const std::string& action) {
    try {
      echoplan::robot::PerformanceRows::Taken taken = rows_->take(action, feature_wait_);
      for (const std::string& name : taken.unused)
        ROS_WARN("%s: a %s row arrived between two observations and was not used (observing '%s')",
                 names::kFeatureTopic, name.c_str(), action.c_str());
      return std::move(taken.rows);
    } catch (const echoplan::InputError& e) {
      throw echoplan::robot::TransientError(e.what());
    }
  }

  void on_row(const echoplan_ros::FeatureRow::ConstPtr& message) {
    const std::string why = rows_->add({message->behaviour, message->modality, message->values});
    if (!why.empty()) ROS_WARN("%s: %s; ignored", names::kFeatureTopic, why.c_str());
  }

  echoplan::robot::ClassifierService service_;
  std::chrono::milliseconds feature_wait_;
  std::optional<SensorStreams> streams_;                  // when ~series names streams
  std::optional<echoplan::robot::PerformanceRows> rows_;  // when some sensor modality comes as rows
  ros::CallbackQueue feature_queue_;
  ros::Subscriber feature_sub_;
  std::optional<ros::AsyncSpinner> feature_spinner_;
  ros::ServiceServer server_;
  std::optional<echoplan::robot::MasterWatch> watch_;  // after the server it registers again
};

// A duration parameter: > 0 seconds.
double seconds_param(ros::NodeHandle& priv, const char* name, double fallback) {
  double value = fallback;
  priv.param(name, value, fallback);
  if (!(value > 0))
    throw echoplan::InputError(fmt::format("~{}", name), 0,
                               fmt::format("must be > 0 seconds, got {}", value));
  return value;
}

NodeSettings read_settings(ros::NodeHandle& priv) {
  NodeSettings s;
  s.feature_wait_s = seconds_param(priv, "feature_wait_s", 2.0);
  s.series_wait_s = seconds_param(priv, "series_wait_s", 2.0);
  priv.param<std::string>("marker_topic", s.marker_topic, names::kPerformanceTopic);
  // A list from a launch file's rosparam; on the command line (where roscpp reads no lists) one
  // text with the entries separated by commas or spaces.
  XmlRpc::XmlRpcValue series;
  if (!priv.getParam("series", series)) return s;
  std::vector<std::string> entries;
  if (series.getType() == XmlRpc::XmlRpcValue::TypeString) {
    std::string text = series;
    std::replace(text.begin(), text.end(), ',', ' ');
    std::istringstream words(text);
    for (std::string w; words >> w;) entries.push_back(w);
  } else if (series.getType() == XmlRpc::XmlRpcValue::TypeArray) {
    for (int i = 0; i < series.size(); ++i) {
      if (series[i].getType() != XmlRpc::XmlRpcValue::TypeString)
        throw echoplan::InputError(
            "~series", 0, fmt::format("entry {} is not a MODALITY=TOPIC[:FIELD] text", i + 1));
      entries.push_back(series[i]);
    }
  } else {
    throw echoplan::InputError(
        "~series", 0,
        "expected MODALITY=TOPIC[:FIELD] entries, a list or one text "
        "separated by commas (effort=/joint_states,force=/wrist/wrench:force)");
  }
  for (const std::string& entry : entries) {
    try {
      s.series.push_back(echoplan::robot::parse_series_topic(entry));
    } catch (const echoplan::InputError& e) {
      throw echoplan::InputError("~series", 0, e.problem());
    }
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "echoplan_observation");
  ros::NodeHandle node;
  ros::NodeHandle priv("~");
  return echoplan::ros_app::run_node([&] {
    std::string model_path;
    if (!priv.getParam("model", model_path) || model_path.empty())
      throw echoplan::InputError(
          "~model", 0, "the parameter is required: a model file from `echoplan train --out`");
    const NodeSettings settings = read_settings(priv);
    auto model = std::make_shared<const echoplan::perception::ObservationModel>(
        echoplan::perception::load_observation_model(model_path));
    ObservationNode server(node, model, settings);
    ROS_INFO("observation service %s ready (model %s)", names::kObserveService, model_path.c_str());
    ros::spin();  // one thread: the classifier service's analyser is reused from clip to clip
    return 0;
  });
}
