#!/usr/bin/python3
"""realmap_scenario: a random fleet on a real map, as a YAML scenario for fleet_planner_cli.

Usage: scripts/realmap_scenario.py --map MAP.yaml --fleet FLEET.yaml --robots N --seed S --out OUT.yaml

The robots take the fleet file's footprints in turn (metres, costmap_2d conventions, padding
applied) and are named <fleet id>_<k>. Each start and goal is a random free cell at a random yaw
(--grid-headings: a random grid heading), where the robot's circumscribed disc covers only free
cells and keeps clear of the other robots' starts (goals); the cells are the map's own.
Each target is reachable from its start for the robot alone: both lie in one 4-connected region
of cells where the disc fits, so the robot can drive and turn all the way (--any-target: a
target anywhere the disc fits, reachable or not). Seeded: the same arguments give the same
file. Unknown cells count as blocked.
"""
import argparse
import math
import os
import random
import sys
from collections import deque

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "src"))

from fleet_planner.fleet_config import load_fleet  # noqa: E402
from fleet_planner.map_yaml import load_map  # noqa: E402


def reach(footprint):
    """Circumscribed radius (metres)."""
    if footprint.kind == "circle":
        return footprint.radius
    if footprint.kind == "block":
        return max(math.hypot(x, y) for x in (footprint.min_x, footprint.max_x)
                   for y in (footprint.min_y, footprint.max_y))
    return max(math.hypot(x, y) for x, y in footprint.points)


def nearest_heading(yaw):
    """The grid heading (0 +x, 1 -x, 2 +y, 3 -y) nearest to `yaw`."""
    quarter = int(round(yaw / (math.pi / 2))) % 4  # 0 +x, 1 +y, 2 -x, 3 -y
    return (0, 2, 1, 3)[quarter]


def pose_yaw(yaw, grid_headings):
    """(heading, yaw) of a pose drawn at `yaw`: the nearest grid heading, and the yaw unless on grid headings."""
    return nearest_heading(yaw), None if grid_headings else yaw


def scenario_footprint(footprint, resolution):
    """The footprint in cells, as a scenario writes it."""
    s = 1.0 / resolution
    if footprint.kind == "circle":
        return "{type: circle, radius: %.4f}" % (footprint.radius * s)
    if footprint.kind == "block":
        return "{type: block, min_x: %.4f, min_y: %.4f, max_x: %.4f, max_y: %.4f}" % (
            footprint.min_x * s, footprint.min_y * s, footprint.max_x * s, footprint.max_y * s)
    points = ", ".join("[%.4f, %.4f]" % (x * s, y * s) for x, y in footprint.points)
    return "{type: polygon, points: [%s]}" % points


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
    """4-connected regions of `fits`: a label per cell (-1 outside) and each region's cells."""
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


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--map", required=True)
    p.add_argument("--fleet", required=True)
    p.add_argument("--robots", type=int, required=True)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--out", required=True)
    p.add_argument("--grid-headings", action="store_true", help="poses on the grid headings only (no yaw)")
    p.add_argument("--any-target", action="store_true", help="targets need not be reachable from the starts")
    args = p.parse_args(argv)
    grid = load_map(args.map)
    fleet = load_fleet(args.fleet)
    rng = random.Random(args.seed)
    w, h, res = grid.width, grid.height, grid.resolution
    free = numpy.array(grid.data, dtype=numpy.int64).reshape(h, w) == 0
    fit_regions = {}  # radius -> (label, cells)

    def draw(r, taken, region):
        """A cell of `region` (None: anywhere the disc fits) clear of `taken`, or None."""
        label, cells = fit_regions[r]
        for _ in range(20000):
            if region is None:
                x, y = rng.randrange(w), rng.randrange(h)
                if label[y, x] < 0:
                    continue
            else:
                x, y = rng.choice(cells[region])
            if not any((x - ox) ** 2 + (y - oy) ** 2 < (r + orr) ** 2 for ox, oy, orr in taken):
                return x, y
        return None

    robots, taken = [], {"start": [], "target": []}
    for i in range(args.robots):
        footprint = fleet[i % len(fleet)]
        r = int(math.ceil(reach(footprint) / res + 0.5))
        if r not in fit_regions:
            fit_regions[r] = regions(disc_fits(free, r))
        label = fit_regions[r][0]
        pose = None
        for _ in range(200):
            start = draw(r, taken["start"], None)
            if start is None:
                break
            target = draw(r, taken["target"], None if args.any_target else label[start[1], start[0]])
            if target is not None:
                pose = {end: (x, y) + pose_yaw(rng.uniform(-math.pi, math.pi), args.grid_headings)
                        for end, (x, y) in (("start", start), ("target", target))}
                break
        if pose is None:
            sys.exit("realmap_scenario: no room for robot %d (%s)" % (i, footprint.robot_id))
        taken["start"].append(start + (r,))
        taken["target"].append(target + (r,))
        robots.append((footprint, pose))
    out_dir = os.path.dirname(os.path.abspath(args.out))
    with open(args.out, "w") as f:
        f.write("# %d robots of %s on %s, seed %d (scripts/realmap_scenario.py)\n"
                % (args.robots, os.path.basename(args.fleet), os.path.basename(args.map), args.seed))
        f.write("map: %s\nrobots:\n" % os.path.relpath(os.path.abspath(args.map), out_dir))
        for k, (footprint, pose) in enumerate(robots):
            f.write("  - id: %s_%d\n    footprint: %s\n" % (footprint.robot_id, k, scenario_footprint(footprint, res)))
            for end in ("start", "target"):
                x, y, h, yaw = pose[end]
                f.write("    %s: [%d, %d, %d]\n" % (end, x, y, h))
                if yaw is not None:
                    f.write("    %s_yaw: %.6f\n" % (end, yaw))
    return 0


if __name__ == "__main__":
    sys.exit(main())
