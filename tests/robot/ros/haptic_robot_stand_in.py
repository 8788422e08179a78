#!/usr/bin/python3
# Helper of the ros_haptic test: stands in for a robot without a microphone whose one other sensor
# measures each performance. It serves /echoplan/begin_trial and /echoplan/execute_action as an
# arm driver does, and for each sensing action publishes, before it answers, what its sensor
# measured on /echoplan/features (echoplan_ros/FeatureRow): the next row of the trial's object in
# session SESSION of DATA/<behaviour>/<MODALITY>.csv, in file order, as `echoplan run --data`
# replays a session. Every row published is appended to PUBLISHED as
# `performance,behaviour,modality,value...` (values as Python's repr: the same doubles when read
# back). Actions that are not behaviours of DATA are sorting actions: done, nothing published.
#
#   haptic_robot_stand_in.py DATA MODALITY SESSION PUBLISHED
#
# Needs echoplan's generated Python messages on PYTHONPATH (build/ros/python).
import csv
import os
import sys
import threading

import rospy
from echoplan_ros.msg import FeatureRow
from echoplan_ros.srv import BeginTrial, BeginTrialResponse, ExecuteAction, ExecuteActionResponse


def read_rows(data, modality, session):
    """{behaviour: {object: [row, ...]}} of `session`, rows in file order."""
    rows = {}
    for behaviour in sorted(os.listdir(data)):
        path = os.path.join(data, behaviour, modality + ".csv")
        if not os.path.isfile(path):
            continue
        with open(path, newline="") as f:
            reader = csv.reader(f)
            next(reader)  # object,session,features...
            for line in reader:
                if line and line[1] == session:
                    rows.setdefault(behaviour, {}).setdefault(line[0], []).append(
                        [float(v) for v in line[2:]])
    return rows


class StandIn:
    def __init__(self, data, modality, session, published):
        self.rows = read_rows(data, modality, session)
        self.modality, self.session, self.published = modality, session, published
        self.lock = threading.Lock()
        self.object, self.used, self.performances = None, {}, 0
        self.features = rospy.Publisher("/echoplan/features", FeatureRow, queue_size=16)
        self.waited = False
        # BeginTrial first, as the contract asks (docs/real-robot.md).
        rospy.Service("/echoplan/begin_trial", BeginTrial, self.begin_trial)
        rospy.Service("/echoplan/execute_action", ExecuteAction, self.execute)

    def begin_trial(self, request):
        with self.lock:
            if not any(request.object in by_object for by_object in self.rows.values()):
                return BeginTrialResponse(False, "no rows of '%s' in session '%s'" % (request.object, self.session))
            self.object, self.used = request.object, {}
            return BeginTrialResponse(True, "")

    def execute(self, request):
        with self.lock:
            action = request.action
            if action not in self.rows:
                return ExecuteActionResponse(status=ExecuteActionResponse.DONE, duration_s=0.01)
            if self.object is None:
                return ExecuteActionResponse(status=ExecuteActionResponse.FAILED, reason="no trial begun")
            n = self.used.get(action, 0)
            rows = self.rows[action].get(self.object, [])
            if n >= len(rows):
                return ExecuteActionResponse(
                    status=ExecuteActionResponse.FAILED,
                    reason="session '%s' of '%s' has %d '%s' rows" % (self.session, self.object, len(rows), action))
            self.used[action] = n + 1
            values = rows[n]
            # A subscriber that connects after a message was published never gets it: wait for the
            # observation node once.
            if not self.waited:
                deadline = rospy.get_time() + 10
                while self.features.get_num_connections() == 0 and rospy.get_time() < deadline:
                    rospy.sleep(0.01)
                self.waited = True
            self.features.publish(FeatureRow(action, self.modality, values))
            self.performances += 1
            with open(self.published, "a") as f:
                f.write(",".join([str(self.performances), action, self.modality] + [repr(v) for v in values]) + "\n")
            return ExecuteActionResponse(status=ExecuteActionResponse.DONE, duration_s=0.01)


def main():
    data, modality, session, published = sys.argv[1:5]
    rospy.init_node("haptic_robot_stand_in", disable_signals=True)
    StandIn(data, modality, session, published)
    rospy.spin()


if __name__ == "__main__":
    main()
