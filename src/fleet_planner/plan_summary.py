"""A human-readable summary of a PlanFleet response, without ROS (duck-typed on the response).

Status numbers are named from the message classes' own constants (`constant_names`), so the
summary follows the .srv/.msg files when they change.
"""


def constant_names(message_class):
    """{value: NAME} of a generated message class's integer constants (e.g. SUCCESS=0)."""
    names = {}
    for name, value in vars(message_class).items():
        if name.isupper() and not name.startswith("_") and isinstance(value, int) \
                and not isinstance(value, bool):
            names.setdefault(value, name)
    return names


def name_of(value, names):
    return names.get(value, "UNKNOWN(%d)" % value)


def format_summary(response, status_names, robot_status_names):
    """The summary as text: fleet status and message, one line per robot (its cost when it has a
    timeline, its message unless it is OK), the subproblems in solving order, and the
    statistics. `status_names` / `robot_status_names` map the
    response's and RobotResult's status numbers to names (see constant_names)."""
    lines = ["status: %s" % name_of(response.status, status_names)]
    if response.message:
        lines.append("message: %s" % response.message)
    lines.append("robots (%d):" % len(response.robots))
    width = max([len(r.robot_id) for r in response.robots] + [5])
    cost = {t.robot_id: t.cost for t in response.timelines}
    for robot in response.robots:
        status = name_of(robot.status, robot_status_names)
        text = "  %-*s  %-13s" % (width, robot.robot_id, status)
        if robot.robot_id in cost:
            text += "  cost %4d steps" % cost[robot.robot_id]
        if robot.message and status != "OK":
            text += "  %s" % robot.message
        lines.append(text.rstrip())
    lines.append("subproblems (%d), in solving order:" % len(response.subproblems))
    for sub in response.subproblems:
        lines.append("  #%d  cluster %d  level %d  %s  %.3f s  delay %d  robots: %s" % (
            sub.index, sub.cluster, sub.level, sub.status or "-", sub.solve_time, sub.delay,
            ", ".join(sub.robot_ids)))
        if getattr(sub, "stopped_early", False):  # LA-CBS at its limit: the best plan it had
            lines.append("      stopped at its limit: not proven optimal, any plan costs at least %d steps"
                         % sub.lower_bound)
    s = response.statistics
    lines.append("statistics:")
    lines.append("  robots %d, subproblems %d, largest subproblem %d"
                 % (s.robots, s.subproblems, s.largest_subproblem))
    lines.append("  time: precompute %.3f s, decomposition %.3f s, solve %.3f s, total %.3f s"
                 % (s.precompute_time, s.decomposition_time, s.solve_time, s.total_time))
    lines.append("  SOC %s, makespan %s" % (_steps(s.soc), _steps(s.makespan)))
    return "\n".join(lines)


def _steps(value):
    return "%d steps" % value if value >= 0 else "- (no plan)"
