"""Random robot poses on a map that a robot can reach: for the real-map benchmark's scenarios and
the execution soak. No ROS.

A pose is drawn at a cell where the robot's circumscribed disc covers only free cells (so it can
stand and turn there at any yaw) and keeps clear of the other robots' poses of the same kind
(starts, goals). A cell where the disc fits is reachable from another such cell when both lie in
one 4-connected region of such cells: the robot can drive and turn all the way. Unknown cells
count as blocked. Seeded through the caller's random.Random.
"""
import math
from collections import deque

import numpy

from fleet_planner.footprint import reach


def disc_fits(free, r):
    """Cells where a disc of r cells around the cell covers only free cells, inside the map."""
    h, w = free.shape
    fits = numpy.zeros_like(free)
    fits[r:h - r, r:w - r] = True
    for dy in range(-r, r + 1):
        for dx in range(-r, r + 1):
            if dx * dx + dy * dy <= r * r:
                shifted = numpy.ones_like(free)
                ys, yd = (slice(0, h - dy), slice(dy, h)) if dy >= 0 else (slice(-dy, h), slice(0, h + dy))
                xs, xd = (slice(0, w - dx), slice(dx, w)) if dx >= 0 else (slice(-dx, w), slice(0, w + dx))
                shifted[ys, xs] = free[yd, xd]
                fits &= shifted
    return fits


def regions(fits):
    """4-connected regions of `fits`: a label per cell (-1 outside) and each region's cells (x, y)."""
    h, w = fits.shape
    label = numpy.full(fits.shape, -1, dtype=numpy.int64)
    cells = []
    for y0, x0 in zip(*numpy.nonzero(fits)):
        if label[y0, x0] >= 0:
            continue
        k, members, queue = len(cells), [], deque([(int(y0), int(x0))])
        label[y0, x0] = k
        while queue:
            y, x = queue.popleft()
            members.append((x, y))
            for ny, nx in ((y + 1, x), (y - 1, x), (y, x + 1), (y, x - 1)):
                if 0 <= ny < h and 0 <= nx < w and fits[ny, nx] and label[ny, nx] < 0:
                    label[ny, nx] = k
                    queue.append((ny, nx))
        cells.append(members)
    return label, cells


class PoseSampler:
    """Draws cells for robots of given footprints on an OccupancyMap (map_yaml.load_map)."""

    def __init__(self, grid, rng):
        self.grid = grid
        self.rng = rng
        self.free = numpy.array(grid.data, dtype=numpy.int64).reshape(grid.height, grid.width) == 0
        self._regions = {}  # radius in cells -> (label, cells)

    def radius(self, footprint):
        """The footprint's circumscribed radius in cells, rounded up with half a cell to spare."""
        return int(math.ceil(reach(footprint) / self.grid.resolution + 0.5))

    def _fit(self, r):
        if r not in self._regions:
            self._regions[r] = regions(disc_fits(self.free, r))
        return self._regions[r]

    def region_of(self, footprint, cell):
        """The region of `cell` (x, y) for this footprint, or None where its disc does not fit."""
        label = self._fit(self.radius(footprint))[0][cell[1], cell[0]]
        return None if label < 0 else int(label)

    def draw(self, footprint, taken, region=None, tries=20000):
        """A cell (x, y) where the footprint's disc fits, in `region` if given, whose disc keeps
        clear of every (x, y, r) in `taken`; None if none is found."""
        r = self.radius(footprint)
        label, cells = self._fit(r)
        for _ in range(tries):
            if region is None:
                x, y = self.rng.randrange(self.grid.width), self.rng.randrange(self.grid.height)
                if label[y, x] < 0:
                    continue
            else:
                x, y = self.rng.choice(cells[region])
            if not any((x - ox) ** 2 + (y - oy) ** 2 < (r + orr) ** 2 for ox, oy, orr in taken):
                return x, y
        return None

    def metres(self, cell, yaw):
        """The map-frame pose (x, y, yaw) of the centre of `cell`."""
        ox, oy, oyaw = self.grid.origin
        res = self.grid.resolution
        gx, gy = (cell[0] + 0.5) * res, (cell[1] + 0.5) * res
        c, s = math.cos(oyaw), math.sin(oyaw)
        return (ox + c * gx - s * gy, oy + s * gx + c * gy, math.remainder(yaw + oyaw, 2 * math.pi))

    def cell_of(self, x, y):
        """The cell (x, y) holding the map-frame point."""
        ox, oy, oyaw = self.grid.origin
        c, s = math.cos(oyaw), math.sin(oyaw)
        dx, dy = x - ox, y - oy
        return (int(math.floor((c * dx + s * dy) / self.grid.resolution)),
                int(math.floor((-s * dx + c * dy) / self.grid.resolution)))
