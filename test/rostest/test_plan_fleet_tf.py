#!/usr/bin/python3
"""Robots at any yaw, started from TF: plan_fleet_tf.test publishes each robot's pose with
static_transform_publisher at a yaw off the grid headings; PlanFleet with start_from_tf plans
them to goals at any yaw. Checks SUCCESS, each timeline beginning at its TF pose (the cell's
centre, the TF yaw) and ending at its goal (its yaw), and the nav_msgs/Path on ~plans/<robot>.

Run: rostest fleet_planner plan_fleet_tf.test
"""
import math
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Pose2D
from nav_msgs.msg import Path

from fleet_planner.msg import RobotTask
from fleet_planner.srv import PlanFleet, PlanFleetRequest, PlanFleetResponse

PLAN = "/fleet_planner/plan_fleet"
#: The TF poses of plan_fleet_tf.test (x, y, yaw) and the goals.
STARTS = {"c1": (0.52, 0.47, 0.913), "b1": (3.28, 0.53, 2.316), "p1": (1.9, 0.5, -0.634)}
GOALS = {"c1": (3.1, 1.1, 1.0), "b1": (0.7, 1.5, 2.0), "p1": (2.1, 1.5, -2.5)}
RESOLUTION = 0.2  # data/corridor.yaml


def angle_diff(a, b):
    return abs(math.remainder(a - b, 2 * math.pi))


def centre(v):
    return (math.floor(v / RESOLUTION) + 0.5) * RESOLUTION


class PlanFleetTfTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_plan_fleet_tf")
        rospy.wait_for_service(PLAN, timeout=60)
        plan = rospy.ServiceProxy(PLAN, PlanFleet)
        tasks = [RobotTask(robot_id=r, start_from_tf=True, goal=Pose2D(*GOALS[r])) for r in sorted(STARTS)]
        request = PlanFleetRequest(tasks=tasks, time_limit=10.0, seed=0)
        # The map, the footprints and the transforms reach the planner asynchronously.
        deadline = time.time() + 30
        cls.response = plan(request)
        while cls.response.status in (PlanFleetResponse.NO_MAP, PlanFleetResponse.UNKNOWN_ROBOT,
                                      PlanFleetResponse.NO_TRANSFORM) and time.time() < deadline:
            rospy.sleep(0.3)
            cls.response = plan(request)

    def test_plans_from_the_tf_poses_at_any_yaw(self):
        r = self.response
        self.assertEqual(r.status, PlanFleetResponse.SUCCESS, r.message)
        self.assertEqual(len(r.timelines), 3)
        for timeline in r.timelines:
            rid = timeline.robot_id
            first, last = timeline.states[0], timeline.states[-1]
            x, y, yaw = STARTS[rid]
            self.assertAlmostEqual(first.x, centre(x), delta=1e-6, msg=rid)
            self.assertAlmostEqual(first.y, centre(y), delta=1e-6, msg=rid)
            self.assertLess(angle_diff(first.yaw, yaw), 1e-3, "%s starts at yaw %g, TF says %g" % (rid, first.yaw, yaw))
            gx, gy, gyaw = GOALS[rid]
            self.assertAlmostEqual(last.x, centre(gx), delta=1e-6, msg=rid)
            self.assertAlmostEqual(last.y, centre(gy), delta=1e-6, msg=rid)
            self.assertLess(angle_diff(last.yaw, gyaw), 1e-3, "%s ends at yaw %g, goal %g" % (rid, last.yaw, gyaw))
            # Off the grid headings, the first and the last step are turns in place.
            self.assertEqual((first.cell_x, first.cell_y), (timeline.states[1].cell_x, timeline.states[1].cell_y))
            self.assertEqual((last.cell_x, last.cell_y), (timeline.states[-2].cell_x, timeline.states[-2].cell_y))

    def test_each_plan_is_a_path_topic(self):
        self.assertEqual(self.response.status, PlanFleetResponse.SUCCESS, self.response.message)
        for timeline in self.response.timelines:
            path = rospy.wait_for_message("/fleet_planner/plans/" + timeline.robot_id, Path, timeout=10)
            self.assertEqual(len(path.poses), len(timeline.states))
            self.assertAlmostEqual(path.poses[0].pose.position.x, timeline.states[0].x, delta=1e-9)
            stamps = [p.header.stamp.to_sec() for p in path.poses]
            self.assertEqual(stamps, sorted(stamps))


if __name__ == "__main__":
    rostest.rosrun("fleet_planner", "plan_fleet_tf", PlanFleetTfTest)
