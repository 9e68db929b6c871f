"""Conversions between the helpers' plain types and ROS messages (the only helper module that
needs the generated messages: build the package and source its devel space first).
"""
import math

from geometry_msgs.msg import Point32, Pose2D, Quaternion
from nav_msgs.msg import MapMetaData, OccupancyGrid

from fleet_planner.errors import InputError
from fleet_planner.footprint import (BLOCK, CIRCLE, POLYGON, Footprint, id_problem,
                                     padding_problem, shape_problem)
from fleet_planner.msg import RobotFootprint, RobotTask

_KIND_OF_TYPE = {RobotFootprint.CIRCLE: CIRCLE, RobotFootprint.BLOCK: BLOCK,
                 RobotFootprint.POLYGON: POLYGON}
_TYPE_OF_KIND = {kind: type_ for type_, kind in _KIND_OF_TYPE.items()}


def footprint_to_msg(footprint):
    """A Footprint (padding applied) as a fleet_planner/RobotFootprint."""
    msg = RobotFootprint(robot_id=footprint.robot_id, type=_TYPE_OF_KIND[footprint.kind])
    if footprint.kind == CIRCLE:
        msg.radius = footprint.radius
    elif footprint.kind == BLOCK:
        msg.min_x, msg.max_x = footprint.min_x, footprint.max_x
        msg.min_y, msg.max_y = footprint.min_y, footprint.max_y
    else:
        msg.points = [Point32(x=x, y=y, z=0.0) for x, y in footprint.points]
    return msg


def footprint_from_msg(msg, source="request"):
    """A RobotFootprint message as a Footprint, checked as the fleet file is checked.
    Raises InputError(source, 0, reason, robot) for an unknown type, a bad id or shape."""
    problem = id_problem(msg.robot_id)
    if problem:
        raise InputError(source, 0, "robot_id: " + problem)
    kind = _KIND_OF_TYPE.get(msg.type)
    if kind is None:
        raise InputError(source, 0, "unknown footprint type %d (CIRCLE=0, BLOCK=1, POLYGON=2)"
                         % msg.type, msg.robot_id)
    if kind == CIRCLE:
        footprint = Footprint(msg.robot_id, kind, radius=msg.radius, source=source)
    elif kind == BLOCK:
        footprint = Footprint(msg.robot_id, kind, min_x=msg.min_x, max_x=msg.max_x,
                              min_y=msg.min_y, max_y=msg.max_y, source=source)
    else:
        points = tuple((float(p.x), float(p.y)) for p in msg.points)
        footprint = Footprint(msg.robot_id, kind, points=points, source=source)
    problem = shape_problem(footprint)
    if problem:
        raise InputError(source, 0, problem, msg.robot_id)
    return footprint


def check_padding(padding, robot_id, source="request"):
    """Raises InputError unless `padding` is a finite number >= 0."""
    problem = padding_problem(padding)
    if problem:
        raise InputError(source, 0, problem.replace("footprint_padding", "padding"), robot_id)


def yaw_quaternion(yaw):
    return Quaternion(x=0.0, y=0.0, z=math.sin(yaw / 2.0), w=math.cos(yaw / 2.0))


def map_metadata(occupancy_map, stamp):
    """The nav_msgs/MapMetaData of a map_yaml.OccupancyMap; `stamp` is its load time."""
    info = MapMetaData(map_load_time=stamp, resolution=occupancy_map.resolution,
                       width=occupancy_map.width, height=occupancy_map.height)
    x, y, yaw = occupancy_map.origin
    info.origin.position.x, info.origin.position.y = x, y
    info.origin.orientation = yaw_quaternion(yaw)
    return info


def occupancy_grid(occupancy_map, frame_id, stamp):
    """The nav_msgs/OccupancyGrid of a map_yaml.OccupancyMap."""
    grid = OccupancyGrid(info=map_metadata(occupancy_map, stamp), data=occupancy_map.data)
    grid.header.frame_id = frame_id
    grid.header.stamp = stamp
    return grid


def task_to_msg(task):
    """A tasks_config.Task as a fleet_planner/RobotTask."""
    msg = RobotTask(robot_id=task.robot_id, goal=Pose2D(*task.goal),
                    start_from_tf=task.start_from_tf)
    if task.start is not None:
        msg.start = Pose2D(*task.start)
    return msg
