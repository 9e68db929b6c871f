"""Tests of fleet_planner.tasks_config (the tasks file). No ROS master needed. Whether the poses
fit the map and the fleet is the planner's check (the rostests, demo_plans.test).

Run: PYTHONPATH=src /usr/bin/python3 -m unittest discover -s test/python
"""
import math
import unittest

from fleet_planner.errors import InputError
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


if __name__ == "__main__":
    unittest.main()
