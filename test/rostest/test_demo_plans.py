#!/usr/bin/python3
"""The demo tasks plan with SUCCESS on the demo map and fleet, with each backend (demo_plans.test).

Run: rostest fleet_planner demo_plans.test
"""
import unittest

import rospy
import rostest

from fleet_planner.ros_conversions import task_to_msg
from fleet_planner.srv import PlanFleet, PlanFleetRequest, PlanFleetResponse
from fleet_planner.tasks_config import load_tasks
from plan_when_ready import plan_when_ready


class DemoPlansTest(unittest.TestCase):
    def test_demo_tasks_plan_with_each_backend(self):
        rospy.init_node("test_demo_plans")
        tasks = [task_to_msg(t) for t in load_tasks(rospy.get_param("~tasks_file"))]
        rospy.wait_for_service("/fleet_planner/plan_fleet", timeout=60)
        plan = rospy.ServiceProxy("/fleet_planner/plan_fleet", PlanFleet)
        for backend in ("la_lacam", "la_cbs"):
            request = PlanFleetRequest(tasks=tasks, backend=backend, time_limit=30.0)
            response = plan_when_ready(plan, request)
            self.assertEqual(response.status, PlanFleetResponse.SUCCESS,
                             backend + ": " + response.message)
            self.assertEqual(len(response.timelines), len(tasks))


if __name__ == "__main__":
    rostest.rosrun("fleet_planner", "demo_plans", DemoPlansTest)
