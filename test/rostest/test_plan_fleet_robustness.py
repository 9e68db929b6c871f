#!/usr/bin/python3
"""PlanFleet against a hostile client (plan_fleet_robustness.test): the planner never dies and
every call is answered.

1. Malformed requests, one at a time: each gets its own non-SUCCESS status and a message naming
   the robot or the field.
2, 3. Bursts of 50 calls (5 clients x 10, valid and invalid mixed) against the reject planner
   and the queue planner: every call is answered, none hangs, bad requests get their own
   status even while the planner is busy, both planners are still up and the next valid call
   succeeds.
4. Map and footprint updates while a slow call plans: the call answers with a plan that the
   independent validator (fleet_planner_cli check) accepts on the map and footprints it started
   with; the next calls use the new map and registry. Meanwhile a queued call on the queue
   planner gives up after its own time limit.
5. A footprint of 1e6 m added through update_footprint: answered at once, the planner stays up.

The parts run in this order (4 changes the map and the registry).

Prints the calls made, the answers by status and the largest latency of each part.

Run: rostest fleet_planner plan_fleet_robustness.test
"""
import collections
import copy
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import roslib.packages
import rosnode
import rospy
import rostest
import yaml
from nav_msgs.msg import OccupancyGrid

from fleet_planner import map_yaml
from fleet_planner.msg import FleetFootprints, RobotFootprint, RobotResult, RobotTask
from fleet_planner.ros_conversions import occupancy_grid, task_to_msg
from fleet_planner.srv import (PlanFleet, PlanFleetRequest, PlanFleetResponse, UpdateFootprint,
                               UpdateFootprintRequest)
from fleet_planner.tasks_config import load_tasks
from geometry_msgs.msg import Point32, Pose2D

R = PlanFleetResponse
REJECT = "/fleet_planner"           # busy_policy reject
QUEUE = "/queued/fleet_planner"     # busy_policy queue
UPDATE = "/footprint_registry/update_footprint"
STATUS = {v: k for k, v in vars(PlanFleetResponse).items()
          if k.isupper() and isinstance(v, int)}
#: The resolution of the test's own maps: float32(0.2) exactly, so that the OccupancyGrid the
#: planner gets and the YAML the validator reads give the same footprint cells.
RES = 0.20000000298023224
#: Raw LA-CBS on the 360 x 360 map below takes seconds (0.37 s at 140 x 140 since LA-CBS got
#: faster, which raced the updates): long enough for them.
SLOW_MAP = 360
CALL_TIMEOUT = 30.0  # seconds: a call not answered by then counts as hung


def centre(i):
    return (i + 0.5) * RES


def pose(i, j, yaw=0.0):
    return Pose2D(x=centre(i), y=centre(j), theta=yaw)


def task(robot_id, start, goal):
    return RobotTask(robot_id=robot_id, start=start, goal=goal)


class Figures:
    """Calls, answers by status and latencies, per part of the test (thread-safe)."""

    def __init__(self):
        self._lock = threading.Lock()
        self.parts = collections.OrderedDict()
        self._dropped = collections.Counter()

    def add(self, part, status, latency):
        with self._lock:
            entry = self.parts.setdefault(part, {"calls": 0, "statuses": collections.Counter(),
                                                 "max_latency": 0.0, "unanswered": 0})
            entry["calls"] += 1
            if status is None:
                entry["unanswered"] += 1
            else:
                entry["statuses"][STATUS.get(status, str(status))] += 1
            entry["max_latency"] = max(entry["max_latency"], latency)

    def dropped(self, part):
        """A call whose connection the transport dropped (made once more)."""
        with self._lock:
            self._dropped[part] += 1

    def report(self):
        """One line per part and one for all: calls, unanswered, max latency, statuses."""
        total = {"calls": 0, "statuses": collections.Counter(), "max_latency": 0.0,
                 "unanswered": 0}
        for e in self.parts.values():
            total["calls"] += e["calls"]
            total["unanswered"] += e["unanswered"]
            total["statuses"].update(e["statuses"])
            total["max_latency"] = max(total["max_latency"], e["max_latency"])
        lines = ["PlanFleet robustness figures:"]
        for part, e in list(self.parts.items()) + [("all", total)]:
            dropped = sum(self._dropped.values()) if part == "all" else self._dropped[part]
            lines.append("  %-17s calls %3d  unanswered %d  dropped %d  max latency %6.3f s  %s" % (
                part, e["calls"], e["unanswered"], dropped, e["max_latency"],
                ", ".join("%s %d" % kv for kv in sorted(e["statuses"].items()))))
        return "\n".join(lines)


