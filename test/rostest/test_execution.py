#!/usr/bin/python3
"""Live execution (execution.test): the planner executes its plan of the demo's 10 robots while
the fleet simulator drives them late at random, with stops, and holds tug_1 for 6 s.

Checks: every robot arrives (the execution reports done, each robot ARRIVED, each TF pose at its
goal), no two robots' footprints ever shared a cell (the planner's monitor, from TF), and tug_1
was late while held while other robots drove on and arrived before it.

Run: rostest fleet_planner execution.test
"""
import math
import threading
import unittest

import rospy
import rostest
import tf2_ros

from fleet_planner.msg import FleetExecution, RobotExecution
from fleet_planner.ros_conversions import task_to_msg
from fleet_planner.srv import PlanFleet, PlanFleetRequest, PlanFleetResponse
from fleet_planner.tasks_config import load_tasks
from plan_when_ready import plan_when_ready, wait_until

HELD = "tug_1"


class ExecutionTest(unittest.TestCase):
    def test_late_robots_arrive_without_touching(self):
        rospy.init_node("test_execution")
        tasks = load_tasks(rospy.get_param("~tasks_file"))
        seen = {"last": None, "held_late": 0.0, "waited_for_held": set(), "arrived_before_held": set()}
        lock = threading.Lock()

        def on_execution(msg):
            with lock:
                seen["last"] = msg
                by_id = {r.robot_id: r for r in msg.robots}
                held = by_id.get(HELD)
                if held is None:
                    return
                seen["held_late"] = max(seen["held_late"], held.lateness)
                for r in msg.robots:
                    if r.blocked_by == HELD:
                        seen["waited_for_held"].add(r.robot_id)
                    if r.state == RobotExecution.ARRIVED and held.state != RobotExecution.ARRIVED:
                        seen["arrived_before_held"].add(r.robot_id)

        rospy.Subscriber("/fleet_planner/execution", FleetExecution, on_execution)
        rospy.wait_for_service("/fleet_planner/plan_fleet", timeout=60)
        plan = rospy.ServiceProxy("/fleet_planner/plan_fleet", PlanFleet)
        request = PlanFleetRequest(tasks=[task_to_msg(t) for t in tasks], time_limit=30.0)
        response = plan_when_ready(plan, request)
        self.assertEqual(response.status, PlanFleetResponse.SUCCESS, response.message)

        def all_arrived():
            with lock:
                return seen["last"] is not None and seen["last"].done

        wait_until(all_arrived, 180)
        with lock:
            last = seen["last"]
            summary = "dependencies %s, collisions %s; %s late by up to %.1f s; waited for it: %s; arrived before it: %s" % (
                last and last.dependencies, last and last.collisions, HELD, seen["held_late"],
                sorted(seen["waited_for_held"]), sorted(seen["arrived_before_held"]))
        rospy.loginfo("execution: %s", summary)
        self.assertIsNotNone(last, "no execution message")
        self.assertTrue(last.done, "not every robot arrived: %s" % [(r.robot_id, r.state, r.progress, r.last_state,
                                                                     r.blocked_by) for r in last.robots])
        self.assertEqual(last.collisions, 0, summary)
        self.assertGreater(last.dependencies, 0)
        for r in last.robots:
            self.assertEqual(r.state, RobotExecution.ARRIVED, r.robot_id)
        self.assertGreater(seen["held_late"], 3.0, summary)
        self.assertTrue(seen["arrived_before_held"], summary)

        buffer = tf2_ros.Buffer()
        tf2_ros.TransformListener(buffer)
        for task in tasks:
            t = buffer.lookup_transform("map", task.robot_id + "/base_link", rospy.Time(0), rospy.Duration(5))
            x, y = t.transform.translation.x, t.transform.translation.y
            self.assertLess(math.hypot(x - task.goal[0], y - task.goal[1]), 0.11, task.robot_id)


if __name__ == "__main__":
    rostest.rosrun("fleet_planner", "execution", ExecutionTest)
