#!/usr/bin/python3
# Helper of the ros_streams test: stands in for a robot without a microphone whose arm driver
# publishes its joint efforts (sensor_msgs/JointState on /joint_states) and its wrist's force
# (geometry_msgs/WrenchStamped on /wrist/wrench), and nothing else of its own: no feature rows, no
# markers. It serves /echoplan/begin_trial and /echoplan/execute_action as an arm driver does; for
# each sensing action it publishes, while "performing" it, the next recorded performance of the
# trial's object in session SESSION of the recordings tree TREE (DIR/<object>/<action>/<name>.
# effort.csv and .force.csv, in manifest order, as `echoplan run --data` replays a session), one
# message per sample, then answers. Sorting actions: done, nothing published.
#
#   stream_robot_stand_in.py TREE SESSION SUBSCRIBERS [FAULTS]
#
# SUBSCRIBERS: how many subscribers each topic must have before the first trial begins (the
# observation node, and rosbag when it records). FAULTS: comma-separated PERFORMANCE:KIND, the
# performance counted from 1 over the run: `silent` publishes no joint state in it (the stream
# stopped), `missing` publishes one joint state without the last joint, `short` only one joint state.
import csv
import os
import sys
import threading

import rospy
from echoplan_ros.srv import BeginTrial, BeginTrialResponse, ExecuteAction, ExecuteActionResponse
from geometry_msgs.msg import WrenchStamped
from sensor_msgs.msg import JointState


def read_series(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0][1:], [[float(v) for v in r] for r in rows[1:]]


def read_session(tree, session):
    """{action: {object: [(effort, force), ...]}} of `session`, in manifest order."""
    out = {}
    with open(os.path.join(tree, "manifest.csv"), newline="") as f:
        for row in csv.DictReader(f):
            if row["session"] != session:
                continue
            stem = os.path.join(tree, row["file"]).rsplit(".", 2)[0]
            out.setdefault(row["action"], {}).setdefault(row["object"], []).append(
                (read_series(stem + ".effort.csv"), read_series(stem + ".force.csv")))
    return out


class StandIn:
    def __init__(self, tree, session, subscribers, faults):
        self.performances = read_session(tree, session)
        self.session, self.subscribers, self.faults = session, subscribers, faults
        self.lock = threading.Lock()
        self.object, self.used, self.count = None, {}, 0
        self.efforts = rospy.Publisher("/joint_states", JointState, queue_size=10000)
        self.wrenches = rospy.Publisher("/wrist/wrench", WrenchStamped, queue_size=10000)
        rospy.Service("/echoplan/begin_trial", BeginTrial, self.begin_trial)
        rospy.Service("/echoplan/execute_action", ExecuteAction, self.execute)

    def begin_trial(self, request):
        # A subscriber that connects after a message was published never gets it.
        deadline = rospy.get_time() + 10
        while rospy.get_time() < deadline and min(
                self.efforts.get_num_connections(), self.wrenches.get_num_connections()) < self.subscribers:
            rospy.sleep(0.01)
        with self.lock:
            if not any(request.object in by_object for by_object in self.performances.values()):
                return BeginTrialResponse(False, "no performances of '%s' in session '%s'" % (request.object, self.session))
            self.object, self.used = request.object, {}
            return BeginTrialResponse(True, "")

    def publish(self, effort, force, fault):
        (joints, effort_rows), (_, force_rows) = effort, force
        # An arm's first samples of a motion come some milliseconds after the command; the
        # planner's start marker, published before it, is then surely in (the two travel on
        # different connections, so a sample sent at once could overtake it).
        rospy.sleep(0.05)
        if fault == "short":
            effort_rows = effort_rows[:1]
        samples = [(r[0], "effort", r[1:]) for r in effort_rows if fault != "silent"]
        samples += [(r[0], "force", r[1:]) for r in force_rows]
        efforts = 0
        for _, kind, values in sorted(samples, key=lambda s: (s[0], s[1])):
            if kind == "effort":
                efforts += 1
                names = joints[:-1] if fault == "missing" and efforts == 3 else joints
                self.efforts.publish(JointState(name=names, effort=values[:len(names)]))
            else:
                w = WrenchStamped()
                w.wrench.force.x, w.wrench.force.y, w.wrench.force.z = values
                self.wrenches.publish(w)
            rospy.sleep(0.002)
        # A performance ends after its last sample has gone out.
        rospy.sleep(0.2)

    def execute(self, request):
        with self.lock:
            action = request.action
            if action not in self.performances:
                return ExecuteActionResponse(status=ExecuteActionResponse.DONE, duration_s=0.01)
            n = self.used.get(action, 0)
            recorded = self.performances[action].get(self.object, [])
            if n >= len(recorded):
                return ExecuteActionResponse(status=ExecuteActionResponse.FAILED,
                                             reason="session '%s' has %d '%s' performances of '%s'" % (
                                                 self.session, len(recorded), action, self.object))
            self.used[action] = n + 1
            self.count += 1
            self.publish(*recorded[n], self.faults.get(self.count))
            return ExecuteActionResponse(status=ExecuteActionResponse.DONE, duration_s=0.3)


def main():
    tree, session, subscribers = sys.argv[1], sys.argv[2], int(sys.argv[3])
    faults = {}
    for item in (sys.argv[4].split(",") if len(sys.argv) > 4 and sys.argv[4] else []):
        n, kind = item.split(":")
        faults[int(n)] = kind
    rospy.init_node("stream_robot_stand_in", disable_signals=True)
    StandIn(tree, session, subscribers, faults)
    rospy.spin()


if __name__ == "__main__":
    main()
