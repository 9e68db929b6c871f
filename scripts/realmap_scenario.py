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

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "src"))

from fleet_planner.fleet_config import load_fleet  # noqa: E402
from fleet_planner.map_yaml import load_map  # noqa: E402
from fleet_planner.pose_sampling import PoseSampler  # noqa: E402


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
    res = grid.resolution
    sampler = PoseSampler(grid, rng)
    robots, taken = [], {"start": [], "target": []}
    for i in range(args.robots):
        footprint = fleet[i % len(fleet)]
        r = sampler.radius(footprint)
        pose = None
        for _ in range(200):
            start = sampler.draw(footprint, taken["start"])
            if start is None:
                break
            region = None if args.any_target else sampler.region_of(footprint, start)
            target = sampler.draw(footprint, taken["target"], region)
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
