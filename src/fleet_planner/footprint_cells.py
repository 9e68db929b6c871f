"""Which grid cells a footprint covers at a pose, with the planner's rule: a footprint covers a
cell when it overlaps the cell's square with positive area (touching an edge or a corner does
not count), and the robot's origin sits at the centre of its cell, heading along a grid axis.
A Python port of the core's squareOverlapsDisc/squareOverlapsPolygon (geometry.cpp), for
checking start and goal poses (demo data, tests) without the planner.
"""
import functools
import math

from fleet_planner.footprint import CIRCLE, outline, reach

_EPS = 1e-9
_QUARTER = math.pi / 2


def pose_cell(x, y, yaw, origin, resolution, tolerance=1e-6):
    """The grid state (cell_x, cell_y, quarter_turns) of a map-frame pose, or raise ValueError
    if the pose is not at a cell centre or its yaw not a multiple of pi/2 (within `tolerance`
    metres / radians). `origin` is the map's (x, y, yaw); a rotated map is not supported."""
    if origin[2] != 0:
        raise ValueError("maps with a rotated origin are not supported")
    fx = (x - origin[0]) / resolution - 0.5
    fy = (y - origin[1]) / resolution - 0.5
    cx, cy, turns = round(fx), round(fy), round(yaw / _QUARTER)
    if abs(fx - cx) * resolution > tolerance or abs(fy - cy) * resolution > tolerance:
        raise ValueError("(%g, %g) is not the centre of a cell" % (x, y))
    if abs(yaw - turns * _QUARTER) > tolerance:
        raise ValueError("yaw %g is not a multiple of pi/2" % yaw)
    return int(cx), int(cy), int(turns) % 4


def body_cells(footprint, quarter_turns, resolution):
    """The cells (dx, dy) that the footprint covers, relative to the robot's cell, when turned
    `quarter_turns` * 90 degrees counter-clockwise. Lengths are scaled to cells."""
    radius = reach(footprint) / resolution
    span = int(math.ceil(radius)) + 1
    if footprint.kind == CIRCLE:
        covers = functools.partial(_square_overlaps_disc, r=radius)
    else:
        polygon = [_rotate((x / resolution, y / resolution), quarter_turns)
                   for x, y in outline(footprint)]
        covers = functools.partial(_square_overlaps_polygon, polygon=polygon)
    return {(dx, dy) for dx in range(-span, span + 1) for dy in range(-span, span + 1)
            if covers((dx, dy))}


def cells_at(footprint, cell_x, cell_y, quarter_turns, resolution):
    """The absolute cells the footprint covers with its origin at the centre of (cell_x, cell_y)."""
    return {(cell_x + dx, cell_y + dy)
            for dx, dy in body_cells(footprint, quarter_turns, resolution)}


def _rotate(p, quarter_turns):
    x, y = p
    return [(x, y), (-y, x), (-x, -y), (y, -x)][quarter_turns % 4]


def _square_overlaps_disc(c, r):
    dx = max(abs(c[0]) - 0.5, 0.0)
    dy = max(abs(c[1]) - 0.5, 0.0)
    reach_ = r - _EPS
    return reach_ > 0 and dx * dx + dy * dy < reach_ * reach_


def _strictly_inside_square(p, c):
    return abs(p[0] - c[0]) < 0.5 - _EPS and abs(p[1] - c[1]) < 0.5 - _EPS


def _segment_enters_square(a, b, c):
    """Liang-Barsky clip against the closed square; the clipped piece reaches the open interior
    exactly when its midpoint lies in the interior."""
    t0, t1 = 0.0, 1.0
    d = (b[0] - a[0], b[1] - a[1])
    ps = (-d[0], d[0], -d[1], d[1])
    qs = (a[0] - (c[0] - 0.5), (c[0] + 0.5) - a[0], a[1] - (c[1] - 0.5), (c[1] + 0.5) - a[1])
    for p, q in zip(ps, qs):
        if p == 0.0:
            if q < 0.0:
                return False
            continue
        t = q / p
        if p < 0.0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return False
    mid = 0.5 * (t0 + t1)
    return _strictly_inside_square((a[0] + mid * d[0], a[1] + mid * d[1]), c)


def _point_in_polygon(p, polygon):
    inside = False
    j = len(polygon) - 1
    for i in range(len(polygon)):
        a, b = polygon[i], polygon[j]
        if (a[1] > p[1]) != (b[1] > p[1]):
            x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if p[0] < x:
                inside = not inside
        j = i
    return inside


def _square_overlaps_polygon(c, polygon):
    n = len(polygon)
    if any(_segment_enters_square(polygon[i], polygon[(i + 1) % n], c) for i in range(n)):
        return True
    return _point_in_polygon(c, polygon)
