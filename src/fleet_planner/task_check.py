"""Checks tasks against a map and a fleet before planning, without the planner: every start and
goal pose at a cell centre facing along a grid axis, its footprint on free cells of the map,
and no two robots' footprints sharing a cell at the starts, nor at the goals.

Unknown cells (-1) count as blocked, as the planner's default does.
"""
from fleet_planner.footprint_cells import cells_at, pose_cell


def task_problems(occupancy_map, fleet, tasks):
    """A list of problems (strings naming the robot and the pose), empty when all is well.
    `occupancy_map` is a map_yaml.OccupancyMap, `fleet` Footprints, `tasks` tasks_config.Tasks."""
    footprints = {footprint.robot_id: footprint for footprint in fleet}
    problems = []
    taken = {"start": {}, "goal": {}}
    for task in tasks:
        footprint = footprints.get(task.robot_id)
        if footprint is None:
            problems.append("%s: robot '%s' is not in the fleet" % (task.source, task.robot_id))
            continue
        for which, pose in (("start", task.start), ("goal", task.goal)):
            if pose is None:
                continue
            where = "%s: robot '%s' %s %s" % (task.source, task.robot_id, which, _pose(pose))
            try:
                cell_x, cell_y, turns = pose_cell(*pose, occupancy_map.origin,
                                                  occupancy_map.resolution)
            except ValueError as error:
                problems.append("%s: %s" % (where, error))
                continue
            cells = cells_at(footprint, cell_x, cell_y, turns, occupancy_map.resolution)
            blocked = sorted(c for c in cells if not _free(occupancy_map, *c))
            if blocked:
                problems.append("%s: footprint on %d blocked or unknown cells, e.g. %s"
                                % (where, len(blocked), blocked[0]))
            others = sorted({taken[which][c] for c in cells if c in taken[which]})
            if others:
                problems.append("%s: footprint overlaps %s's %s"
                                % (where, ", ".join(others), which))
            taken[which].update((c, task.robot_id) for c in cells)
    return problems


def _free(occupancy_map, x, y):
    m = occupancy_map
    return 0 <= x < m.width and 0 <= y < m.height and m.data[y * m.width + x] == 0


def _pose(pose):
    return "(%g, %g, %g)" % pose
