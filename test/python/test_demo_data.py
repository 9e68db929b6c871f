"""Checks the demo data (maps/warehouse.yaml, config/demo_fleet.yaml, config/demo_tasks.yaml):
the map is the documented warehouse, the fleet is mixed, every robot has a task. No ROS master
needed; that the tasks plan (free, non-overlapping starts and goals) is checked by the planner
itself in test/rostest/demo_plans.test.

Run: PYTHONPATH=src /usr/bin/python3 -m unittest discover -s test/python
"""
import math
import os
import unittest

from fleet_planner.fleet_config import load_fleet
from fleet_planner.footprint import BLOCK, CIRCLE, POLYGON, reach
from fleet_planner.map_yaml import load_map
from fleet_planner.tasks_config import load_tasks

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def path(*parts):
    return os.path.join(ROOT, *parts)


class DemoData(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.map = load_map(path("maps", "warehouse.yaml"))
        cls.fleet = load_fleet(path("config", "demo_fleet.yaml"))
        cls.tasks = load_tasks(path("config", "demo_tasks.yaml"))

    def test_warehouse_map(self):
        m = self.map
        self.assertEqual((m.width, m.height, m.resolution, m.origin), (120, 80, 0.2, (0, 0, 0)))
        self.assertTrue(set(m.data) <= {0, 100})
        border = [m.data[i] for i in range(m.width)] + [m.data[y * m.width] for y in range(80)]
        self.assertEqual(set(border), {100})

    def test_mixed_fleet(self):
        self.assertGreaterEqual(len(self.fleet), 8)
        kinds = {f.kind for f in self.fleet}
        self.assertEqual(kinds, {CIRCLE, BLOCK, POLYGON})
        self.assertTrue(any(len(f.points) > 4 for f in self.fleet), "a non-rectangular polygon")
        for footprint in self.fleet:
            self.assertTrue(0.15 <= reach(footprint) <= 0.55, footprint)

    def test_every_robot_has_a_task(self):
        self.assertEqual(sorted(t.robot_id for t in self.tasks),
                         sorted(f.robot_id for f in self.fleet))

    def test_robots_cross_the_warehouse(self):
        crossing = [t for t in self.tasks if abs(t.goal[0] - t.start[0]) > 8.0]
        self.assertGreaterEqual(len(crossing), 5)
        for task in self.tasks:
            for pose in (task.start, task.goal):
                self.assertAlmostEqual(math.remainder(pose[2], math.pi / 2), 0.0)

    def test_the_generator_writes_the_committed_map(self):
        import importlib.util
        spec = importlib.util.spec_from_file_location("make_demo_map",
                                                      path("scripts", "make_demo_map.py"))
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        with open(path("maps", "warehouse.pgm"), "rb") as stream:
            self.assertEqual(module.pgm_bytes(module.build_grid()), stream.read())


if __name__ == "__main__":
    unittest.main()
