// echoplan_sim_robot: the reference arm driver. Serves ExecuteAction and BeginTrial with the
// simulator (robot::SimulatedWorld: MuJoCo + modal sound synthesis) and publishes what the world
// sounded like during each sensing action on /echoplan/sim_clip, where echoplan_listener (with
// ~source simulation) hears it. With it the whole loop runs over ROS without hardware.
//
// The clip is published before ExecuteAction answers, so it is on its way to the listener before
// the planner lowers the record parameter.
//
// Private parameters:
//   ~catalogue        object catalogue YAML (default: the shipped objects/catalogue.yaml)
//   ~sim_config       simulator configuration YAML (default: built-in)
//   ~min_duration_s   answer no sooner than this after a request (0): a real arm takes seconds,
//                     and a microphone that reads faster than real time (the tests' file-backed
//                     device) needs the time to fill its recording
//   ~sorting_actions  the sorting actions it accepts, comma-separated (default:
//   "move_to_A,move_to_B")
#include <fmt/format.h>
#include <ros/ros.h>

#include <chrono>
#include <optional>
#include <sstream>

#include "common/error.h"
#include "node_main.h"
#include "robot/ros/clip_message.h"
#include "robot/ros/master_watch.h"
#include "robot/ros/ros_messages.h"
#include "robot/ros/ros_protocol.h"
#include "robot/simulated_world.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace {

namespace names = echoplan::robot::ros_names;
using echoplan::robot::ActionStatus;

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

class SimRobotNode {
 public:
  SimRobotNode(ros::NodeHandle& node, echoplan::robot::SimulatedWorld& world, double min_duration_s)
      : world_(world), min_duration_s_(min_duration_s) {
    clips_ = node.advertise<echoplan_ros::Clip>(names::kSimClipTopic, 8);
    // BeginTrial first: a planner that finds ExecuteAction takes a missing BeginTrial for an arm
    // reset by hand.
    begin_ = node.advertiseService(names::kBeginTrialService, &SimRobotNode::begin_trial, this);
    execute_ = node.advertiseService(names::kExecuteActionService, &SimRobotNode::execute, this);
    watch_.emplace(std::vector<std::string>{begin_.getService(), execute_.getService()});
  }

 private:
  bool begin_trial(echoplan_ros::BeginTrial::Request& request,
                   echoplan_ros::BeginTrial::Response& response) {
    try {
      world_.check_object(request.object);
      echoplan::robot::TrialContext context;
      context.trial = request.trial;
      context.object = request.object;
      context.seed = request.seed;
      world_.begin_trial(context);
      in_trial_ = true;
      response.ok = true;
      ROS_INFO("trial %d: %s (seed %llu)", request.trial, request.object.c_str(),
               static_cast<unsigned long long>(request.seed));
    } catch (const std::exception& e) {
      response.ok = false;
      response.reason = e.what();
      ROS_ERROR("cannot begin trial %d: %s", request.trial, e.what());
    }
    return true;
  }

  // Sensing actions are heard (as the in-process loop's microphone hears them); sorting actions are
  // silent and reported done.
  bool execute(echoplan_ros::ExecuteAction::Request& request,
               echoplan_ros::ExecuteAction::Response& response) {
    using Response = echoplan_ros::ExecuteAction::Response;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      if (!in_trial_)
        throw std::logic_error("no trial begun (call " + std::string(names::kBeginTrialService) +
                               ")");
      world_.check_action(request.action);
    } catch (const std::exception& e) {
      response.status = Response::FAILED;
      response.reason = fmt::format("unknown action '{}': {}", request.action, e.what());
      if (!in_trial_) response.reason = e.what();
      ROS_ERROR("%s", response.reason.c_str());
      return true;
    }
    const auto sensing = echoplan::robot::SimulatedWorld::sensing_actions();
    const bool heard = std::find(sensing.begin(), sensing.end(), request.action) != sensing.end();
    try {
      if (heard) world_.start_listening();
      const echoplan::robot::ActionReport report = world_.execute(request.action);
      if (heard) {
        echoplan_ros::Clip clip;
        clip.sequence = ++sequence_;
        clip.action = request.action;
        echoplan::robot::fill_message(world_.stop_listening(), clip);
        // A listener started with this node may not be connected yet at the first clip, which would
        // be lost: give the connection a moment, once (with a microphone listener nobody
        // subscribes).
        if (!waited_for_listener_) {
          for (int i = 0; i < 500 && clips_.getNumSubscribers() == 0; ++i)
            ros::WallDuration(0.01).sleep();
          waited_for_listener_ = true;
        }
        clips_.publish(clip);
      }
      response.status = report.status == ActionStatus::done        ? Response::DONE
                        : report.status == ActionStatus::collision ? Response::COLLISION
                                                                   : Response::FAILED;
      response.reason = report.reason;
      response.duration_s = report.duration_s;
      response.retry_safe = report.retry_safe;
    } catch (const std::exception& e) {
      response.status = Response::FAILED;
      response.reason = e.what();
      ROS_ERROR("'%s' failed: %s", request.action.c_str(), e.what());
    }
    const double elapsed_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (elapsed_s < min_duration_s_) ros::WallDuration(min_duration_s_ - elapsed_s).sleep();
    ROS_INFO(
        "%s: %s%s%s (%.1f ms)", request.action.c_str(),
        echoplan::robot::to_string(response.status == Response::DONE ? ActionStatus::done
                                   : response.status == Response::COLLISION
                                       ? ActionStatus::collision
                                       : ActionStatus::failed),
        response.reason.empty() ? "" : ": ", response.reason.c_str(),
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    return true;
  }

  echoplan::robot::SimulatedWorld& world_;
  double min_duration_s_;
  ros::Publisher clips_;
  ros::ServiceServer execute_;
  ros::ServiceServer begin_;
  std::optional<echoplan::robot::MasterWatch> watch_;  // after the servers it registers again
  std::uint32_t sequence_ = 0;
  bool in_trial_ = false;
  bool waited_for_listener_ = false;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "echoplan_sim_robot");
  ros::NodeHandle node;
  ros::NodeHandle priv("~");
  return echoplan::ros_app::run_node([&] {
    std::string catalogue_path, config_path, sorting;
    priv.param<std::string>("catalogue", catalogue_path, "");
    priv.param<std::string>("sim_config", config_path, "");
    priv.param<std::string>("sorting_actions", sorting, "move_to_A,move_to_B");
    echoplan::sim::Catalogue catalogue = echoplan::sim::load_catalogue(
        catalogue_path.empty() ? echoplan::sim::default_catalogue_path() : catalogue_path);
    echoplan::sim::SimConfig config;
    if (!config_path.empty()) config = echoplan::sim::load_sim_config(config_path);
    echoplan::robot::SimulatedWorld world(std::move(catalogue), std::move(config),
                                          split_commas(sorting));
    double min_duration_s = 0;
    priv.param("min_duration_s", min_duration_s, 0.0);
    SimRobotNode server(node, world, min_duration_s);
    ROS_INFO("simulated robot ready: %s, %s", names::kExecuteActionService,
             names::kBeginTrialService);
    // One thread: MuJoCo's data is not shared, and actions run one at a time like on an arm.
    ros::spin();
    return 0;
  });
}
