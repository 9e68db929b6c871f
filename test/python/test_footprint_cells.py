"""Tests of fleet_planner.footprint_cells: the cells a footprint covers at a pose, against the
C++ core's own expectations (test/core/footprint_cells_test.cpp; lengths there are in cells,
so the resolution here is 1). Quarter turns: 0 = +x, 1 = +y, 2 = -x, 3 = -y.

Run: PYTHONPATH=src /usr/bin/python3 -m unittest discover -s test/python
"""
import math
import unittest

from fleet_planner.footprint import BLOCK, CIRCLE, POLYGON, Footprint
from fleet_planner.footprint_cells import body_cells, cells_at, pose_cell


def rect(x0, x1, y0, y1):
    return {(x, y) for x in range(x0, x1 + 1) for y in range(y0, y1 + 1)}


def circle(r):
    return Footprint("c", CIRCLE, radius=r)


def block(min_x, min_y, max_x, max_y):
    return Footprint("b", BLOCK, min_x=min_x, max_x=max_x, min_y=min_y, max_y=max_y)


def polygon(*points):
    return Footprint("p", POLYGON, points=tuple(points))


class CoversCellsWithPositiveArea(unittest.TestCase):
    def test_circles(self):
        for r in (0.1, 0.4, 0.5):
            self.assertEqual(body_cells(circle(r), 0, 1.0), {(0, 0)})
        self.assertEqual(body_cells(circle(0.6), 0, 1.0),
                         {(0, 0), (1, 0), (-1, 0), (0, 1), (0, -1)})
        self.assertEqual(body_cells(circle(1.0), 1, 1.0), rect(-1, 1, -1, 1))
        self.assertEqual(body_cells(circle(1.5), 2, 1.0), rect(-1, 1, -1, 1))
        self.assertEqual(body_cells(circle(1.55), 3, 1.0),
                         rect(-1, 1, -1, 1) | {(2, 0), (-2, 0), (0, 2), (0, -2)})
        big = rect(-2, 2, -2, 2) - {(2, 2), (-2, 2), (2, -2), (-2, -2)}
        self.assertEqual(body_cells(circle(1.6), 0, 1.0), big)

    def test_block_at_all_four_headings(self):
        b = block(-0.3, -1.1, 1.1, 1.1)
        self.assertEqual(body_cells(b, 0, 1.0), rect(0, 1, -1, 1))
        self.assertEqual(body_cells(b, 1, 1.0), rect(-1, 1, 0, 1))
        self.assertEqual(body_cells(b, 2, 1.0), rect(-1, 0, -1, 1))
        self.assertEqual(body_cells(b, 3, 1.0), rect(-1, 1, -1, 0))

    def test_block_edges_on_cell_borders_do_not_spill(self):
        b = block(-0.5, -0.5, 1.5, 0.5)
        self.assertEqual(body_cells(b, 0, 1.0), {(0, 0), (1, 0)})
        self.assertEqual(body_cells(b, 1, 1.0), {(0, 0), (0, 1)})

    def test_polygons(self):
        triangle = polygon((1, 0), (-1, 1), (-1, -1))
        self.assertEqual(body_cells(triangle, 0, 1.0),
                         {(0, 0), (1, 0), (-1, 0), (-1, 1), (-1, -1), (0, 1), (0, -1)})
        self.assertEqual(body_cells(triangle, 1, 1.0),
                         {(0, 0), (0, 1), (0, -1), (-1, -1), (1, -1), (-1, 0), (1, 0)})
        notch = polygon((-0.5, -0.5), (1.5, -0.5), (1.5, 0.5), (0.5, 0.5), (0.5, 1.5),
                        (-0.5, 1.5))
        self.assertEqual(body_cells(notch, 0, 1.0), {(0, 0), (1, 0), (0, 1)})
        self.assertEqual(body_cells(notch, 3, 1.0), {(0, 0), (0, -1), (1, 0)})
        away = polygon((1.5, -0.5), (2.5, -0.5), (2.5, 0.5), (1.5, 0.5))
        self.assertEqual(body_cells(away, 0, 1.0), {(2, 0)})

    def test_metres_are_scaled_by_the_resolution(self):
        self.assertEqual(body_cells(circle(0.12), 0, 0.2), body_cells(circle(0.6), 0, 1.0))
        self.assertEqual(cells_at(block(-0.1, -0.1, 0.3, 0.1), 5, 7, 0, 0.2), {(5, 7), (6, 7)})


class PoseCells(unittest.TestCase):
    def test_cell_centres_and_quarter_turns(self):
        self.assertEqual(pose_cell(1.3, 0.5, math.pi, (0, 0, 0), 0.2), (6, 2, 2))
        self.assertEqual(pose_cell(-0.9, 2.1, -math.pi / 2, (-1, 2, 0), 0.2), (0, 0, 3))
        self.assertEqual(pose_cell(0.1, 0.1, 2 * math.pi, (0, 0, 0), 0.2), (0, 0, 0))

    def test_rejects_poses_off_the_grid(self):
        with self.assertRaisesRegex(ValueError, "centre of a cell"):
            pose_cell(0.2, 0.1, 0, (0, 0, 0), 0.2)
        with self.assertRaisesRegex(ValueError, "multiple of pi/2"):
            pose_cell(0.1, 0.1, 0.3, (0, 0, 0), 0.2)
        with self.assertRaisesRegex(ValueError, "rotated"):
            pose_cell(0.1, 0.1, 0, (0, 0, 0.5), 0.2)


if __name__ == "__main__":
    unittest.main()
