"""The tasks file: a start and a goal pose per robot, for a PlanFleet request, without ROS.

```yaml
# Poses in the map frame: [x, y, yaw], metres and radians.
tasks:
  - id: amr_1
    start: [1.1, 2.3, 0.0]
    goal: [20.1, 5.3, 3.141592653589793]
  - id: tug_1
    start_from_tf: true           # start from TF (map -> tug_1/base_link) instead of `start`
    goal: [4.1, 8.3, 1.5707963267948966]
```

Each task has an `id` (unique), a `goal`, and either a `start` or `start_from_tf: true`. Other
keys are errors naming the file, the line and the robot.
"""
from dataclasses import dataclass

from fleet_planner.errors import InputError
from fleet_planner.footprint import id_problem
from fleet_planner.yaml_fields import Fields, load_yaml_file, parse_yaml

TASK_KEYS = ("id", "start", "goal", "start_from_tf")


@dataclass(frozen=True)
class Task:
    """One robot's task; poses are (x, y, yaw) tuples, `start` None when `start_from_tf`."""

    robot_id: str
    start: tuple
    goal: tuple
    start_from_tf: bool = False
    source: str = ""


def load_tasks(path):
    """The tasks of a tasks file, in file order. Raises InputError."""
    return tasks_from_yaml(load_yaml_file(path), path)


def parse_tasks(text, source):
    """Like load_tasks, for YAML text; `source` names it in messages."""
    return tasks_from_yaml(parse_yaml(text, source), source)


def tasks_from_yaml(root, source):
    if root is None:
        raise InputError(source, 0, "the tasks file is empty: expected a 'tasks' list")
    top = Fields(root, source, "the tasks file", ("tasks",))
    entries = top.require("tasks")
    if not isinstance(entries, list) or not entries:
        raise top.error("tasks", "tasks must be a non-empty list of tasks")
    tasks, lines = [], {}
    for index, entry in enumerate(entries):
        line = entries.line_of(index) if hasattr(entries, "line_of") else 0
        task = _task(entry, source, index, line)
        if task.robot_id in lines:
            raise InputError(source, line, "robot already has a task at line %d"
                             % lines[task.robot_id], task.robot_id)
        lines[task.robot_id] = line
        tasks.append(task)
    return tasks


def _task(entry, source, index, line):
    label = "task %d" % (index + 1)
    robot_id = entry.get("id") if isinstance(entry, dict) else None
    named = isinstance(robot_id, str) and not id_problem(robot_id)
    fields = Fields(entry, source, label, TASK_KEYS, robot_id if named else None, line)
    fields.require("id")
    if not named:
        raise fields.error("id", "%s: %s" % (label, id_problem(robot_id)))
    from_tf = fields.mapping.get("start_from_tf", False)
    if not isinstance(from_tf, bool):
        raise fields.error("start_from_tf", "start_from_tf must be true or false")
    if from_tf and fields.has("start"):
        raise fields.error("start", "give either start or start_from_tf: true, not both")
    start = None if from_tf else _pose(fields, "start")
    return Task(robot_id, start, _pose(fields, "goal"), from_tf, "%s:%d" % (source, line))


def _pose(fields, key):
    value = fields.require(key)
    if not isinstance(value, list) or len(value) != 3:
        raise fields.error(key, "%s must be [x, y, yaw] (metres, radians)" % key)
    return tuple(fields.check_number(v, key, "%s %s" % (key, name))
                 for v, name in zip(value, ("x", "y", "yaw")))
