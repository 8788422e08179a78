// echoplan_observation: the original system's observation service node. Serves Observe: a clip (its
// samples, or a WAV file the node can read) and the action it was recorded with in; the trained
// model's class, per-class probabilities and unknown flag out (robot::ClassifierService over the
// model file).
//
// Private parameters:
//   ~model   the trained observation model (`echoplan train --out`), required
//
// A request the model cannot serve (no classifier for the action, an unreadable or too short clip)
// gets an answer with `error` set, so the caller learns why; the node keeps serving.
#include <fmt/format.h>
#include <ros/ros.h>

#include <chrono>
#include <memory>

#include "audio/io.h"
#include "common/error.h"
#include "node_main.h"
#include "perception/observation_model.h"
#include "robot/classifier_service.h"
#include "robot/ros/clip_message.h"
#include "robot/ros/ros_messages.h"
#include "robot/ros/ros_protocol.h"

namespace {

namespace names = echoplan::robot::ros_names;

class ObservationNode {
 public:
  ObservationNode(ros::NodeHandle& node,
                  std::shared_ptr<const echoplan::perception::ObservationModel> model)
      : service_(std::move(model)) {
    server_ = node.advertiseService(names::kObserveService, &ObservationNode::observe, this);
  }

 private:
  bool observe(echoplan_ros::Observe::Request& request, echoplan_ros::Observe::Response& response) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      const echoplan::audio::AudioClip clip =
          !request.samples.empty()
              ? echoplan::robot::clip_from_request(request, names::kObserveService)
          : !request.clip_path.empty()
              ? echoplan::audio::read_audio(request.clip_path)
              : throw echoplan::InputError(names::kObserveService, 0,
                                           "the request holds no samples and no clip_path");
      const echoplan::robot::HeardObservation heard = service_.observe(clip, request.action);
      response.label = heard.label;
      response.unknown = heard.unknown;
      response.probability = heard.probability;
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

  echoplan::robot::ClassifierService service_;
  ros::ServiceServer server_;
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
    auto model = std::make_shared<const echoplan::perception::ObservationModel>(
        echoplan::perception::load_observation_model(model_path));
    ObservationNode server(node, model);
    ROS_INFO("observation service %s ready (model %s)", names::kObserveService, model_path.c_str());
    ros::spin();  // one thread: the classifier service's analyser is reused from clip to clip
    return 0;
  });
}
