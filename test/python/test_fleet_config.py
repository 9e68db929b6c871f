"""Tests of fleet_planner.fleet_config and fleet_planner.footprint: the fleet file, costmap_2d
padding, and the messages for bad robots (file, line, robot). No ROS master needed.

Run: PYTHONPATH=src /usr/bin/python3 -m unittest discover -s test/python
"""
import math
import os
import tempfile
import unittest

from fleet_planner.errors import InputError
from fleet_planner.fleet_config import load_fleet, parse_fleet
from fleet_planner.footprint import (BLOCK, CIRCLE, POLYGON, Footprint, padded, reach,
                                     shape_problem)

GOOD = """\
robots:
  - id: amr_1
    robot_radius: 0.35
    footprint_padding: 0.02
  - id: tug_1
    footprint: [[0.5, 0.3], [-0.5, 0.3], [-0.5, -0.3], [0.5, -0.3]]
  - id: forklift_1
    block: {min_x: -0.4, max_x: 0.9, min_y: -0.35, max_y: 0.35}
    footprint_padding: 0.05
  - id: arrow
    footprint: "[[0.4, 0.0], [-0.2, 0.2], [-0.2, -0.2]]"
    footprint_padding: 0.1
"""


class ReadsFleetFiles(unittest.TestCase):
    def test_good_file_in_order_with_padding(self):
        fleet = parse_fleet(GOOD, "fleet.yaml")
        self.assertEqual([f.robot_id for f in fleet], ["amr_1", "tug_1", "forklift_1", "arrow"])
        self.assertEqual([f.kind for f in fleet], [CIRCLE, POLYGON, BLOCK, POLYGON])
        self.assertAlmostEqual(fleet[0].radius, 0.37)
        self.assertEqual(fleet[1].points, ((0.5, 0.3), (-0.5, 0.3), (-0.5, -0.3), (0.5, -0.3)))
        block = fleet[2]
        for got, want in zip((block.min_x, block.max_x, block.min_y, block.max_y),
                             (-0.45, 0.95, -0.4, 0.4)):
            self.assertAlmostEqual(got, want)
        self.assertEqual(fleet[0].source, "fleet.yaml:3")
        self.assertEqual(fleet[2].source, "fleet.yaml:8")

    def test_polygon_padding_moves_vertices_by_their_signs_as_costmap_2d(self):
        # costmap_2d padFootprint: x += sign(x) * padding, y += sign(y) * padding; sign(0) = 0.
        arrow = parse_fleet(GOOD, "fleet.yaml")[3]
        expected = ((0.5, 0.0), (-0.3, 0.3), (-0.3, -0.3))
        for point, want in zip(arrow.points, expected):
            self.assertAlmostEqual(point[0], want[0])
            self.assertAlmostEqual(point[1], want[1])

    def test_padding_of_each_kind(self):
        circle = padded(Footprint("c", CIRCLE, radius=0.2), 0.05)
        self.assertAlmostEqual(circle.radius, 0.25)
        block = padded(Footprint("b", BLOCK, min_x=-1, max_x=2, min_y=-0.5, max_y=0.5), 0.5)
        self.assertEqual((block.min_x, block.max_x, block.min_y, block.max_y), (-1.5, 2.5, -1, 1))
        same = Footprint("p", POLYGON, points=((1, 0), (0, 1), (-1, -1)))
        self.assertIs(padded(same, 0), same)
        self.assertAlmostEqual(reach(padded(same, 0.5)), math.hypot(1.5, 1.5))

    def test_load_fleet_reads_a_file(self):
        with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as stream:
            stream.write(GOOD)
        self.addCleanup(os.remove, stream.name)
        self.assertEqual(len(load_fleet(stream.name)), 4)

    def test_empty_robot_list_is_allowed(self):
        self.assertEqual(parse_fleet("robots: []\n", "fleet.yaml"), [])


