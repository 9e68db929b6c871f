"""The fleet file: every robot's footprint, in costmap_2d's conventions, without ROS.

```yaml
robots:
  - id: amr_1
    robot_radius: 0.35            # a circle, metres
    footprint_padding: 0.02       # optional, default 0
  - id: tug_1
    footprint: [[0.5, 0.3], [-0.5, 0.3], [-0.5, -0.3], [0.5, -0.3]]   # polygon, robot frame
  - id: forklift_1
    block: {min_x: -0.4, max_x: 0.9, min_y: -0.35, max_y: 0.35}      # rectangle
```

Each robot has an `id` (a ROS name: letter, then letters, digits, '_'; unique) and exactly one
of `robot_radius`, `footprint` (at least 3 [x, y] points; a string holding such a list is
accepted too, as costmap_2d does) and `block`. `footprint_padding` (>= 0) is applied as
costmap_2d applies it (see footprint.padded). Anything else is an error naming the file, the
line and the robot.
"""
import math

import yaml

from fleet_planner.errors import InputError
from fleet_planner.footprint import (BLOCK, CIRCLE, POLYGON, Footprint, id_problem, padded,
                                     padding_problem, shape_problem)
from fleet_planner.yaml_fields import Fields, is_number, load_yaml_file, parse_yaml

ROBOT_KEYS = ("id", "robot_radius", "footprint", "block", "footprint_padding")
SHAPE_KEYS = ("robot_radius", "footprint", "block")
BLOCK_KEYS = ("min_x", "max_x", "min_y", "max_y")


def load_fleet(path):
    """The robots of a fleet file as padded Footprints, in file order. Raises InputError."""
    return fleet_from_yaml(load_yaml_file(path), path)


def parse_fleet(text, source):
    """Like load_fleet, for YAML text; `source` names it in messages."""
    return fleet_from_yaml(parse_yaml(text, source), source)


def fleet_from_yaml(root, source):
    """The robots of a parsed fleet file (yaml_fields' marked mappings give the lines)."""
    if root is None:
        raise InputError(source, 0, "the fleet file is empty: expected a 'robots' list")
    top = Fields(root, source, "the fleet file", ("robots",))
    robots = top.require("robots")
    if not isinstance(robots, list):
        raise top.error("robots", "robots must be a list of robots")
    fleet, lines = [], {}
    for index, entry in enumerate(robots):
        line = robots.line_of(index) if hasattr(robots, "line_of") else 0
        footprint = robot_from_yaml(entry, source, index, line)
        if footprint.robot_id in lines:
            raise InputError(source, line, "id '%s' is already used at line %d"
                             % (footprint.robot_id, lines[footprint.robot_id]),
                             footprint.robot_id)
        lines[footprint.robot_id] = line
        fleet.append(footprint)
    return fleet


def robot_from_yaml(entry, source, index, line=0):
    """One entry of `robots` (the index-th, at `line`) as a padded Footprint."""
    label = "robot entry %d" % (index + 1)
    robot_id = entry.get("id") if isinstance(entry, dict) else None
    named = isinstance(robot_id, str) and not id_problem(robot_id)
    fields = Fields(entry, source, label, ROBOT_KEYS, robot_id if named else None, line)
    fields.require("id")
    if not named:
        raise fields.error("id", "%s: %s" % (label, id_problem(robot_id)))
    shapes = [key for key in SHAPE_KEYS if fields.has(key)]
    if len(shapes) != 1:
        raise fields.error(shapes[1] if len(shapes) > 1 else None,
                           "needs exactly one of robot_radius, footprint, block; got %s"
                           % (", ".join(shapes) or "none"))
    where = "%s:%d" % (source, fields.line(shapes[0]))
    footprint = _shape(fields, shapes[0], robot_id, where)
    problem = shape_problem(footprint)
    if problem:
        raise fields.error(shapes[0], "%s: %s" % (shapes[0], problem))
    padding = fields.number("footprint_padding", 0.0)
    problem = padding_problem(padding)
    if problem:
        raise fields.error("footprint_padding", problem)
    grown = padded(footprint, padding)
    problem = shape_problem(grown)
    if problem:
        raise fields.error("footprint_padding", "after padding by %g: %s" % (padding, problem))
    return grown


def _shape(fields, key, robot_id, where):
    if key == "robot_radius":
        return Footprint(robot_id, CIRCLE, radius=fields.number(key), source=where)
    if key == "block":
        block = Fields(fields.mapping[key], fields.source, "block", BLOCK_KEYS, robot_id,
                       fields.line(key))
        values = {name: block.number(name) for name in BLOCK_KEYS}
        return Footprint(robot_id, BLOCK, source=where, **values)
    return Footprint(robot_id, POLYGON, points=_points(fields, key), source=where)


def _points(fields, key):
    """The [[x, y], ...] list at `key` (or a string holding one, as costmap_2d accepts)."""
    value = fields.mapping[key]
    if isinstance(value, str):
        try:
            value = yaml.safe_load(value)
        except yaml.YAMLError:
            raise fields.error(key, "footprint string is not a list [[x, y], ...]: '%s'"
                               % fields.mapping[key])
    if not isinstance(value, list):
        raise fields.error(key, "footprint must be a list of [x, y] points")
    points = []
    for i, point in enumerate(value):
        line = value.line_of(i) if hasattr(value, "line_of") else fields.line(key)
        if not isinstance(point, list) or len(point) != 2:
            raise InputError(fields.source, line, "footprint point %d must be [x, y], got %s"
                             % (i + 1, point), fields.robot)
        for c, axis in zip(point, "xy"):
            if not is_number(c) or not math.isfinite(c):
                raise InputError(fields.source, line, "footprint point %d: %s must be a finite "
                                 "number, got %s" % (i + 1, axis, c), fields.robot)
        points.append((float(point[0]), float(point[1])))
    return tuple(points)
