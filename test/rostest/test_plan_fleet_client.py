#!/usr/bin/python3
"""A PlanFleet client test, written as a user's client would be: rospy + unittest against the
real nodes started by plan_fleet_client.test (map_server, footprint_registry, the planner).

Checks that a bundled scenario (data/corridor_tasks.yaml) plans with SUCCESS, one timeline per
task in request order, starting at the starts and ending at the goals, with one action at most
between consecutive states; that the latched `timelines` topic carries the same plan; and that
footprint changes through /footprint_registry/update_footprint reach the next plan.

Run: rostest fleet_planner plan_fleet_client.test
"""
import math
import threading
import time
import unittest

import rospy
import rostest
from nav_msgs.msg import OccupancyGrid

from fleet_planner.msg import FleetTimelines, RobotFootprint, RobotResult
from fleet_planner.ros_conversions import task_to_msg
from fleet_planner.srv import (PlanFleet, PlanFleetRequest, PlanFleetResponse, UpdateFootprint,
                               UpdateFootprintRequest)
from fleet_planner.tasks_config import load_tasks

PLAN = "/fleet_planner/plan_fleet"
UPDATE = "/footprint_registry/update_footprint"
#: TimedState.heading -> (unit step of a forward move, yaw).
HEADINGS = {0: ((1, 0), 0.0), 1: ((-1, 0), math.pi), 2: ((0, 1), math.pi / 2),
            3: ((0, -1), -math.pi / 2)}


def angle_diff(a, b):
    return abs(math.remainder(a - b, 2 * math.pi))


def grid_state(state):
    return state.cell_x, state.cell_y, state.heading


class PlanFleetClientTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_plan_fleet_client")
        cls.tasks = load_tasks(rospy.get_param("~tasks_file"))
        rospy.wait_for_service(PLAN, timeout=60)
        rospy.wait_for_service(UPDATE, timeout=60)
        cls.plan_fleet = rospy.ServiceProxy(PLAN, PlanFleet)
        cls.update_footprint = rospy.ServiceProxy(UPDATE, UpdateFootprint)
        cls.map = rospy.wait_for_message("/map", OccupancyGrid, timeout=30)
        cls.timelines = []
        cls.timelines_lock = threading.Lock()
        rospy.Subscriber("/fleet_planner/timelines", FleetTimelines, cls._on_timelines)
        # The planner may not have the map and the footprints yet.
        response = cls.plan_until(lambda r: r.status not in (PlanFleetResponse.NO_MAP,
                                                             PlanFleetResponse.UNKNOWN_ROBOT))
        assert response.status == PlanFleetResponse.SUCCESS, response.message

    @classmethod
    def _on_timelines(cls, msg):
        with cls.timelines_lock:
            cls.timelines.append(msg)

    @classmethod
    def plan(cls):
        request = PlanFleetRequest(tasks=[task_to_msg(t) for t in cls.tasks], time_limit=10.0,
                                   seed=0)
        return cls.plan_fleet(request)

    @classmethod
    def plan_until(cls, accept, timeout=20.0):
        """Plans until `accept(response)` (topics reach the planner asynchronously)."""
        deadline = time.time() + timeout
        response = cls.plan()
        while not accept(response) and time.time() < deadline:
            rospy.sleep(0.2)
            response = cls.plan()
        return response

    def update(self, footprint, operation=UpdateFootprintRequest.ADD_OR_UPDATE, padding=0.0):
        response = self.update_footprint(operation=operation, footprint=footprint,
                                         padding=padding)
        self.assertTrue(response.success, response.message)

    def restore(self, footprint):
        """Puts a robot back and waits until the fleet plans again."""
        self.update(footprint)
        response = self.plan_until(lambda r: r.status == PlanFleetResponse.SUCCESS)
        self.assertEqual(response.status, PlanFleetResponse.SUCCESS, response.message)

    def assertAtPose(self, state, pose, what):
        x0, y0 = self.map.info.origin.position.x, self.map.info.origin.position.y
        self.assertAlmostEqual(state.x, pose[0], delta=1e-3, msg=what)
        self.assertAlmostEqual(state.y, pose[1], delta=1e-3, msg=what)
        self.assertLess(angle_diff(state.yaw, pose[2]), 1e-3, what)
        resolution = self.map.info.resolution
        self.assertEqual(state.cell_x, math.floor((pose[0] - x0) / resolution), what)
        self.assertEqual(state.cell_y, math.floor((pose[1] - y0) / resolution), what)

    def assertOneAction(self, before, after, what):
        (x0, y0, h0), (x1, y1, h1) = grid_state(before), grid_state(after)
        if (x0, y0) == (x1, y1):  # wait, or a quarter turn (+x/-x <-> +y/-y)
            self.assertTrue(h0 == h1 or (h0 < 2) != (h1 < 2), "%s: turns 180 degrees" % what)
        else:
            step = HEADINGS[h0][0]
            self.assertEqual(h0, h1, "%s: moves and turns at once" % what)
            self.assertIn((x1 - x0, y1 - y0), (step, (-step[0], -step[1])),
                          "%s: not one cell along its heading" % what)

    def test_plan_succeeds_with_one_valid_timeline_per_task(self):
        response = self.plan()
        self.assertEqual(response.status, PlanFleetResponse.SUCCESS, response.message)
        ids = [t.robot_id for t in self.tasks]
        self.assertEqual([r.robot_id for r in response.robots], ids)
        self.assertEqual({r.status for r in response.robots}, {RobotResult.OK})
        self.assertEqual([t.robot_id for t in response.timelines], ids)
        for task, timeline in zip(self.tasks, response.timelines):
            states = timeline.states
            self.assertGreater(len(states), 1, task.robot_id)
            self.assertAtPose(states[0], task.start, "%s start" % task.robot_id)
            self.assertAtPose(states[-1], task.goal, "%s goal" % task.robot_id)
            self.assertEqual([s.step for s in states], list(range(len(states))))
            for before, after in zip(states, states[1:]):
                self.assertOneAction(before, after, "%s step %d" % (task.robot_id, after.step))
            for state in states:
                self.assertLess(angle_diff(state.yaw, HEADINGS[state.heading][1]), 1e-3)
            self.assertEqual(grid_state(states[timeline.cost]), grid_state(states[-1]))
        costs = [t.cost for t in response.timelines]
        stats = response.statistics
        self.assertEqual((stats.robots, stats.soc, stats.makespan),
                         (len(ids), sum(costs), max(costs)))
        planned = sorted(r for sub in response.subproblems for r in sub.robot_ids)
        self.assertEqual(planned, sorted(ids))

    def test_timelines_topic_carries_the_same_plan(self):
        rospy.sleep(1.0)  # the latched message of an earlier call, if any, arrives first
        with self.timelines_lock:
            del self.timelines[:]
        response = self.plan()
        self.assertEqual(response.status, PlanFleetResponse.SUCCESS, response.message)
        deadline = time.time() + 10.0
        while not self.timelines and time.time() < deadline:
            rospy.sleep(0.1)
        with self.timelines_lock:
            self.assertTrue(self.timelines, "nothing on /fleet_planner/timelines")
            published = self.timelines[-1]
        self.assertGreater(published.seconds_per_step, 0)
        self.assertEqual(published.header.frame_id, self.map.header.frame_id)
        self.assertEqual([t.robot_id for t in published.timelines],
                         [t.robot_id for t in response.timelines])
        for sent, answered in zip(published.timelines, response.timelines):
            self.assertEqual([grid_state(s) for s in sent.states],
                             [grid_state(s) for s in answered.states], sent.robot_id)
            self.assertEqual(sent.cost, answered.cost)
            for state in sent.states:
                self.assertAlmostEqual(state.time, state.step * published.seconds_per_step)

    def test_a_grown_footprint_makes_the_start_invalid(self):
        grown = RobotFootprint(robot_id="c1", type=RobotFootprint.CIRCLE, radius=0.3)
        self.update(grown, padding=0.05)  # radius 0.35 m: into the walls at c1's start
        try:
            response = self.plan_until(lambda r: r.status != PlanFleetResponse.SUCCESS)
            self.assertEqual(response.status, PlanFleetResponse.INVALID_START, response.message)
            statuses = {r.robot_id: r.status for r in response.robots}
            self.assertEqual(statuses["c1"], RobotResult.INVALID_START)
            self.assertNotIn(RobotResult.INVALID_START,
                             [s for robot, s in statuses.items() if robot != "c1"])
            self.assertEqual(len(response.timelines), 0)
        finally:
            self.restore(RobotFootprint(robot_id="c1", type=RobotFootprint.CIRCLE, radius=0.15))

    def test_a_removed_robot_is_unknown(self):
        self.update(RobotFootprint(robot_id="b1"), operation=UpdateFootprintRequest.REMOVE)
        try:
            response = self.plan_until(lambda r: r.status != PlanFleetResponse.SUCCESS)
            self.assertEqual(response.status, PlanFleetResponse.UNKNOWN_ROBOT, response.message)
            statuses = {r.robot_id: r.status for r in response.robots}
            self.assertEqual(statuses["b1"], RobotResult.UNKNOWN_ROBOT)
        finally:
            self.restore(RobotFootprint(robot_id="b1", type=RobotFootprint.BLOCK, min_x=-0.15,
                                        max_x=0.25, min_y=-0.15, max_y=0.15))

    def test_bad_footprint_updates_are_refused(self):
        bad = RobotFootprint(robot_id="c1", type=RobotFootprint.POLYGON)
        response = self.update_footprint(operation=UpdateFootprintRequest.ADD_OR_UPDATE,
                                         footprint=bad, padding=0.0)
        self.assertFalse(response.success)
        self.assertIn("c1", response.message)
        self.assertIn("at least 3 points", response.message)
        self.assertEqual(self.plan().status, PlanFleetResponse.SUCCESS)


if __name__ == "__main__":
    rostest.rosrun("fleet_planner", "plan_fleet_client", PlanFleetClientTest)