FIGURES = Figures()


def dropped_by_transport(error):
    """True for a connection that rospy saw close after the handshake, before any answer
    ("transport error completing service call: unable to receive data from sender"). Under a
    burst of short-lived connections from one process, the ROS transport can, rarely, close a
    fresh connection within milliseconds while the node stays up and answers the others: that
    is the middleware's failure, not the planner's, so such a call is made once more."""
    return isinstance(error, rospy.ServiceException) and "transport error" in str(error)


def timed_call(proxy, request, part):
    """Calls in a helper thread so that a hung call cannot hang the test: (response or None,
    latency, error). A call not answered within CALL_TIMEOUT counts as unanswered. A call
    dropped by the transport is retried once (counted as "dropped"); a second drop fails."""
    start = time.time()
    for attempt in range(2):
        result = {}

        def run():
            try:
                result["response"] = proxy(request)
            except Exception as error:  # a dropped connection is a failure to answer
                result["error"] = error

        thread = threading.Thread(target=run, daemon=True)
        thread.start()
        thread.join(CALL_TIMEOUT)
        if attempt == 0 and dropped_by_transport(result.get("error")):
            FIGURES.dropped(part)
            continue
        break
    latency = time.time() - start
    response = result.get("response")
    FIGURES.add(part, None if response is None else response.status, latency)
    return response, latency, result.get("error")


