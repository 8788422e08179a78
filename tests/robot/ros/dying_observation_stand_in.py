#!/usr/bin/python3
# Helper of the ros_restart_observation test: stands in for an observation node that dies in the
# middle of a call. It serves /echoplan/observe and, on the first request, exits at once without
# answering (as a node killed mid-call), so the caller's connection closes during its call.
#
#   dying_observation_stand_in.py
#
# Needs echoplan's generated Python messages on PYTHONPATH (build/ros/python).
import os

import rospy
from echoplan_ros.srv import Observe


def die(_request):
    rospy.loginfo("observe request received: dying without an answer")
    os._exit(3)


rospy.init_node("echoplan_observation")
rospy.Service("/echoplan/observe", Observe, die)
rospy.loginfo("dying observation stand-in ready")
rospy.spin()
