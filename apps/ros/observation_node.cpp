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

#include "audio/io.h"
#include "common/error.h"
#include "node_main.h"
#include "perception/observation_model.h"
#include "robot/classifier_service.h"
#include "robot/performance_rows.h"
#include "robot/ros/clip_message.h"
#include "robot/ros/master_watch.h"
#include "robot/ros/ros_messages.h"
#include "robot/ros/ros_protocol.h"
#include "robot/ros/series_topic.h"
#include "robot/transient_error.h"
#include "sensor_streams.h"
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

// The model's modalities computed from the robot's sensor streams: which action reads which
// stream with which features (checked against the model), and each performance's rows.
class StreamedFeatures {
 public:
  StreamedFeatures(ros::NodeHandle& node, const echoplan::perception::ObservationModel& model,
                   std::vector<SeriesTopic> topics, const std::string& marker_topic,
                   std::chrono::milliseconds wait)
      : wait_(wait) {
    match_model(model, topics);
    streams_.emplace(node, std::move(topics), marker_topic);
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
      const std::vector<echoplan::signal::Series> series = streams_->take(action, wanted, wait_);
      for (std::size_t k = 0; k < series.size(); ++k) {
        const StreamedModality& m = it->second[k];
        out[m.modality] = m.features.extract(series[k], streams_->topics()[m.stream].topic);
      }
    } catch (const echoplan::InputError& e) {
      throw echoplan::robot::TransientError(e.what());
    }
    return out;
  }

 private:
  // Which action reads which stream: every ~series modality must be one the model computes from a
  // series.
  void match_model(const echoplan::perception::ObservationModel& model,
                   const std::vector<SeriesTopic>& topics) {
    std::vector<bool> used(topics.size(), false);
    for (const std::string& action : model.actions())
      for (const echoplan::perception::ModalityModel& m : model.modalities(action))
        for (std::size_t i = 0; i < topics.size(); ++i) {
          if (topics[i].modality != m.name) continue;
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
    for (std::size_t i = 0; i < topics.size(); ++i)
      if (!used[i])
        throw echoplan::InputError(
            "~series", 0,
            fmt::format("no action of the model reads a '{}' series", topics[i].modality));
  }

  std::chrono::milliseconds wait_;
  std::map<std::string, std::vector<StreamedModality>> by_action_;
  std::optional<echoplan::ros_app::SensorStreams> streams_;
};

// What the node reads besides the model.
struct NodeSettings {
  std::chrono::milliseconds feature_wait{2000};
  std::vector<SeriesTopic> series;
  std::string marker_topic = names::kPerformanceTopic;
  std::chrono::milliseconds series_wait{2000};
};

class ObservationNode {
 public:
  ObservationNode(ros::NodeHandle& node,
                  std::shared_ptr<const echoplan::perception::ObservationModel> model,
                  const NodeSettings& settings)
      : service_(std::move(model)), feature_wait_(settings.feature_wait) {
    if (!settings.series.empty())
      streams_.emplace(node, service_.model(), settings.series, settings.marker_topic,
                       settings.series_wait);
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
  std::optional<StreamedFeatures> streams_;               // when ~series names streams
  std::optional<echoplan::robot::PerformanceRows> rows_;  // when some sensor modality comes as rows
  ros::CallbackQueue feature_queue_;
  ros::Subscriber feature_sub_;
  std::optional<ros::AsyncSpinner> feature_spinner_;
  ros::ServiceServer server_;
  std::optional<echoplan::robot::MasterWatch> watch_;  // after the server it registers again
};

NodeSettings read_settings(ros::NodeHandle& priv) {
  NodeSettings s;
  s.feature_wait = echoplan::ros_app::seconds_param(priv, "feature_wait_s", 2.0);
  s.series_wait = echoplan::ros_app::seconds_param(priv, "series_wait_s", 2.0);
  priv.param<std::string>("marker_topic", s.marker_topic, names::kPerformanceTopic);
  s.series = echoplan::ros_app::series_param(priv);
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
