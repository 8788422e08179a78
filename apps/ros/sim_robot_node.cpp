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
//   ~sensors          true: also publish the arm's sensors during each sensing action, as a real
//                     arm's driver does: its joint torques as sensor_msgs/JointState efforts
//                     (joints j1..j7) on ~joint_states_topic (/joint_states) and its wrist force as
//                     geometry_msgs/WrenchStamped on ~wrench_topic (/wrist/wrench), one message per
//                     reading (sim/arm_sensors.h, with their noise), before ExecuteAction answers;
//                     what echoplan_observation computes a model's effort and force from (~series).
//                     Default false
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
#include "robot/ros/sensor_messages.h"
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

// Where the arm's sensors are published, when they are.
struct SensorTopics {
  std::string joint_states = "/joint_states";
  std::string wrench = "/wrist/wrench";
};

// The arm's readings of one action as a driver publishes them: every reading in time order, the
// joint states and the wrenches interleaved.
class SensorPublisher {
 public:
  SensorPublisher(ros::NodeHandle& node, const SensorTopics& topics)
      : joints_(node.advertise<echoplan::robot::JointStateOut>(topics.joint_states, 10000)),
        wrenches_(node.advertise<echoplan::robot::WrenchStampedOut>(topics.wrench, 10000)) {}

  void publish(const echoplan::sim::ArmReadings& readings) {
    // Subscribers that connect after a message was published never get it: the first action waits
    // for them a moment, once.
    if (!waited_) {
      for (int i = 0;
           i < 500 && (joints_.getNumSubscribers() == 0 || wrenches_.getNumSubscribers() == 0); ++i)
        ros::WallDuration(0.01).sleep();
      waited_ = true;
    }
    const echoplan::signal::Series& effort = readings.effort;
    const echoplan::signal::Series& force = readings.force;
    std::size_t e = 0, f = 0;
    while (e < effort.samples() || f < force.samples()) {
      if (e < effort.samples() && (f >= force.samples() || effort.t[e] <= force.t[f]))
        joints_.publish(joint_state(effort, e++));
      else
        wrenches_.publish(wrench(force, f++));
    }
    // Out on their connections before the answer lets the planner mark the performance's end: ROS
    // cannot flush a publisher, so the node waits. 20 ms was too little for a few hundred messages
    // on a loaded machine (the ASan build's ros_torque heard a strike's wrench after its end
    // marker); a real driver's messages flow all through an action that lasts seconds.
    ros::WallDuration(0.25).sleep();
  }

 private:
  echoplan::robot::JointStateOut joint_state(const echoplan::signal::Series& s, std::size_t i) {
    echoplan::robot::JointStateOut m;
    m.header.seq = ++seq_;
    m.header.stamp = ros::Time::now();
    m.name = s.channels;
    for (const auto& channel : s.values) m.effort.push_back(channel[i]);
    return m;
  }
  echoplan::robot::WrenchStampedOut wrench(const echoplan::signal::Series& s, std::size_t i) {
    echoplan::robot::WrenchStampedOut m;
    m.header.seq = ++seq_;
    m.header.stamp = ros::Time::now();
    for (int a = 0; a < 3; ++a) m.force[a] = s.values[static_cast<std::size_t>(a)][i];
    return m;
  }

  ros::Publisher joints_, wrenches_;
  std::uint32_t seq_ = 0;
  bool waited_ = false;
};

class SimRobotNode {
 public:
  SimRobotNode(ros::NodeHandle& node, echoplan::robot::SimulatedWorld& world, double min_duration_s,
               const std::optional<SensorTopics>& sensors)
      : world_(world), min_duration_s_(min_duration_s) {
    if (sensors) sensors_.emplace(node, *sensors);
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
        if (sensors_ && world_.last_outcome()) sensors_->publish(world_.last_outcome()->readings);
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
  std::optional<SensorPublisher> sensors_;
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
    bool sensors = false;
    priv.param("sensors", sensors, false);
    std::optional<SensorTopics> topics;
    if (sensors) {
      topics.emplace();
      priv.param<std::string>("joint_states_topic", topics->joint_states, topics->joint_states);
      priv.param<std::string>("wrench_topic", topics->wrench, topics->wrench);
    }
    SimRobotNode server(node, world, min_duration_s, topics);
    ROS_INFO("simulated robot ready: %s, %s", names::kExecuteActionService,
             names::kBeginTrialService);
    // One thread: MuJoCo's data is not shared, and actions run one at a time like on an arm.
    ros::spin();
    return 0;
  });
}
