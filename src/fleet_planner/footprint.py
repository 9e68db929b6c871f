"""Robot footprints in metres, in the robot's frame (+x forward, +y left), without ROS.

Three kinds, as fleet_planner/RobotFootprint: a circle (radius about the origin), a block (the
rectangle [min_x, max_x] x [min_y, max_y]) and a polygon (vertices in order, the costmap_2d
`footprint` convention, convex or not). `shape_problem()` applies the C++ core's checks
(footprintProblem), so a footprint accepted here is accepted by the planner. `padded()` applies
a padding as costmap_2d does.
"""
import math
import re
from dataclasses import dataclass, replace

CIRCLE, BLOCK, POLYGON = "circle", "block", "polygon"
KINDS = (CIRCLE, BLOCK, POLYGON)

_ID = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")
_EPS = 1e-9


@dataclass(frozen=True)
class Footprint:
    """One robot's footprint. Only the fields of its `kind` matter; `points` is a tuple of
    (x, y) tuples. `source` says where it came from (e.g. "fleet.yaml:12"), for messages."""

    robot_id: str
    kind: str
    radius: float = 0.0
    min_x: float = 0.0
    max_x: float = 0.0
    min_y: float = 0.0
    max_y: float = 0.0
    points: tuple = ()
    source: str = ""


def id_problem(robot_id):
    """"" when `robot_id` can name a robot (and its TF frames `<id>/base_link`, `<id>/planned`):
    a ROS name without namespaces, i.e. a letter, then letters, digits or underscores."""
    if isinstance(robot_id, str) and _ID.match(robot_id):
        return ""
    return ("id must be a letter followed by letters, digits or '_' (a ROS name), got '%s'"
            % (robot_id,))


def shape_problem(footprint):
    """"" when the shape is usable, else the reason (the core's footprintProblem rules)."""
    f = footprint
    if f.kind == CIRCLE:
        if not math.isfinite(f.radius):
            return "radius is not a finite number"
        return "" if f.radius > 0 else "radius must be positive, got %g" % f.radius
    if f.kind == BLOCK:
        extents = (f.min_x, f.max_x, f.min_y, f.max_y)
        if not all(math.isfinite(v) for v in extents):
            return "block extents must be finite numbers"
        if not (f.min_x < f.max_x and f.min_y < f.max_y):
            return ("block must have min_x < max_x and min_y < max_y, got x [%g, %g], y [%g, %g]"
                    % extents)
        return ""
    if f.kind == POLYGON:
        return polygon_problem(f.points)
    return "unknown footprint kind '%s'" % (f.kind,)


def polygon_problem(points):
    """"" when `points` make a simple polygon with area, else the reason."""
    if len(points) < 3:
        return "a polygon footprint needs at least 3 points, got %d" % len(points)
    if not all(math.isfinite(c) for p in points for c in p):
        return "polygon points must be finite numbers"
    if abs(signed_area(points)) < _EPS:
        return "polygon has zero area"
    if self_intersecting(points):
        return "polygon edges cross or touch each other (or two points coincide)"
    return ""


def padded(footprint, padding):
    """The footprint grown by `padding` metres (>= 0) as costmap_2d grows it: a circle's
    radius and a block's extents grow by `padding`; each polygon vertex moves by
    (sign(x) * padding, sign(y) * padding) (costmap_2d's padFootprint; sign(0) = 0)."""
    p = float(padding)
    if p == 0:
        return footprint
    if footprint.kind == CIRCLE:
        return replace(footprint, radius=footprint.radius + p)
    if footprint.kind == BLOCK:
        return replace(footprint, min_x=footprint.min_x - p, max_x=footprint.max_x + p,
                       min_y=footprint.min_y - p, max_y=footprint.max_y + p)
    points = tuple((x + _sign(x) * p, y + _sign(y) * p) for x, y in footprint.points)
    return replace(footprint, points=points)


def padding_problem(padding):
    """"" when `padding` (metres) is a finite number >= 0, else the reason."""
    if isinstance(padding, bool) or not isinstance(padding, (int, float)):
        return "footprint_padding must be a number, got %s" % (padding,)
    if not math.isfinite(padding) or padding < 0:
        return "footprint_padding must be a finite number >= 0, got %g" % padding
    return ""


def outline(footprint):
    """The footprint's outline as a list of (x, y): a block's 4 corners (counter-clockwise), a
    polygon's points; a circle has none."""
    f = footprint
    if f.kind == BLOCK:
        return [(f.max_x, f.min_y), (f.max_x, f.max_y), (f.min_x, f.max_y), (f.min_x, f.min_y)]
    return list(f.points) if f.kind == POLYGON else []


def reach(footprint):
    """The largest distance from the robot's origin to a point of the footprint (metres)."""
    if footprint.kind == CIRCLE:
        return footprint.radius
    return max(math.hypot(x, y) for x, y in outline(footprint))


def describe(footprint):
    """A short human description, e.g. "circle r=0.22 m", "block x [-0.4, 0.9] y [-0.35, 0.35]
    m", "polygon of 5 points"."""
    f = footprint
    if f.kind == CIRCLE:
        return "circle r=%g m" % f.radius
    if f.kind == BLOCK:
        return "block x [%g, %g] y [%g, %g] m" % (f.min_x, f.max_x, f.min_y, f.max_y)
    return "polygon of %d points" % len(f.points)


def signed_area(points):
    """Shoelace area, positive for counter-clockwise points."""
    n = len(points)
    return 0.5 * sum(points[i][0] * points[(i + 1) % n][1] - points[(i + 1) % n][0] * points[i][1]
                     for i in range(n))


def self_intersecting(points):
    """Two edges touch or cross (other than neighbours at their shared vertex, unless they
    fold back onto each other), or an edge has zero length. The core's selfIntersecting()."""
    n = len(points)
    if any(math.dist(points[i], points[(i + 1) % n]) < _EPS for i in range(n)):
        return True
    for i in range(n):
        p1, p2 = points[i], points[(i + 1) % n]
        for j in range(i + 1, n):
            q1, q2 = points[j], points[(j + 1) % n]
            if j == i + 1 or (i == 0 and j == n - 1):
                shared, p_other, q_other = (p2, p1, q2) if j == i + 1 else (p1, p2, q1)
                if _orientation(p_other, shared, q_other) == 0 and _dot(p_other, shared,
                                                                        q_other) > 0:
                    return True
            elif _segments_touch(p1, p2, q1, q2):
                return True
    return False


def _sign(v):
    return (v > 0) - (v < 0)


def _dot(a, origin, b):
    return (a[0] - origin[0]) * (b[0] - origin[0]) + (a[1] - origin[1]) * (b[1] - origin[1])


def _orientation(a, b, c):
    v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return 1 if v > _EPS else (-1 if v < -_EPS else 0)


def _on_segment(a, b, p):
    return (min(a[0], b[0]) - _EPS <= p[0] <= max(a[0], b[0]) + _EPS
            and min(a[1], b[1]) - _EPS <= p[1] <= max(a[1], b[1]) + _EPS)


def _segments_touch(p1, p2, q1, q2):
    o1, o2 = _orientation(p1, p2, q1), _orientation(p1, p2, q2)
    o3, o4 = _orientation(q1, q2, p1), _orientation(q1, q2, p2)
    if o1 != o2 and o3 != o4 and 0 not in (o1, o2, o3, o4):
        return True
    return ((o1 == 0 and _on_segment(p1, p2, q1)) or (o2 == 0 and _on_segment(p1, p2, q2))
            or (o3 == 0 and _on_segment(q1, q2, p1)) or (o4 == 0 and _on_segment(q1, q2, p2)))
