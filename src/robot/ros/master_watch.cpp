#include "robot/ros/master_watch.h"

#include <fmt/format.h>
#include <ros/connection_manager.h>
#include <ros/master.h>
#include <ros/names.h>
#include <ros/network.h>
#include <ros/publication.h>
#include <ros/service_manager.h>
#include <ros/topic_manager.h>
#include <ros/xmlrpc_manager.h>

namespace echoplan::robot {
namespace {

// One call to the master that does not wait for it: false when it did not answer or refused.
bool call_master(const char* method, const std::vector<std::string>& args) {
  XmlRpc::XmlRpcValue request, response, payload;
  request.setSize(static_cast<int>(args.size()));
  for (std::size_t i = 0; i < args.size(); ++i) request[static_cast<int>(i)] = args[i];
  return ros::master::execute(method, request, response, payload, false);
}

std::optional<int> master_pid() {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  if (!ros::master::execute("getPid", request, response, payload, false) ||
      payload.getType() != XmlRpc::XmlRpcValue::TypeInt)
    return std::nullopt;
  return static_cast<int>(payload);
}

}  // namespace

bool set_param_once(const std::string& key, const XmlRpc::XmlRpcValue& value) {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  request[1] = ros::names::resolve(key);
  request[2] = value;
  return ros::master::execute("setParam", request, response, payload, false);
}

MasterWatch::MasterWatch(std::vector<std::string> services)
    : services_(std::move(services)), pid_(master_pid()), spinner_(1, &queue_) {
  ros::NodeHandle node;
  node.setCallbackQueue(&queue_);
  timer_ =
      node.createWallTimer(ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) { poll(); });
  spinner_.start();
}

MasterWatch::~MasterWatch() {
  spinner_.stop();
  timer_.stop();
}

void MasterWatch::poll() {
  const std::optional<int> pid = master_pid();
  if (!pid) {
    if (!lost_)
      ROS_WARN(
          "the ROS master at %s does not answer; this node registers with it again when it "
          "is back",
          ros::master::getURI().c_str());
    lost_ = true;
    return;
  }
  // Unreachable and back, or another process at the same URI: a master that forgot us. (A master
  // that was only slow to answer is told again what it knows, which changes nothing.)
  if (pid_ && (lost_ || *pid != *pid_)) {
    if (!register_again()) return;  // it went away again: the next poll tries again
    ++renewed_;
  }
  pid_ = pid;
  lost_ = false;
}

bool MasterWatch::register_again() {
  const std::string caller = ros::this_node::getName();
  const std::string api = ros::XMLRPCManager::instance()->getServerURI();
  std::size_t topics = 0, services = 0;
  ros::V_string names;
  ros::this_node::getAdvertisedTopics(names);
  for (const std::string& topic : names) {
    const ros::PublicationPtr publication = ros::TopicManager::instance()->lookupPublication(topic);
    if (!publication) continue;  // shut down meanwhile
    if (!call_master("registerPublisher", {caller, topic, publication->getDataType(), api}))
      return false;
    ++topics;
  }
  names.clear();
  ros::this_node::getSubscribedTopics(names);
  // roscpp does not tell a subscription's type; "*" is the master's "any type", which a publisher's
  // registration then replaces with the real one. The master answers with the topic's publishers,
  // which the node is connected to already: a publisher registering later is announced to it.
  for (const std::string& topic : names) {
    if (!call_master("registerSubscriber", {caller, topic, "*", api})) return false;
    ++topics;
  }
  const std::string service_api = fmt::format("rosrpc://{}:{}", ros::network::getHost(),
                                              ros::ConnectionManager::instance()->getTCPPort());
  for (const std::string& service : services_) {
    if (!ros::ServiceManager::instance()->lookupServicePublication(service)) continue;
    if (!call_master("registerService", {caller, service, service_api, api})) return false;
    ++services;
  }
  ROS_WARN(
      "the ROS master at %s restarted; registered %zu topic(s) and %zu service(s) with it again",
      ros::master::getURI().c_str(), topics, services);
  return true;
}

bool wait_for_master(double timeout_s) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
  while (!ros::master::check()) {
    if (ros::WallTime::now() >= deadline || !ros::ok()) return false;
    ros::WallDuration(0.1).sleep();
  }
  return true;
}

std::string master_unreachable_note() {
  return ros::master::check()
             ? ""
             : fmt::format(" (the ROS master at {} does not answer)", ros::master::getURI());
}

}  // namespace echoplan::robot
