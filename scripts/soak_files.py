"""The files scripts/fleet_soak writes into its ROS_HOME for a soak (soak_driver.py): the fleet
file of the footprint registry, the simulator's starts, and the launch file of the nodes."""
import os


def fleet_yaml(robots):
    """A fleet file for (id, footprint) pairs (padding already applied)."""
    lines = ["robots:"]
    for robot_id, f in robots:
        lines.append("  - id: %s" % robot_id)
        if f.kind == "circle":
            lines.append("    robot_radius: %.6f" % f.radius)
        elif f.kind == "block":
            lines.append("    block: {min_x: %.6f, max_x: %.6f, min_y: %.6f, max_y: %.6f}"
                         % (f.min_x, f.max_x, f.min_y, f.max_y))
        else:
            lines.append("    footprint: [%s]" % ", ".join("[%.6f, %.6f]" % p for p in f.points))
    return "\n".join(lines) + "\n"


def tasks_yaml(poses):
    lines = ["tasks:"]
    for robot_id, (x, y, yaw) in poses:
        lines += ["  - id: %s" % robot_id, "    start: [%.6f, %.6f, %.6f]" % (x, y, yaw),
                  "    goal: [%.6f, %.6f, %.6f]" % (x, y, yaw)]
    return "\n".join(lines) + "\n"


def launch_xml(args, folder):
    return """<launch>
  <node pkg="fleet_planner" type="map_server" name="map_server" args="{map}"/>
  <node pkg="fleet_planner" type="footprint_registry" name="footprint_registry" args="{folder}/fleet.yaml"/>
  <include file="$(find fleet_planner)/launch/planner.launch">
    <arg name="execute" value="true"/>
    <arg name="seconds_per_step" value="{sps}"/>
    <arg name="output" value="log"/>
  </include>
  <node pkg="fleet_planner" type="fleet_simulator" name="fleet_simulator">
    <param name="tasks_file" value="{folder}/starts.yaml"/>
    <param name="rate" value="50"/>
    <param name="slowdown" value="{slowdown}"/>
    <param name="stops_per_plan" value="{stops}"/>
    <param name="drifts_per_plan" value="{drifts}"/>
    <param name="drift_offset" value="0.4"/>
    <param name="stop_probability" value="{stop_probability}"/>
    <param name="stop_seconds" value="{stop_seconds}"/>
    <param name="seed" value="{seed}"/>
    <param name="uncoordinated" value="{uncoordinated}"/>
  </node>
  <param name="/fleet_planner/blocked_timeout" value="{blocked_timeout}"/>
  <param name="/fleet_planner/replan_blocked" value="{replan}"/>
</launch>
""".format(map=os.path.abspath(args.map), folder=folder, sps=args.seconds_per_step, slowdown=args.slowdown,
           stops=0 if args.live_goals else args.stops, stop_seconds=args.stop_seconds, seed=args.seed,
           drifts=0 if args.live_goals else args.drifts,
           stop_probability=args.stops / (100.0 * args.robots) if args.live_goals else 0.0,
           uncoordinated="true" if args.uncoordinated else "false", blocked_timeout=args.blocked_timeout,
           replan="false" if args.no_replan else "true")
