#!/usr/bin/python3
# Helper of the ros_retry_safe and ros_fail_unsafe tests: stands in for an arm driver whose first
# sorting action fails before the arm moved. It serves /echoplan/execute_action in front of
# echoplan_sim_robot (started with /echoplan/execute_action remapped to /sim/execute_action): the
# first move_to_* request is answered FAILED with `retry_safe` as given, without reaching the
# simulated arm; every other request is passed on and its answer returned.
#
#   flaky_arm_stand_in.py true|false
#
# A sorting action, because it is not recorded: the retry costs no listener wait. Needs echoplan's
# generated Python messages on PYTHONPATH (build/ros/python).
import sys

import rospy
from echoplan_ros.srv import ExecuteAction, ExecuteActionResponse

retry_safe = {"true": True, "false": False}[sys.argv[1]]
failed_once = False


def execute(request):
    global failed_once
    if request.action.startswith("move_to_") and not failed_once:
        failed_once = True
        rospy.loginfo("'%s': failing once (retry_safe %s)", request.action, retry_safe)
        return ExecuteActionResponse(status=ExecuteActionResponse.FAILED,
                                     reason="the gripper missed the object before lifting it",
                                     retry_safe=retry_safe)
    return arm(request.action)


rospy.init_node("flaky_arm")
rospy.wait_for_service("/sim/execute_action", timeout=30)
arm = rospy.ServiceProxy("/sim/execute_action", ExecuteAction, persistent=True)
rospy.Service("/echoplan/execute_action", ExecuteAction, execute)
rospy.loginfo("flaky arm stand-in ready (retry_safe %s)", retry_safe)
rospy.spin()
