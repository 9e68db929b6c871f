#!/usr/bin/python3
"""realmap_scenario: a random fleet on a real map, as a YAML scenario for fleet_planner_cli.

Usage: scripts/realmap_scenario.py --map MAP.yaml --fleet FLEET.yaml --robots N --seed S --out OUT.yaml

The robots take the fleet file's footprints in turn (metres, costmap_2d conventions, padding
applied) and are named <fleet id>_<k>. Each start and goal is a random free cell at a random grid
heading, where the robot's circumscribed disc covers only free cells and keeps clear of the other
robots' starts (goals); the cells are the map's own (a scenario's poses are cells and headings).
Seeded: the same arguments give the same file. Unknown cells count as blocked.
"""
import argparse
import math
import os
import random
import sys

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


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--map", required=True)
    p.add_argument("--fleet", required=True)
    p.add_argument("--robots", type=int, required=True)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--out", required=True)
    args = p.parse_args(argv)
    grid = load_map(args.map)
    fleet = load_fleet(args.fleet)
    rng = random.Random(args.seed)
    w, h, res = grid.width, grid.height, grid.resolution
    free = [grid.data[y * w + x] == 0 for y in range(h) for x in range(w)]

    def disc_free(cx, cy, r):
        for y in range(max(0, cy - r), min(h, cy + r + 1)):
            for x in range(max(0, cx - r), min(w, cx + r + 1)):
                if (x - cx) ** 2 + (y - cy) ** 2 <= r * r and not free[y * w + x]:
                    return False
        return cx - r >= 0 and cy - r >= 0 and cx + r < w and cy + r < h

    robots, taken = [], {"start": [], "target": []}
    for i in range(args.robots):
        footprint = fleet[i % len(fleet)]
        r = int(math.ceil(reach(footprint) / res + 0.5))
        pose = {}
        for end in ("start", "target"):
            for _ in range(20000):
                x, y = rng.randrange(w), rng.randrange(h)
                if not free[y * w + x] or not disc_free(x, y, r):
                    continue
                if any((x - ox) ** 2 + (y - oy) ** 2 < (r + orr) ** 2 for ox, oy, orr in taken[end]):
                    continue
                pose[end] = (x, y, rng.randrange(4))
                taken[end].append((x, y, r))
                break
            else:
                sys.exit("realmap_scenario: no room for robot %d (%s) after 20000 draws" % (i, footprint.robot_id))
        robots.append((footprint, pose))
    out_dir = os.path.dirname(os.path.abspath(args.out))
    with open(args.out, "w") as f:
        f.write("# %d robots of %s on %s, seed %d (scripts/realmap_scenario.py)\n"
                % (args.robots, os.path.basename(args.fleet), os.path.basename(args.map), args.seed))
        f.write("map: %s\nrobots:\n" % os.path.relpath(os.path.abspath(args.map), out_dir))
        for k, (footprint, pose) in enumerate(robots):
            f.write("  - id: %s_%d\n    footprint: %s\n    start: [%d, %d, %d]\n    target: [%d, %d, %d]\n"
                    % ((footprint.robot_id, k, scenario_footprint(footprint, res)) + pose["start"] + pose["target"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
