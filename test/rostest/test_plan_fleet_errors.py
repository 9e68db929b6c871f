#!/usr/bin/python3
"""PlanFleet's error answers through the real node (plan_fleet_errors.test): each bad request gets
its own status and a message naming the robot or the field; the node answers BUSY while planning,
takes starts from TF, publishes markers and timelines, and stops at startup on a bad parameter.

Run: rostest fleet_planner plan_fleet_errors.test
"""
import copy
import os
import subprocess
import threading
import unittest

import roslib.packages
import rospy
import rostest
from visualization_msgs.msg import MarkerArray

from fleet_planner.msg import FleetTimelines, RobotResult
from fleet_planner.ros_conversions import task_to_msg
from fleet_planner.srv import PlanFleet, PlanFleetRequest, PlanFleetResponse
from fleet_planner.tasks_config import load_tasks

R = PlanFleetResponse


class PlanFleetErrorsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_plan_fleet_errors")
        cls.tasks = [task_to_msg(t) for t in load_tasks(rospy.get_param("~tasks_file"))]
        rospy.wait_for_service("/fleet_planner/plan_fleet", timeout=60)
        cls.plan = rospy.ServiceProxy("/fleet_planner/plan_fleet", PlanFleet)
        # Wait until the planner has the map and the registry.
        deadline = rospy.Time.now() + rospy.Duration(30)
        while rospy.Time.now() < deadline:
            response = cls.plan(cls.request())
            if response.status not in (R.NO_MAP, R.UNKNOWN_ROBOT):
                break
            rospy.sleep(0.2)
        assert response.status == R.SUCCESS, response.message

    @classmethod
    def request(cls, **fields):
        request = PlanFleetRequest(tasks=copy.deepcopy(cls.tasks), time_limit=20.0)
        for key, value in fields.items():
            setattr(request, key, value)
        return request

    def expect(self, request, status, *words, robot=None, robot_status=None, service=None):
        response = (service or self.plan)(request)
        self.assertEqual(response.status, status, response.message)
        for word in words:
            self.assertIn(word, response.message)
        if robot is not None:
            result = response.robots[robot]
            self.assertEqual(result.status, robot_status, result.message)
        self.assertEqual(response.timelines, [])
        return response

    def test_unknown_robot(self):
        request = self.request()
        request.tasks[1].robot_id = "ghost"
        self.expect(request, R.UNKNOWN_ROBOT, "'ghost'", "registry", robot=1,
                    robot_status=RobotResult.UNKNOWN_ROBOT)

    def test_start_in_an_obstacle(self):
        request = self.request()
        request.tasks[0].start.x, request.tasks[0].start.y = 0.1, 0.1  # the room's corner
        response = self.expect(request, R.INVALID_START, "'c1'", "start", robot=0,
                               robot_status=RobotResult.INVALID_START)
        self.assertTrue("blocked cell" in response.message or "leaves the map" in response.message,
                        response.message)

    def test_goal_off_the_map(self):
        request = self.request()
        request.tasks[2].goal.x = 40.0
        self.expect(request, R.INVALID_GOAL, "'p1'", "off the map", robot=2,
                    robot_status=RobotResult.INVALID_GOAL)

    def test_nan_pose(self):
        request = self.request()
        request.tasks[1].goal.theta = float("nan")
        self.expect(request, R.INVALID_GOAL, "'b1'", "theta is nan")

    def test_zero_time_limit(self):
        self.expect(self.request(time_limit=0.0), R.INVALID_REQUEST, "time_limit")

    def test_unknown_backend(self):
        self.expect(self.request(backend="teleport"), R.UNKNOWN_BACKEND, "teleport", "la_lacam")

    def test_no_map_yet(self):
        rospy.wait_for_service("/mapless/fleet_planner/plan_fleet", timeout=30)
        mapless = rospy.ServiceProxy("/mapless/fleet_planner/plan_fleet", PlanFleet)
        self.expect(self.request(), R.NO_MAP, "no map", service=mapless)

    def test_missing_transform(self):
        request = self.request()
        request.tasks[1].start_from_tf = True  # nobody publishes b1/base_link
        self.expect(request, R.NO_TRANSFORM, "b1/base_link", robot=1,
                    robot_status=RobotResult.NO_TRANSFORM)

    def test_start_from_tf(self):
        request = self.request()
        request.tasks[0].start_from_tf = True
        request.tasks[0].start.x = request.tasks[0].start.y = float("nan")  # ignored
        response = self.plan(request)
        self.assertEqual(response.status, R.SUCCESS, response.message)
        first = response.timelines[0].states[0]
        self.assertAlmostEqual(first.x, 0.5, places=6)
        self.assertAlmostEqual(first.y, 0.5, places=6)

    def test_markers_and_timelines_are_published(self):
        markers, timelines = [], []
        subs = [rospy.Subscriber("/fleet_planner/markers", MarkerArray, markers.append),
                rospy.Subscriber("/fleet_planner/timelines", FleetTimelines, timelines.append)]
        try:
            response = self.plan(self.request(backend="la_cbs", seed=3))
            self.assertEqual(response.status, R.SUCCESS, response.message)
            deadline = rospy.Time.now() + rospy.Duration(10)
            # Wait for this plan's messages: the latched ones of an earlier call may come first,
            # and the markers may come after the timelines.
            def starts(array):
                return len([m for m in array.markers if m.ns == "start"])
            while rospy.Time.now() < deadline and not (
                    timelines and timelines[-1].timelines == response.timelines and markers
                    and starts(markers[-1]) == len(response.timelines)):
                rospy.sleep(0.1)
            self.assertEqual(timelines[-1].timelines, response.timelines)
            latest = markers[-1].markers
            for ns in ("start", "goal", "path", "label"):
                ids = sorted(m.id for m in latest if m.ns == ns)
                self.assertEqual(ids, [0, 1, 2], ns)
        finally:
            for sub in subs:
                sub.unregister()

    def test_busy_while_planning(self):
        # Raw LA-CBS on these robots takes about 0.1 s; calls made meanwhile are answered BUSY
        # (busy_policy: reject). Keep calling while the slow call runs.
        slow = self.request(backend="la_cbs", decomposition=PlanFleetRequest.DECOMPOSITION_RAW,
                            time_limit=3.0)
        answers = []
        for _ in range(30):  # each try can miss the slow call's 0.1 s (5 tries missed 1 run in 15)
            thread = threading.Thread(target=self.plan, args=(slow,))
            thread.start()
            while thread.is_alive():
                answers.append(self.plan(self.request(time_limit=3.0)))
                if answers[-1].status == R.BUSY:
                    thread.join()
                    self.assertIn("busy_policy", answers[-1].message)
                    return
            thread.join()
        self.fail("no BUSY answer among %d calls: %s" % (len(answers), [a.status for a in answers]))

    def test_bad_parameter_stops_the_node(self):
        # The executable as roslaunch finds it (rosrun is confused by a build folder inside the
        # package's source folder, as scripts/build makes).
        found = [p for p in roslib.packages.find_node("fleet_planner", "fleet_planner_node")
                 if os.path.isfile(p) and os.access(p, os.X_OK)]
        self.assertTrue(found, "fleet_planner_node not found")
        node = subprocess.run(
            [found[0], "__name:=bad_planner",
             "_time_limit:=-1.0", "_busy_policy:=sometimes"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60, env=os.environ,
            universal_newlines=True)
        self.assertEqual(node.returncode, 1, node.stdout)
        self.assertIn("/bad_planner/time_limit must be > 0", node.stdout)
        self.assertIn("/bad_planner/busy_policy must be 'reject' or 'queue'", node.stdout)


if __name__ == "__main__":
    rostest.rosrun("fleet_planner", "plan_fleet_errors", PlanFleetErrorsTest)
