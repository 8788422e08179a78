// echoplan_collector: a training set collected on a robot over ROS (loop/collection.h), the way
// `echoplan collect` collects one on the simulated robot: for every object and session a trial in
// which the arm performs each behaviour in turn, through the same services the planner calls
// (/echoplan/begin_trial, /echoplan/execute_action), while the listener records it (as for the
// planner: the record parameter around each behaviour) and the sensor streams named by ~series
// are cut between the performance markers the collector publishes (as the observation node cuts
// them). Written as a recordings tree DIR/<object>/<behaviour>/sNNN.wav and sNNN.<modality>.csv
// with DIR/manifest.csv, which `echoplan train` reads.
//
// Private parameters:
//   ~objects        the objects, in order (a list, or one text separated by commas); required
//   ~behaviours     the behaviours each session performs, in order (the same forms); required
//   ~sessions       sessions per object (10)
//   ~out            the folder to write, or to resume; required
//   ~seed           the trials' seeds, as the planner's (0)
//   ~listen         true (default): echoplan_listener records each performance's audio; false:
//                   no microphone (then ~series must name at least one stream)
//   ~series         MODALITY=TOPIC[:FIELD] entries, as echoplan_observation takes them
//   ~series_wait_s  how long a performance's streams are waited for after it ended (2)
//   ~wait_timeout_s how long to wait for a node to appear or answer before failing (10)
//
// Each trial begins with BeginTrial: an arm driver that needs the operator to place the object
// waits for them there. Resumable: run it again with the same ~out and it performs only what the
// manifest does not list yet. A performance whose recording or streams failed (the listener
// answered nothing, a stream stopped) is not written and is logged; running again performs it.
// Exits 0 when the collection is complete, 130 when stopped by SIGINT or SIGTERM (after the
// performance under way), 2 for bad parameters or files, 1 when a node failed.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <ros/ros.h>

#include <memory>
#include <set>

#include "common/error.h"
#include "common/stop_signal.h"
#include "loop/collection.h"
#include "node_main.h"
#include "robot/ros/master_watch.h"
#include "robot/ros/performance_marks.h"
#include "robot/ros/ros_protocol.h"
#include "robot/ros/ros_recorder.h"
#include "robot/ros/ros_robot.h"
#include "robot/transient_error.h"
#include "sensor_streams.h"

namespace {

namespace names = echoplan::robot::ros_names;
using echoplan::InputError;

// A required list of names (words_param).
std::vector<std::string> names_param(ros::NodeHandle& priv, const char* name) {
  auto names = echoplan::ros_app::words_param(priv, name);
  if (!names) throw InputError(fmt::format("~{}", name), 0, "the parameter is required");
  return std::move(*names);
}

echoplan::loop::CollectionPlan read_plan(ros::NodeHandle& priv) {
  echoplan::loop::CollectionPlan plan;
  plan.objects = names_param(priv, "objects");
  plan.behaviours = names_param(priv, "behaviours");
  priv.param("sessions", plan.sessions, 10);
  int seed = 0;
  priv.param("seed", seed, 0);
  if (seed < 0) throw InputError("~seed", 0, fmt::format("must be >= 0, got {}", seed));
  plan.seed = static_cast<std::uint64_t>(seed);
  if (!priv.getParam("out", plan.output_dir) || plan.output_dir.empty())
    throw InputError("~out", 0, "the parameter is required: the folder to write (or to resume)");
  return plan;
}

// Each performance's streams, by modality, cut between the collector's own markers.
echoplan::loop::PerformanceSignals stream_signals(echoplan::ros_app::SensorStreams& streams,
                                                  std::chrono::milliseconds wait) {
  return [&streams, wait](const std::string& /*object*/, int /*session*/,
                          const std::string& behaviour) {
    std::vector<std::size_t> all(streams.topics().size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    std::vector<std::pair<std::string, echoplan::signal::Series>> out;
    try {
      std::vector<echoplan::signal::Series> series = streams.take(behaviour, all, wait);
      for (std::size_t i = 0; i < all.size(); ++i)
        out.emplace_back(streams.topics()[i].modality, std::move(series[i]));
    } catch (const InputError& e) {
      throw echoplan::robot::TransientError(e.what());
    }
    return out;
  };
}

int collect(ros::NodeHandle& node, ros::NodeHandle& priv) {
  const echoplan::loop::CollectionPlan plan = read_plan(priv);
  double wait_timeout_s = 10.0;
  priv.param("wait_timeout_s", wait_timeout_s, 10.0);
  bool listen = true;
  priv.param("listen", listen, true);
  const auto series = echoplan::ros_app::series_param(priv);
  const auto series_wait = echoplan::ros_app::seconds_param(priv, "series_wait_s", 2.0);
  if (!listen && series.empty())
    throw InputError("~series", 0,
                     "with ~listen false, name the streams to record (nothing would be recorded)");
  ros::master::setRetryTimeout(ros::WallDuration(wait_timeout_s));
  std::optional<echoplan::ros_app::SensorStreams> streams;
  if (!series.empty()) streams.emplace(node, series, names::kPerformanceTopic);
  echoplan::robot::MarkedRobot robot(
      node,
      std::make_unique<echoplan::robot::RosRobot>(node, wait_timeout_s,
                                                  /*begin_trial_required=*/false),
      std::set<std::string>(plan.behaviours.begin(), plan.behaviours.end()),
      names::kPerformanceTopic);
  std::optional<echoplan::robot::RosRecorder> recorder;
  if (listen) recorder.emplace(node, wait_timeout_s);
  const echoplan::robot::MasterWatch watch;
  const echoplan::StopSignal stop;
  const echoplan::loop::CollectionSummary summary = echoplan::loop::collect(
      robot, recorder ? &*recorder : nullptr, plan,
      streams ? stream_signals(*streams, series_wait) : echoplan::loop::PerformanceSignals{},
      [](const echoplan::loop::CollectionStep& s) {
        if (s.lost.empty())
          ROS_INFO("[%d/%d] %s session %d %s", s.done, s.total, s.object.c_str(), s.session,
                   s.behaviour.c_str());
        else
          ROS_WARN("%s session %d %s not recorded (run again to perform it): %s", s.object.c_str(),
                   s.session, s.behaviour.c_str(), s.lost.c_str());
      },
      stop.flag());
  ROS_INFO(
      "%d performances recorded, %d already there, %d lost, %d not done as planned; "
      "manifest: %s/manifest.csv",
      summary.performed, summary.kept, summary.lost, summary.failed, plan.output_dir.c_str());
  return summary.interrupted ? 130 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  // SIGINT and SIGTERM stop the collection between performances (StopSignal), not roscpp.
  ros::init(argc, argv, "echoplan_collector", ros::init_options::NoSigintHandler);
  ros::NodeHandle node;
  ros::NodeHandle priv("~");
  // The recorder's answers arrive while the collection blocks on this thread.
  ros::AsyncSpinner spinner(1);
  spinner.start();
  const int status =
      echoplan::ros_app::run_node([&] { return collect(node, priv); }, "collection stopped: ");
  ros::shutdown();
  return status;
}
