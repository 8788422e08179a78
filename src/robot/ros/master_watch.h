// Riding through a restart of the ROS master, for every echoplan node.
//
// A rosmaster that is killed and started again (same URI) knows nothing: the registrations of the
// running nodes (their publishers, subscribers and services) died with the old one, while the
// nodes' TCP connections to each other are still up. Whatever is already connected keeps working,
// but every new lookup fails: a planner started later finds no service, a topic's new publisher is
// never announced to the old subscribers, `rosservice list` is empty.
//
// A MasterWatch asks the master for its pid once a second on a thread of its own. When the master
// was unreachable and is back, or answers with another pid, it registers the node's publishers,
// subscribers and the services it was given with the new master again. It registers them directly
// (the master's registerPublisher, registerSubscriber and registerService calls with the node's
// own URIs) rather than shutting them down and advertising them anew, because a shut down server
// drops its connections: a planner's call in flight on its persistent connection would fail, and a
// latched message would be lost. Registering changes nothing on the connections.
//
// What it cannot give back: the parameter server's contents (the planner sets its parameters at
// every recording, and again each second while no listener has answered, so they come back by
// themselves) and roscpp's cached-parameter subscriptions
// (ros::param::getCached then keeps the value it had: echoplan_listener's ~cached_param true does
// not survive a master restart).
#pragma once

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <atomic>
#include <optional>
#include <string>
#include <vector>

namespace echoplan::robot {

class MasterWatch {
 public:
  // `services`: the names (ros::ServiceServer::getService()) of the services this node serves,
  // which roscpp offers no way to list. Topics are found by themselves. Needs ros::init.
  explicit MasterWatch(std::vector<std::string> services = {});
  ~MasterWatch();
  MasterWatch(const MasterWatch&) = delete;
  MasterWatch& operator=(const MasterWatch&) = delete;

  // How many times the node registered again with a restarted master.
  int registrations_renewed() const { return renewed_; }

 private:
  void poll();
  bool register_again();

  std::vector<std::string> services_;
  std::optional<int> pid_;  // of the master the node is registered with
  bool lost_ = false;       // the master did not answer the last poll
  std::atomic<int> renewed_ = 0;
  // Its own queue and thread: a poll of a master that does not answer never delays the node's
  // callbacks, and a node busy in a long callback (an arm's action) still notices the restart.
  ros::CallbackQueue queue_;
  ros::WallTimer timer_;
  ros::AsyncSpinner spinner_;
};

// Waits up to `timeout_s` for the master to answer (a restart takes a second or two); false when it
// did not. For a client about to call the master, which must neither hang nor fail at once.
bool wait_for_master(double timeout_s);

// Sets parameter `key` (resolved in the node's namespace) on the master once: false when the master
// did not answer or refused. ros::param::set instead retries for ever, so a master that dies
// between a check and the call would hang the node.
bool set_param_once(const std::string& key, const XmlRpc::XmlRpcValue& value);

// " (the ROS master at URI does not answer)" when it does not, else "": for the messages of a
// call or a wait that failed, so that a user whose master died is told so rather than sent after
// the node.
std::string master_unreachable_note();

}  // namespace echoplan::robot
