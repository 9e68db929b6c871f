#!/usr/bin/python3
"""Writes the demo warehouse map: maps/warehouse.pgm + maps/warehouse.yaml (map_server format).

Usage: scripts/make_demo_map.py [OUT_DIR]      (default: the package's maps/ folder)

A 24 m x 16 m warehouse at 0.2 m/cell (120 x 80 cells), origin (0, 0): outer walls, a loading
area on the west side (dock bumpers, a pallet stack, two pillars), and two blocks of five
shelving racks (0.8 m deep) separated by a 2 m cross aisle with a pillar in it. Aisles are 2.6,
2.0 and 1.4 m wide (13, 10 and 7 cells): two small robots pass each other in the wide ones,
not in the narrow ones. Deterministic: the same files every run. Rectangles are in metres.
"""
import os
import sys

RESOLUTION = 0.2
WIDTH, HEIGHT = 120, 80  # cells
FREE, OCCUPIED = 254, 0  # map_saver's shades

WALL = 0.2
#: Rack rows (y from, y to) and blocks (x from, x to), metres.
RACK_ROWS = [(2.8, 3.6), (5.6, 6.4), (7.8, 8.6), (10.6, 11.4), (12.8, 13.6)]
RACK_BLOCKS = [(7.0, 13.6), (15.6, 22.4)]
#: Other obstacles: (x0, y0, x1, y1) metres.
OBSTACLES = [
    (0.2, 3.8, 0.6, 4.2), (0.2, 7.8, 0.6, 8.2), (0.2, 11.8, 0.6, 12.2),  # dock bumpers
    (1.0, 14.2, 2.2, 15.2),  # pallet stack
    (3.0, 5.0, 3.4, 5.4), (3.0, 10.6, 3.4, 11.0),  # loading area pillars
    (14.4, 9.4, 14.8, 9.8),  # cross aisle pillar
]


def cell(metres):
    """The index of the cell boundary at `metres` (rectangles are snapped to cell edges)."""
    return int(round(metres / RESOLUTION))


def build_grid():
    """Rows of shades, row 0 at the bottom (y = 0)."""
    grid = [[FREE] * WIDTH for _ in range(HEIGHT)]

    def fill(x0, y0, x1, y1):
        for y in range(cell(y0), cell(y1)):
            for x in range(cell(x0), cell(x1)):
                grid[y][x] = OCCUPIED

    width_m, height_m = WIDTH * RESOLUTION, HEIGHT * RESOLUTION
    fill(0, 0, width_m, WALL)
    fill(0, height_m - WALL, width_m, height_m)
    fill(0, 0, WALL, height_m)
    fill(width_m - WALL, 0, width_m, height_m)
    for y0, y1 in RACK_ROWS:
        for x0, x1 in RACK_BLOCKS:
            fill(x0, y0, x1, y1)
    for rect in OBSTACLES:
        fill(*rect)
    return grid


def pgm_bytes(grid):
    """A binary PGM (P5); the image's top row is the map's top (highest y)."""
    header = "P5\n# fleet_planner demo warehouse, written by scripts/make_demo_map.py\n%d %d\n255\n"
    pixels = bytes(value for row in reversed(grid) for value in row)
    return (header % (WIDTH, HEIGHT)).encode("ascii") + pixels


YAML = """\
# The fleet_planner demo warehouse (24 m x 16 m), written by scripts/make_demo_map.py.
image: warehouse.pgm
resolution: %g
origin: [0.0, 0.0, 0.0]
negate: 0
occupied_thresh: 0.65
free_thresh: 0.196
"""


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "maps")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "warehouse.pgm"), "wb") as stream:
        stream.write(pgm_bytes(build_grid()))
    with open(os.path.join(out, "warehouse.yaml"), "w") as stream:
        stream.write(YAML % RESOLUTION)
    print("wrote %s/warehouse.pgm and warehouse.yaml (%d x %d cells)"
          % (os.path.normpath(out), WIDTH, HEIGHT))
    return 0


if __name__ == "__main__":
    sys.exit(main())
