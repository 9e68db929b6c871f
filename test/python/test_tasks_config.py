"""Tests of fleet_planner.tasks_config (the tasks file) and fleet_planner.task_check (poses
against a map and a fleet). No ROS master needed.

Run: PYTHONPATH=src /usr/bin/python3 -m unittest discover -s test/python
"""
import array
import math
import unittest

from fleet_planner.errors import InputError
from fleet_planner.footprint import BLOCK, CIRCLE, Footprint
from fleet_planner.map_yaml import OccupancyMap
from fleet_planner.task_check import task_problems
from fleet_planner.tasks_config import Task, parse_tasks

GOOD = """\
tasks:
  - id: a
    start: [0.5, 0.5, 0]
    goal: [2.5, 0.5, 3.141592653589793]
  - id: b
    start_from_tf: true
    goal: [1.5, 1.5, -1.5707963267948966]
"""


class ReadsTasks(unittest.TestCase):
    def test_good_file(self):
        a, b = parse_tasks(GOOD, "tasks.yaml")
        self.assertEqual(a, Task("a", (0.5, 0.5, 0.0), (2.5, 0.5, math.pi), False, "tasks.yaml:2"))
        self.assertEqual((b.robot_id, b.start, b.start_from_tf), ("b", None, True))

    def test_bad_tasks_name_file_line_and_robot(self):
        t = "tasks:\n  - id: a\n"
        cases = [
            (t + "    goal: [0, 0, 0]\n", 2, "a", "task 1 has no 'start'"),
            (t + "    start: [0, 0, 0]\n", 2, "a", "has no 'goal'"),
            (t + "    start: [0, 0]\n    goal: [0, 0, 0]\n", 3, "a", "start must be [x, y, yaw]"),
            (t + "    start: [0, .nan, 0]\n    goal: [0, 0, 0]\n", 3, "a", "start y must be"),
            (t + "    start: [0, 0, 0]\n    goal: [0, 0, x]\n", 4, "a", "goal yaw must be"),
            (t + "    start: [0, 0, 0]\n    goal: [0, 0, 0]\n    speed: 2\n", 5, "a",
             "unknown key 'speed'"),
            (t + "    start: [0, 0, 0]\n    start_from_tf: true\n    goal: [0, 0, 0]\n", 3, "a",
             "not both"),
            (t + "    start_from_tf: 1\n    goal: [0, 0, 0]\n", 3, "a", "true or false"),
            (t + "    start: [0, 0, 0]\n    goal: [0, 0, 0]\n"
                 "  - id: a\n    start: [1, 0, 0]\n    goal: [1, 0, 0]\n", 5, "a",
             "already has a task at line 2"),
            ("tasks:\n  - goal: [0, 0, 0]\n", 2, None, "task 1 has no 'id'"),
            ("tasks:\n  - id: 3a\n", 2, None, "task 1: id must"),
            ("tasks: []\n", 1, None, "non-empty list"),
            ("task: []\n", 1, None, "unknown key 'task'"),
            ("", 0, None, "empty"),
        ]
        for text, line, robot, word in cases:
            with self.subTest(text=text):
                with self.assertRaises(InputError) as caught:
                    parse_tasks(text, "tasks.yaml")
                e = caught.exception
                self.assertEqual((e.source, e.line, e.robot), ("tasks.yaml", line, robot), str(e))
                self.assertIn(word, str(e))


def corridor():
    """A 5 x 3 map at 1 m/cell: free except a blocked cell at (4, 2) and unknown at (4, 0)."""
    data = array.array("b", [0] * 15)
    data[2 * 5 + 4] = 100
    data[4] = -1
    return OccupancyMap(5, 3, 1.0, (0.0, 0.0, 0.0), data, None, "corridor")


class ChecksTasksAgainstTheMap(unittest.TestCase):
    fleet = [Footprint("a", CIRCLE, radius=0.4),
             Footprint("b", BLOCK, min_x=-0.4, max_x=1.4, min_y=-0.4, max_y=0.4)]

    def test_free_poses_pass(self):
        tasks = [Task("a", (0.5, 0.5, 0), (0.5, 2.5, 0)), Task("b", (1.5, 1.5, 0), (2.5, 2.5, 0))]
        self.assertEqual(task_problems(corridor(), self.fleet, tasks), [])

    def test_each_problem_is_named(self):
        tasks = [Task("a", (0.5, 0.5, 0), (4.5, 2.5, 0), source="t.yaml:2"),
                 Task("b", (0.5, 0.5, math.pi / 2), (3.5, 0.5, 0), source="t.yaml:5"),
                 Task("c", (0.5, 0.5, 0), (0.5, 0.5, 0), source="t.yaml:8"),
                 Task("a", (0.7, 0.5, 0), (1.5, 1.5, 0.1), source="t.yaml:11")]
        problems = task_problems(corridor(), self.fleet, tasks)
        expected = [
            "t.yaml:2: robot 'a' goal (4.5, 2.5, 0): footprint on 1 blocked or unknown cells",
            "t.yaml:5: robot 'b' start (0.5, 0.5, 1.5708): footprint overlaps a's start",
            "t.yaml:5: robot 'b' goal (3.5, 0.5, 0): footprint on 1 blocked or unknown cells, "
            "e.g. (4, 0)",
            "t.yaml:8: robot 'c' is not in the fleet",
            "t.yaml:11: robot 'a' start (0.7, 0.5, 0): (0.7, 0.5) is not the centre of a cell",
            "t.yaml:11: robot 'a' goal (1.5, 1.5, 0.1): yaw 0.1 is not a multiple of pi/2",
        ]
        self.assertEqual(len(problems), len(expected), "\n".join(problems))
        for problem, start in zip(problems, expected):
            self.assertTrue(problem.startswith(start), problem)


if __name__ == "__main__":
    unittest.main()