class Grid:
    """A test map: width x height cells of RES, walls around and the listed cells blocked."""

    def __init__(self, width, height, blocked=()):
        self.width, self.height = width, height
        self.blocked = set(blocked)
        for x in range(width):
            self.blocked |= {(x, 0), (x, height - 1)}
        for y in range(height):
            self.blocked |= {(0, y), (width - 1, y)}

    def save(self, folder, name):
        """Writes name.pgm and name.yaml (map_server format); returns the YAML's path."""
        rows = []
        for y in reversed(range(self.height)):  # the image's first row is the map's top
            rows.append(" ".join("0" if (x, y) in self.blocked else "254"
                                 for x in range(self.width)))
        with open(os.path.join(folder, name + ".pgm"), "w") as f:
            f.write("P2\n%d %d\n255\n%s\n" % (self.width, self.height, "\n".join(rows)))
        path = os.path.join(folder, name + ".yaml")
        with open(path, "w") as f:
            f.write("image: %s.pgm\nresolution: %r\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                    "occupied_thresh: 0.65\nfree_thresh: 0.196\n" % (name, RES))
        return path


def footprint_in_cells(msg, resolution):
    """A RobotFootprint (metres) as a scenario footprint (cells), as the planner converts it."""
    if msg.type == RobotFootprint.CIRCLE:
        return {"type": "circle", "radius": msg.radius / resolution}
    if msg.type == RobotFootprint.BLOCK:
        return {"type": "block", "min_x": msg.min_x / resolution, "min_y": msg.min_y / resolution,
                "max_x": msg.max_x / resolution, "max_y": msg.max_y / resolution}
    return {"type": "polygon", "points": [[p.x / resolution, p.y / resolution] for p in msg.points]}


class PlanFleetRobustnessTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_plan_fleet_robustness")
        cls.tasks = [task_to_msg(t) for t in load_tasks(rospy.get_param("~tasks_file"))]
        cls.folder = tempfile.mkdtemp(prefix="plan_fleet_robustness_")
        cls.cli = [p for p in roslib.packages.find_node("fleet_planner", "fleet_planner_cli")
                   if os.path.isfile(p) and os.access(p, os.X_OK)]
        cls.proxies = {}
        for name in (REJECT, QUEUE):
            rospy.wait_for_service(name + "/plan_fleet", timeout=60)
            cls.proxies[name] = rospy.ServiceProxy(name + "/plan_fleet", PlanFleet)
        rospy.wait_for_service(UPDATE, timeout=60)
        cls.update = rospy.ServiceProxy(UPDATE, UpdateFootprint)
        cls.registry = None
        cls.registry_lock = threading.Lock()
        rospy.Subscriber("/fleet_footprints", FleetFootprints, cls._on_registry)
        cls.map_pub = rospy.Publisher("/map", OccupancyGrid, latch=True, queue_size=1)
        for name in (REJECT, QUEUE):  # until each planner has the map and the registry
            response = cls.call_until(name, cls.request(), lambda r: r.status == R.SUCCESS)
            assert response.status == R.SUCCESS, response.message

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.folder, ignore_errors=True)
        report = FIGURES.report()
        print(report)
        sys.stdout.flush()
        rospy.loginfo(report)

    @classmethod
    def _on_registry(cls, msg):
        with cls.registry_lock:
            cls.registry = {f.robot_id: f for f in msg.robots}

    @classmethod
    def request(cls, **fields):
        request = PlanFleetRequest(tasks=copy.deepcopy(cls.tasks), time_limit=10.0)
        for key, value in fields.items():
            setattr(request, key, value)
        return request

    @classmethod
    def call_until(cls, planner, request, accept, timeout=20.0, part="setup"):
        """Calls until `accept(response)`: topics reach the planner asynchronously."""
        deadline = time.time() + timeout
        while True:
            response, _, _ = timed_call(cls.proxies[planner], request, part)
            if (response is not None and accept(response)) or time.time() > deadline:
                return response  # None: not answered
            rospy.sleep(0.1)

    def answer(self, planner, request, part):
        """The planner's answer to one call; fails the test if there is none."""
        response, latency, error = timed_call(self.proxies[planner], request, part)
        self.assertIsNotNone(response, "no answer within %g s (%r)" % (latency, error))
        return response

    def answer_until(self, planner, request, accept, **kwargs):
        """call_until(); fails the test if the last call got no answer."""
        response = self.call_until(planner, request, accept, **kwargs)
        self.assertIsNotNone(response, "no answer within %g s" % CALL_TIMEOUT)
        return response

    def alive(self, planner):
        return rosnode.rosnode_ping(planner, max_count=1, verbose=False)

    def publish_map(self, grid, name):
        path = grid.save(self.folder, name)
        msg = occupancy_grid(map_yaml.load_map(path), "map", rospy.Time.now())
        self.map_pub.publish(msg)
        return path

    def validate(self, map_path, footprints, request, response):
        """The response's plan must start at the starts, end at the goals, and pass the
        independent validator (fleet_planner_cli check) on `map_path` with `footprints`."""
        self.assertTrue(self.cli, "fleet_planner_cli not found")
        self.assertEqual(len(response.timelines), len(request.tasks))
        scenario, plan = {"robots": []}, {"format": "fleet_planner/plan/1", "robots": []}
        # The node plans with backward moves by default (allow_backward); the checker is told.
        plan["backward_moves"] = bool(response.statistics.backward_moves)
        for task_msg, timeline in zip(request.tasks, response.timelines):
            self.assertEqual(timeline.robot_id, task_msg.robot_id)
            first, last = timeline.states[0], timeline.states[-1]
            for state, target in ((first, task_msg.start), (last, task_msg.goal)):
                self.assertAlmostEqual(state.x, target.x, places=5)
                self.assertAlmostEqual(state.y, target.y, places=5)
                self.assertAlmostEqual(math.remainder(state.yaw - target.theta, 2 * math.pi), 0,
                                       places=5)
            scenario["robots"].append({
                "id": task_msg.robot_id,
                "footprint": footprint_in_cells(footprints[task_msg.robot_id], RES),
                "start": [first.cell_x, first.cell_y, first.heading],
                "target": [last.cell_x, last.cell_y, last.heading]})
            plan["robots"].append({"id": task_msg.robot_id,
                                   "path": [[s.cell_x, s.cell_y, s.heading]
                                            for s in timeline.states]})
        scenario_path = os.path.join(self.folder, "scenario.yaml")
        plan_path = os.path.join(self.folder, "plan.yaml")
        with open(scenario_path, "w") as f:
            yaml.safe_dump(scenario, f)
        with open(plan_path, "w") as f:
            yaml.safe_dump(plan, f)
        check = subprocess.run([self.cli[0], "check", "--map", map_path,
                                "--instance", scenario_path, "--plan", plan_path],
                               stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, universal_newlines=True, timeout=60)
        self.assertEqual(check.returncode, 0, check.stdout)
        self.assertTrue(json.loads(check.stdout.strip().splitlines()[-1])["valid"], check.stdout)

    def registry_snapshot(self):
        with self.registry_lock:
            return dict(self.registry or {})

    # -------------------------------------------------------------------------------------
    def test_1_malformed_requests_get_their_own_status(self):
        nan, inf = float("nan"), float("inf")
        cases = []  # (name, request, status, words in the message, (robot index, robot status))

        def add(name, status, words, robot=None, **fields):
            request = self.request()
            for key, value in fields.items():
                if key == "mutate":
                    value(request)
                else:
                    setattr(request, key, value)
            cases.append((name, request, status, words, robot))

        add("empty task list", R.INVALID_REQUEST, ["tasks is empty"], tasks=[])
        add("duplicate robot ids", R.INVALID_REQUEST,
            ["'c1' has two tasks", "tasks[0]", "tasks[2]"],
            mutate=lambda r: setattr(r.tasks[2], "robot_id", "c1"))
        add("empty robot id", R.INVALID_REQUEST, ["tasks[1]", "robot_id is empty"],
            mutate=lambda r: setattr(r.tasks[1], "robot_id", ""))
        for where, status, robot_status in (("start", R.INVALID_START, RobotResult.INVALID_START),
                                            ("goal", R.INVALID_GOAL, RobotResult.INVALID_GOAL)):
            for field, text in (("x", "x"), ("y", "y"), ("theta", "theta")):
                for value in (nan, inf, -inf):
                    add("%s.%s = %r" % (where, field, value), status,
                        ["robot 'b1'", "%s %s is %s" % (where, text, value)],
                        (1, robot_status),
                        mutate=lambda r, w=where, f=field, v=value:
                        setattr(getattr(r.tasks[1], w), f, v))
            for far in (1e6, -1e6):
                add("%s 1e6 m away (%g)" % (where, far), status,
                    ["robot 'p1'", where, "off the map"], (2, robot_status),
                    mutate=lambda r, w=where, v=far: setattr(getattr(r.tasks[2], w), "x", v))
        add("goal yaw 1e20 rad", R.INVALID_GOAL,
            ["robot 'c1'", "goal theta 1e+20 rad is not an angle"],
            (0, RobotResult.INVALID_GOAL), mutate=lambda r: setattr(r.tasks[0].goal, "theta", 1e20))
        add("negative time limit", R.INVALID_REQUEST, ["time_limit must be > 0", "got -5"],
            time_limit=-5.0)
        add("zero time limit", R.INVALID_REQUEST, ["time_limit must be > 0"], time_limit=0.0)
        add("NaN time limit", R.INVALID_REQUEST, ["time_limit must be > 0", "got nan"],
            time_limit=nan)
        add("infinite time limit", R.INVALID_REQUEST, ["time_limit must be > 0", "got inf"],
            time_limit=inf)
        add("time limit 1e12 s", R.INVALID_REQUEST, ["time_limit 1e+12 s", "max_time_limit (60 s)"],
            time_limit=1e12)
        add("unknown backend", R.UNKNOWN_BACKEND, ["'teleport'", "la_lacam", "la_cbs"],
            backend="teleport")
        add("steps out of range", R.INVALID_REQUEST, ["steps must be 1..4", "got 200"], steps=200)
        add("unknown decomposition", R.INVALID_REQUEST, ["decomposition must be", "got 9"],
            decomposition=9)
        add("unknown robot", R.UNKNOWN_ROBOT, ["robot 'ghost'", "not in the footprint registry"],
            (1, RobotResult.UNKNOWN_ROBOT),
            mutate=lambda r: setattr(r.tasks[1], "robot_id", "ghost"))

        # Every case is tried and every wrong answer listed (rosunit drops subTest failures).
        wrong = []
        for name, request, status, words, robot in cases:
            response, latency, error = timed_call(self.proxies[REJECT], request, "malformed")
            if response is None:
                wrong.append("%s: no answer within %g s (%r)" % (name, latency, error))
                continue
            problems = []
            if response.status != status:
                problems.append("status %s, expected %s" % (STATUS[response.status],
                                                           STATUS[status]))
            problems += ["message lacks %r" % w for w in words if w not in response.message]
            if response.timelines:
                problems.append("has timelines")
            if robot is not None:
                index, robot_status = robot
                statuses = [r.status for r in response.robots]
                expected = [robot_status if i == index else RobotResult.NOT_PLANNED
                            for i in range(len(request.tasks))]
                if statuses != expected:
                    problems.append("robot statuses %s, expected %s" % (statuses, expected))
            if problems:
                wrong.append("%s: %s (message: %s)" % (name, "; ".join(problems),
                                                       response.message))
        self.assertEqual(wrong, [], "\n".join(["wrong answers:"] + wrong))
        self.assertTrue(self.alive(REJECT))
        response = self.answer(REJECT, self.request(), "malformed")
        self.assertEqual(STATUS[response.status], "SUCCESS", response.message)

    # -------------------------------------------------------------------------------------
    def test_4_updates_while_a_slow_call_plans(self):
        n = SLOW_MAP
        wall = [(n // 2, y) for y in range(n // 3, 2 * n // 3)]
        map_a = self.publish_map(Grid(n, n, wall), "map_a")
        registry_a = self.registry_snapshot()
        self.assertEqual(sorted(registry_a), ["b1", "c1", "p1"])
        # Map A is in the planners when a goal on A's wall is "blocked" (on the corridor: off
        # the map).
        on_wall = PlanFleetRequest(tasks=[task("c1", pose(3, 3), pose(n // 2, n // 2))],
                                   time_limit=5.0)
        for planner in (REJECT, QUEUE):
            response = self.answer_until(planner, on_wall, lambda r: "blocked cell" in r.message)
            self.assertIn("blocked cell", response.message)

        # The slow call: raw LA-CBS, three robots across map A, on both planners.
        slow = PlanFleetRequest(tasks=[
            task("c1", pose(3, 3), pose(n - 4, n - 4)),
            task("b1", pose(n - 4, 3, math.pi), pose(4, n - 4, math.pi)),
            task("p1", pose(n // 2, 3), pose(n // 2, n - 4))],
            backend="la_cbs", decomposition=PlanFleetRequest.DECOMPOSITION_RAW, time_limit=40.0, seed=1)
        answers = {}

        def plan_slow(planner):
            proxy = rospy.ServiceProxy(planner + "/plan_fleet", PlanFleet)
            for _ in range(200):  # a probe below may hold the reject planner for a moment
                response, latency, error = timed_call(proxy, slow, "slow call")
                if response is None or response.status != R.BUSY:
                    break
                time.sleep(0.02)
            answers[planner] = (response, latency, error)

        threads = {p: threading.Thread(target=plan_slow, args=(p,), daemon=True)
                   for p in (REJECT, QUEUE)}
        for thread in threads.values():
            thread.start()
        quick = PlanFleetRequest(tasks=[task("c1", pose(3, 3), pose(6, 3))], time_limit=5.0)
        # The reject planner is busy with the slow call when a quick call is answered BUSY.
        busy = self.answer_until(REJECT, quick, lambda r: r.status == R.BUSY, timeout=10.0,
                                 part="probe")
        self.assertEqual(STATUS[busy.status], "BUSY",
                         "the slow call was not seen running: " + busy.message)
        # On the queue planner a call with 0.3 s to spare gives up after its 0.3 s.
        impatient = copy.deepcopy(quick)
        impatient.time_limit = 0.3
        waited = latency = None
        deadline = time.time() + 10.0
        while time.time() < deadline:
            waited, latency, _ = timed_call(self.proxies[QUEUE], impatient, "queue wait probe")
            if waited is not None and waited.status == R.TIMEOUT:
                break
        self.assertIsNotNone(waited, "the queue planner did not answer within %g s" % CALL_TIMEOUT)
        self.assertEqual(STATUS[waited.status], "TIMEOUT", waited.message)
        self.assertIn("waiting for other PlanFleet calls", waited.message)
        self.assertLess(latency, 0.3 + 1.5)

        # Meanwhile: a different map (map B, smaller: the slow call's goals are off it), p1
        # removed, n1 added, b1 grown.
        map_b = self.publish_map(Grid(60, 60), "map_b")
        for operation, footprint in (
                (UpdateFootprintRequest.REMOVE, RobotFootprint(robot_id="p1")),
                (UpdateFootprintRequest.ADD_OR_UPDATE,
                 RobotFootprint(robot_id="n1", type=RobotFootprint.CIRCLE, radius=0.25)),
                (UpdateFootprintRequest.ADD_OR_UPDATE,
                 RobotFootprint(robot_id="b1", type=RobotFootprint.BLOCK, min_x=-0.45, max_x=0.45,
                                min_y=-0.25, max_y=0.25))):
            answer = self.update(UpdateFootprintRequest(operation=operation, footprint=footprint))
            self.assertTrue(answer.success, answer.message)
        still_planning = {p: t.is_alive() for p, t in threads.items()}
        for thread in threads.values():
            thread.join(CALL_TIMEOUT + 10)
        self.assertEqual(still_planning, {REJECT: True, QUEUE: True},
                         "the slow calls ended before the updates: the test proves nothing")

        # Each slow call answered, with a valid plan on map A and the old footprints.
        for planner in (REJECT, QUEUE):
            response, latency, error = answers[planner]
            self.assertIsNotNone(response, "%s: no answer (%r)" % (planner, error))
            self.assertEqual(STATUS[response.status], "SUCCESS", response.message)
            self.validate(map_a, registry_a, slow, response)
            self.assertTrue(self.alive(planner))

        # The next calls use map B and the new registry.
        def updated(registry):
            return sorted(registry) == ["b1", "c1", "n1"] and registry["b1"].max_x == 0.45
        deadline = time.time() + 20.0
        while time.time() < deadline and not updated(self.registry_snapshot()):
            rospy.sleep(0.1)
        registry_b = self.registry_snapshot()
        self.assertTrue(updated(registry_b), "the registry did not publish the updates")
        for planner in (REJECT, QUEUE):
            response = self.answer_until(planner, slow, lambda r: r.status == R.UNKNOWN_ROBOT,
                                         part="after updates")
            self.assertEqual(STATUS[response.status], "UNKNOWN_ROBOT", response.message)
            self.assertIn("robot 'p1'", response.message)
            c1_only = copy.deepcopy(slow)  # c1 starts on map B too, but its goal is off it
            c1_only.tasks = c1_only.tasks[:1]
            response = self.answer_until(planner, c1_only, lambda r: "60 x 60 cells" in r.message,
                                         part="after updates")
            self.assertEqual(STATUS[response.status], "INVALID_GOAL", response.message)
            self.assertIn("off the map (60 x 60 cells", response.message)
        # b1 has grown: it no longer fits next to the wall, where it did before.
        grown = PlanFleetRequest(tasks=[task("b1", pose(2, 2), pose(10, 10))], time_limit=10.0)
        response = self.answer_until(REJECT, grown, lambda r: r.status == R.INVALID_START,
                                     part="after updates")
        self.assertEqual(STATUS[response.status], "INVALID_START", response.message)
        self.assertIn("robot 'b1': start", response.message)
        self.assertIn("blocked cell (0,", response.message)
        # n1, new, plans with the others on map B, and the plan is valid there.
        fleet = PlanFleetRequest(tasks=[
            task("n1", pose(5, 5), pose(50, 50)),
            task("b1", pose(50, 5, math.pi), pose(5, 50, math.pi)),
            task("c1", pose(30, 5), pose(30, 50))], time_limit=20.0, seed=2)
        response = self.answer(REJECT, fleet, "after updates")
        self.assertEqual(STATUS[response.status], "SUCCESS", response.message)
        self.validate(map_b, registry_b, fleet, response)

    # -------------------------------------------------------------------------------------
    def test_5_a_footprint_of_a_million_metres(self):
        # footprint_registry accepts any positive size; the planner must not try to rasterise it.
        # A circle of 1e6 m, and a small triangle 1e6 m from the robot's origin.
        giants = [RobotFootprint(robot_id="giant", type=RobotFootprint.CIRCLE, radius=1e6),
                  RobotFootprint(robot_id="far", type=RobotFootprint.POLYGON, points=[
                      Point32(x=1e6, y=0.0), Point32(x=1e6 + 0.2, y=0.0), Point32(x=1e6, y=0.2)])]
        for footprint in giants:
            answer = self.update(UpdateFootprintRequest(
                operation=UpdateFootprintRequest.ADD_OR_UPDATE, footprint=footprint))
            self.assertTrue(answer.success, answer.message)
        try:
            for footprint in giants:
                request = PlanFleetRequest(tasks=[task(footprint.robot_id, pose(5, 5), pose(8, 8))],
                                           time_limit=5.0)
                response = self.answer_until(REJECT, request, lambda r: r.status != R.UNKNOWN_ROBOT,
                                             part="giant footprint")
                self.assertEqual(STATUS[response.status], "INVALID_REQUEST", response.message)
                self.assertEqual(response.robots[0].status, RobotResult.INVALID_FOOTPRINT)
                self.assertIn("robot '%s': footprint" % footprint.robot_id, response.message)
                self.assertIn("larger than the map", response.message)
                self.assertLess(response.statistics.total_time, 2.0)
            self.assertTrue(self.alive(REJECT))
        finally:
            for footprint in giants:
                self.update(UpdateFootprintRequest(
                    operation=UpdateFootprintRequest.REMOVE,
                    footprint=RobotFootprint(robot_id=footprint.robot_id)))

    # -------------------------------------------------------------------------------------
    def burst(self, planner, part):
        """5 clients x 10 calls at once, each with its own ServiceProxy; returns the answers as
        (kind, response, latency, error)."""
        def make(kind):
            request = self.request(seed=7)
            if kind == "valid raw la_cbs":
                request.backend = "la_cbs"
                request.decomposition = PlanFleetRequest.DECOMPOSITION_RAW
            elif kind == "NaN goal":
                request.tasks[1].goal.y = float("nan")
            elif kind == "time limit 1e12":
                request.time_limit = 1e12
            elif kind == "duplicate ids":
                request.tasks[2].robot_id = "c1"
            elif kind == "unknown robot":
                request.tasks[0].robot_id = "ghost"
            return request

        kinds = ["valid", "valid raw la_cbs", "NaN goal", "valid", "time limit 1e12",
                 "valid raw la_cbs", "duplicate ids", "valid", "unknown robot", "valid"]
        answers, lock = [], threading.Lock()
        barrier = threading.Barrier(5)

        def client(c):
            proxy = rospy.ServiceProxy(planner + "/plan_fleet", PlanFleet)
            barrier.wait()
            for i in range(10):
                kind = kinds[(i + 3 * c) % len(kinds)]
                response, latency, error = timed_call(proxy, make(kind), part)
                with lock:
                    answers.append((kind, response, latency, error))

        clients = [threading.Thread(target=client, args=(c,), daemon=True) for c in range(5)]
        for thread in clients:
            thread.start()
        for thread in clients:
            thread.join(10 * CALL_TIMEOUT)
        self.assertFalse(any(t.is_alive() for t in clients), "a client is still waiting")
        self.assertEqual(len(answers), 50)
        return answers

    def check_burst(self, planner, answers, allowed_for_valid):
        expected = {"NaN goal": "INVALID_GOAL", "time limit 1e12": "INVALID_REQUEST",
                    "duplicate ids": "INVALID_REQUEST"}
        for kind, response, latency, error in answers:
            self.assertIsNotNone(response, "%s: no answer within %g s (%r)"
                                 % (kind, latency, error))
            status = STATUS[response.status]
            if kind in expected:  # answered at once, busy or not
                self.assertEqual(status, expected[kind], response.message)
            elif kind == "unknown robot":
                not_planned = [s for s in allowed_for_valid if s != "SUCCESS"]
                self.assertIn(status, ["UNKNOWN_ROBOT"] + not_planned, response.message)
            else:
                self.assertIn(status, allowed_for_valid, response.message)
                if status == "SUCCESS":
                    self.assertEqual(len(response.timelines), 3)
        self.assertTrue(self.alive(planner), planner + " does not answer a ping")
        response = self.answer(planner, self.request(), "after burst")
        self.assertEqual(STATUS[response.status], "SUCCESS", response.message)

    def test_2_burst_of_50_calls_busy_policy_reject(self):
        answers = self.burst(REJECT, "burst (reject)")
        self.check_burst(REJECT, answers, ["SUCCESS", "BUSY"])

    def test_3_burst_of_50_calls_busy_policy_queue(self):
        # Queued calls wait at most their own time limit (10 s): TIMEOUT is an answer too.
        answers = self.burst(QUEUE, "burst (queue)")
        self.check_burst(QUEUE, answers, ["SUCCESS", "TIMEOUT"])
        self.assertNotIn("BUSY", [STATUS[r.status] for _, r, _, _ in answers])


if __name__ == "__main__":
    rostest.rosrun("fleet_planner", "plan_fleet_robustness", PlanFleetRobustnessTest)
