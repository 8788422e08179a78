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
// An action whose modalities are all computed from clips is served exactly as before the feature
// topic existed; the node subscribes to it only when the model has sensor modalities.
//
// Private parameters:
//   ~model           the trained observation model (`echoplan train --out`), required
//   ~feature_wait_s  how long a request waits for a performance's sensor rows (2)
//
// A request the model cannot serve (no classifier for the action, an unreadable or too short clip,
// a sensor row that did not come in time) gets an answer with `error` set, so the caller learns
// why; the node keeps serving.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

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

namespace {

namespace names = echoplan::robot::ros_names;
using echoplan::robot::HeardObservation;

class ObservationNode {
 public:
  ObservationNode(ros::NodeHandle& node,
                  std::shared_ptr<const echoplan::perception::ObservationModel> model,
                  double feature_wait_s)
      : service_(std::move(model)),
        feature_wait_(std::chrono::duration_cast<std::chrono::milliseconds>(
            std::chrono::duration<double>(feature_wait_s))) {
    std::map<std::string, std::vector<std::string>> sensors;
    for (const std::string& action : service_.model().actions())
      if (auto m = service_.sensor_modalities(action); !m.empty()) sensors[action] = std::move(m);
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

  // An action with sensor modalities: their rows from the feature topic, a clip only if the
  // action also has a modality computed from clips.
  HeardObservation observe_performance(const echoplan_ros::Observe::Request& request) {
    const std::string& action = request.action;
    const echoplan::robot::PerformanceRows::Taken taken = rows_->take(action, feature_wait_);
    for (const std::string& name : taken.unused)
      ROS_WARN("%s: a %s row arrived between two observations and was not used (observing '%s')",
               names::kFeatureTopic, name.c_str(), action.c_str());
    const bool needs_clip =
        service_.model().modalities(action).size() > service_.sensor_modalities(action).size();
    std::optional<echoplan::audio::AudioClip> clip;
    if (needs_clip) clip = request_clip(request);
    return service_.observe_performance(action, taken.rows, clip ? &*clip : nullptr);
  }

  void on_row(const echoplan_ros::FeatureRow::ConstPtr& message) {
    const std::string why = rows_->add({message->behaviour, message->modality, message->values});
    if (!why.empty()) ROS_WARN("%s: %s; ignored", names::kFeatureTopic, why.c_str());
  }

  echoplan::robot::ClassifierService service_;
  std::chrono::milliseconds feature_wait_;
  std::optional<echoplan::robot::PerformanceRows> rows_;  // when the model has sensor modalities
  ros::CallbackQueue feature_queue_;
  ros::Subscriber feature_sub_;
  std::optional<ros::AsyncSpinner> feature_spinner_;
  ros::ServiceServer server_;
  std::optional<echoplan::robot::MasterWatch> watch_;  // after the server it registers again
};

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
    double feature_wait_s = 2.0;
    priv.param("feature_wait_s", feature_wait_s, 2.0);
    if (!(feature_wait_s > 0))
      throw echoplan::InputError("~feature_wait_s", 0,
                                 fmt::format("must be > 0 seconds, got {}", feature_wait_s));
    auto model = std::make_shared<const echoplan::perception::ObservationModel>(
        echoplan::perception::load_observation_model(model_path));
    ObservationNode server(node, model, feature_wait_s);
    ROS_INFO("observation service %s ready (model %s)", names::kObserveService, model_path.c_str());
    ros::spin();  // one thread: the classifier service's analyser is reused from clip to clip
    return 0;
  });
}
