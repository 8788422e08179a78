// The names the echoplan ROS nodes agree on: the report's protocol (section 4.4) plus what a robot
// and a listener need to report back. One place, so nodes, clients, launch files and docs match.
//
// - parameter /echoplan/record: bool, the listener records while it is true (the report's protocol)
// - parameter /echoplan/record_action: string, the action being recorded (file names and logs)
// - topic /echoplan/recording: echoplan_ros/RecordingState, latched, the listener's state
// - topic /echoplan/clip: echoplan_ros/Clip, each finished recording
// - topic /echoplan/sim_clip: echoplan_ros/Clip, what the simulated robot's world sounded like
// - topic /echoplan/features: echoplan_ros/FeatureRow, what the robot's other sensors measured of
//   a performance, one message per sensor (for models whose modalities are not all audio)
// - topic /echoplan/performance: std_msgs/String, `start OBJECT ACTION SESSION` and `end` around
//   each sensing action (the planner publishes them; robot/ros/performance_marks.h), where the
//   observation node cuts a robot's sensor streams and a bag import cuts a bag
// - service /echoplan/observe: echoplan_ros/Observe, classify a performance (a clip, feature rows)
// - service /echoplan/execute_action: echoplan_ros/ExecuteAction, run an action on the arm
// - service /echoplan/begin_trial: echoplan_ros/BeginTrial, prepare the arm (and scene) for a trial
#pragma once

namespace echoplan::robot::ros_names {

inline constexpr const char* kRecordParam = "/echoplan/record";
inline constexpr const char* kRecordActionParam = "/echoplan/record_action";
inline constexpr const char* kRecordingTopic = "/echoplan/recording";
inline constexpr const char* kClipTopic = "/echoplan/clip";
inline constexpr const char* kSimClipTopic = "/echoplan/sim_clip";
inline constexpr const char* kObserveService = "/echoplan/observe";
inline constexpr const char* kExecuteActionService = "/echoplan/execute_action";
inline constexpr const char* kBeginTrialService = "/echoplan/begin_trial";
inline constexpr const char* kFeatureTopic = "/echoplan/features";
inline constexpr const char* kPerformanceTopic = "/echoplan/performance";

}  // namespace echoplan::robot::ros_names