class RejectsBadFleets(unittest.TestCase):
    def assertError(self, text, line, robot, *words):
        with self.assertRaises(InputError) as caught:
            parse_fleet(text, "fleet.yaml")
        error = caught.exception
        self.assertEqual((error.source, error.line, error.robot), ("fleet.yaml", line, robot),
                         str(error))
        for word in words:
            self.assertIn(word, str(error))
        return str(error)

    def test_message_names_file_line_and_robot(self):
        text = self.assertError("robots:\n  - id: amr_1\n    robot_radius: .nan\n", 3, "amr_1",
                                "finite")
        self.assertEqual(text, "fleet.yaml:3: robot 'amr_1': robot_radius must be a finite "
                               "number, got nan")

    def test_bad_robots(self):
        r = "robots:\n  - id: a\n"
        cases = [
            (r + "    robot_radius: 0\n", 3, "a", "robot_radius: radius must be positive"),
            (r + "    robot_radius: -1\n", 3, "a", "positive"),
            (r + "    robot_radius: .inf\n", 3, "a", "finite"),
            (r + "    robot_radius: '0.3'\n", 3, "a", "must be a finite number, got '0.3'"),
            (r + "    robot_radius: 1\n    colour: red\n", 4, "a", "unknown key 'colour'"),
            (r + "    robot_radius: 1\n    robot_radius: 2\n", 4, None, "appears twice"),
            (r + "    footprint: [[0, 0], [1, 1]]\n", 3, "a", "at least 3 points, got 2"),
            (r + "    footprint: [[0, 0], [1, 0], [2, 0]]\n", 3, "a", "zero area"),
            (r + "    footprint: [[0, 0], [1, 1], [1, 0], [0, 1]]\n", 3, "a", "polygon"),
            (r + "    footprint: [[0, 0], [2, 0], [2, 2], [1, -1], [0, 2]]\n", 3, "a", "cross"),
            (r + "    footprint:\n      - [0, 0]\n      - [1, x]\n      - [1, 1]\n", 5, "a",
             "footprint point 2: y must be a finite number, got x"),
            (r + "    footprint: [[0, 0], [1], [1, 1]]\n", 3, "a", "point 2 must be [x, y]"),
            (r + "    footprint: 3\n", 3, "a", "list of [x, y] points"),
            (r + "    block: {min_x: 1, max_x: 0, min_y: 0, max_y: 1}\n", 3, "a", "min_x < max_x"),
            (r + "    block: {min_x: 0, max_x: 1, min_y: 0}\n", 3, "a", "block has no 'max_y'"),
            (r + "    block: {min_x: 0, max_x: 1, min_y: 0, max_y: 1, z: 0}\n", 3, "a",
             "unknown key 'z' in block"),
            (r, 2, "a", "exactly one of robot_radius, footprint, block; got none"),
            (r + "    robot_radius: 1\n    block: {}\n", 4, "a", "got robot_radius, block"),
            (r + "    robot_radius: 1\n    footprint_padding: -0.1\n", 4, "a", ">= 0"),
            (r + "    robot_radius: 1\n    footprint_padding: .nan\n", 4, "a", "finite"),
            ("robots:\n  - robot_radius: 1\n", 2, None, "robot entry 1 has no 'id'"),
            ("robots:\n  - id: 7\n    robot_radius: 1\n", 2, None, "robot entry 1: id must"),
            ("robots:\n  - id: my-robot\n    robot_radius: 1\n", 2, None, "ROS name"),
            ("robots:\n  - id: a/b\n    robot_radius: 1\n", 2, None, "ROS name"),
            ("robots:\n  - just a string\n", 2, None, "must be a mapping"),
        ]
        for text, line, robot, word in cases:
            with self.subTest(text=text):
                self.assertError(text, line, robot, word)

    def test_duplicate_ids_name_both_lines(self):
        text = ("robots:\n  - id: a\n    robot_radius: 1\n"
                "  - id: b\n    robot_radius: 1\n"
                "  - id: a\n    robot_radius: 2\n")
        self.assertError(text, 6, "a", "id 'a' is already used at line 2")

    def test_bad_files(self):
        self.assertError("", 0, None, "empty")
        self.assertError("robots: 3\n", 1, None, "robots must be a list")
        self.assertError("robot: []\n", 1, None, "unknown key 'robot'", "expected one of: robots")
        self.assertError("robots: [\n", 2, None, "not valid YAML")
        self.assertError("- a\n", 1, None, "must be a mapping")
        with self.assertRaises(InputError) as caught:
            load_fleet("/no/such/fleet.yaml")
        self.assertEqual(str(caught.exception),
                         "/no/such/fleet.yaml: cannot read the file: No such file or directory")


class ChecksShapes(unittest.TestCase):
    def test_the_cores_rules(self):
        self.assertEqual(shape_problem(Footprint("c", CIRCLE, radius=0.1)), "")
        self.assertIn("positive", shape_problem(Footprint("c", CIRCLE, radius=0.0)))
        self.assertIn("finite", shape_problem(Footprint("c", CIRCLE, radius=float("nan"))))
        self.assertIn("finite", shape_problem(Footprint("b", BLOCK, max_x=float("inf"))))
        self.assertIn("min_x < max_x", shape_problem(Footprint("b", BLOCK, max_x=1)))
        square = ((1, 1), (-1, 1), (-1, -1), (1, -1))
        self.assertEqual(shape_problem(Footprint("p", POLYGON, points=square)), "")
        clockwise = tuple(reversed(square))
        self.assertEqual(shape_problem(Footprint("p", POLYGON, points=clockwise)), "")
        repeated = ((1, 1), (1, 1), (-1, 1), (-1, -1))
        self.assertIn("coincide", shape_problem(Footprint("p", POLYGON, points=repeated)))
        folded = ((0, 0), (2, 0), (1, 0), (1, 1))  # an edge folds back onto its neighbour
        self.assertNotEqual(shape_problem(Footprint("p", POLYGON, points=folded)), "")
        l_shape = ((2, 1), (-1, 1), (-1, -1), (0, -1), (0, 0), (2, 0))
        self.assertEqual(shape_problem(Footprint("p", POLYGON, points=l_shape)), "")
        self.assertIn("unknown", shape_problem(Footprint("x", "triangle")))


if __name__ == "__main__":
    unittest.main()
