#!/usr/bin/python3
"""soak_driver: the rounds of scripts/fleet_soak, which runs it inside its ROS environment.

Usage (through scripts/fleet_soak): --map MAP.yaml --fleet FLEET.yaml --robots N --rounds R
    --seed S --slowdown F --stops K [--stop-seconds 2] [--blocked-timeout 10] [--no-replan]
    [--drifts 0] [--seconds-per-step 0.1] [--time-limit 30] [--round-timeout 600] [--uncoordinated]
    [--live-goals] [--json-out FILE]

The fleet: N robots named <fleet id>_<k>, taking the fleet file's footprints in turn. They start
at random free poses (fleet_planner.pose_sampling). Each round draws a new goal for every robot
(a random free pose at a random yaw that the robot can reach alone from where it stands), plans
the whole fleet from TF (start_from_tf) and waits until the execution reports every robot
arrived. The fleet simulator makes each step up to F slower and holds K random robots for
--stop-seconds during each plan, and --drifts random robots drift up to 0.4 m off their paths
for 6 s (the planner re-plans them from where they stand). The planner re-plans a robot BLOCKED
(waiting longer than --blocked-timeout) around the robot it waits for (replan_blocked;
--no-replan turns it off). A plan that fails gets new goals (up to 3 draws per round).

With --live-goals there is one plan, of every robot's first goal; then each robot, as soon as it
arrives, gets its next goal through the planner's ~add_tasks while the others drive, until every
robot has reached --rounds goals (a goal that cannot be planned is drawn again 2 s later). The
latencies are then the add_tasks calls', replans counts them, and new_goals_planned those merged;
the K stops of a round become a chance of K / (100 N) that a robot stops before a step (about K
stops per N goals of some 100 steps);
deadlocks counts a stop after --round-timeout seconds without any goal reached.

Prints a line per round, then one JSON line: collisions (pairs of robots seen sharing a cell, the
planner's monitor), goals_reached, goals_total, deadlocks (rounds not finished within
--round-timeout), replans (plans made), plan_failures, replan_p50_s and replan_p95_s (plan call
latency), execution_replans and execution_replans_refused (robots re-planned during the execution,
and re-plans that found nothing safe), execution_replan_p50_s and execution_replan_p95_s (their
latency, merged or refused), execution_off_path_replans and execution_off_path_refused (those of
robots off their paths, merged and refused), rss_mb_first (the planner's resident memory after the first round), rss_mb_last,
rss_growth (last / first - 1), rounds_done (fewer than --rounds when interrupted: Ctrl-C ends
the soak with the summary of the rounds done), wall_s. Exit status 1 on a collision or a deadlock.
"""
import argparse
import json
import math
import os
import random
import signal
import subprocess
import sys
import threading
import time
import xmlrpc.client

import rospy
import tf2_ros
from geometry_msgs.msg import Pose2D

# The package's devel space (scripts/fleet_soak sources it): messages and the Python helpers.
from fleet_planner.fleet_config import load_fleet
from fleet_planner.map_yaml import load_map
from fleet_planner.msg import FleetExecution, RobotExecution, RobotTask
from fleet_planner.pose_sampling import PoseSampler
from fleet_planner.srv import AddTasks, AddTasksRequest, AddTasksResponse, PlanFleet, PlanFleetRequest, \
    PlanFleetResponse
from soak_files import fleet_yaml, launch_xml, tasks_yaml



def rss_mb(node):
    """Resident memory of a ROS node (MB), from its pid through the master."""
    try:
        master = xmlrpc.client.ServerProxy(os.environ["ROS_MASTER_URI"])
        _, _, uri = master.lookupNode("/fleet_soak", node)
        _, _, pid = xmlrpc.client.ServerProxy(uri).getPid("/fleet_soak")
        with open("/proc/%d/status" % pid) as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) / 1024.0
    except (OSError, KeyError, ValueError, xmlrpc.client.Error):
        pass
    return None


def percentile(values, q):
    if not values:
        return None
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(math.ceil(q * len(ordered))) - 1)]


class Soak:
    def __init__(self, args):
        self.args = args
        self.rng = random.Random(args.seed)
        self.grid = load_map(args.map)
        self.sampler = PoseSampler(self.grid, self.rng)
        types = load_fleet(args.fleet)
        self.robots = [("%s_%d" % (types[k % len(types)].robot_id, k), types[k % len(types)])
                       for k in range(args.robots)]
        self.last = None
        self.lock = threading.Lock()
        self.execution_replan_times = []  # seconds of each re-plan during the executions
        self.seen_replans = (0, 0, 0)     # (plan, replans, refused) at the last message
        self.off_path = [0, 0]            # re-plans of robots off their paths: merged, refused

    def draw_starts(self):
        taken, poses = [], []
        for robot_id, f in self.robots:
            cell = self.sampler.draw(f, taken)
            if cell is None:
                raise SystemExit("fleet_soak: no room for robot %s" % robot_id)
            taken.append(cell + (self.sampler.radius(f),))
            poses.append((robot_id, self.sampler.metres(cell, self.rng.uniform(-math.pi, math.pi))))
        return poses

    def draw_goals(self, here):
        """A goal per robot that it can reach alone from `here` (robot id -> (x, y)), clear of the others'."""
        taken, goals = [], {}
        for robot_id, f in self.robots:
            region = self.sampler.region_of(f, self.sampler.cell_of(*here[robot_id]))
            cell = self.sampler.draw(f, taken, region)
            if cell is None:
                cell = self.sampler.draw(f, taken)
            if cell is None:
                return None
            taken.append(cell + (self.sampler.radius(f),))
            goals[robot_id] = self.sampler.metres(cell, self.rng.uniform(-math.pi, math.pi))
        return goals

    def draw_goal(self, robot_id, here, goals):
        """A new goal for one robot, reachable alone from `here` (x, y), clear of the other robots'
        goals (robot id -> (x, y, yaw)); None if there is no room."""
        f = dict(self.robots)[robot_id]
        taken = [self.sampler.cell_of(g[0], g[1]) + (self.sampler.radius(dict(self.robots)[r]),)
                 for r, g in goals.items() if r != robot_id]
        cell = self.sampler.draw(f, taken, self.sampler.region_of(f, self.sampler.cell_of(*here)))
        return None if cell is None else self.sampler.metres(cell, self.rng.uniform(-math.pi, math.pi))

    def on_execution(self, msg):
        with self.lock:
            self.last = msg
            plan, replans, refused = self.seen_replans
            if msg.plan != plan:
                replans, refused = 0, 0
            if msg.replans + msg.replans_refused > replans + refused:
                self.execution_replan_times.append(msg.last_replan_time)
                if "(off its path)" in msg.last_replan:
                    self.off_path[0 if msg.replans > replans else 1] += 1
            self.seen_replans = (msg.plan, msg.replans, msg.replans_refused)

    def current(self, tf):
        here = {}
        for robot_id, _ in self.robots:
            t = tf.lookup_transform("map", robot_id + "/base_link", rospy.Time(0), rospy.Duration(10))
            here[robot_id] = (t.transform.translation.x, t.transform.translation.y)
        return here

    def wait_done(self, after_plan):
        deadline = time.monotonic() + self.args.round_timeout
        while time.monotonic() < deadline and not rospy.is_shutdown():
            with self.lock:
                last = self.last
            if last is not None and last.plan > after_plan and last.done:
                return last, True
            time.sleep(0.1)
        with self.lock:
            return self.last, False


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--map", required=True)
    p.add_argument("--fleet", required=True)
    p.add_argument("--robots", type=int, required=True)
    p.add_argument("--rounds", type=int, default=10)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--slowdown", type=float, default=0.5)
    p.add_argument("--stops", type=int, default=5)
    p.add_argument("--stop-seconds", type=float, default=2.0, help="length of each stop")
    p.add_argument("--blocked-timeout", type=float, default=10.0,
                   help="seconds of waiting before a robot is BLOCKED, and re-planned")
    p.add_argument("--no-replan", action="store_true", help="the planner does not re-plan BLOCKED robots")
    p.add_argument("--drifts", type=int, default=0, help="robots drifting off their paths in each round")
    p.add_argument("--live-goals", action="store_true",
                   help="one plan, then each robot gets its next goal (of --rounds) through ~add_tasks as soon "
                        "as it arrives, while the others drive")
    p.add_argument("--seconds-per-step", type=float, default=0.1)
    p.add_argument("--time-limit", type=float, default=30.0)
    p.add_argument("--round-timeout", type=float, default=600.0)
    p.add_argument("--uncoordinated", action="store_true", help="the simulator ignores the releases")
    p.add_argument("--json-out", default="")
    args = p.parse_args(argv)
    # Ctrl-C and SIGTERM end the soak with its summary, also when started in the background
    # (where a non-interactive shell leaves SIGINT ignored).
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    started = time.monotonic()
    soak = Soak(args)
    folder = os.environ["ROS_HOME"]
    with open(os.path.join(folder, "fleet.yaml"), "w") as f:
        f.write(fleet_yaml(soak.robots))
    with open(os.path.join(folder, "starts.yaml"), "w") as f:
        f.write(tasks_yaml(soak.draw_starts()))
    with open(os.path.join(folder, "soak.launch"), "w") as f:
        f.write(launch_xml(args, folder))
    log = open(os.path.join(folder, "launch.log"), "w")
    launch = subprocess.Popen(["roslaunch", "-p", os.environ["FLEET_SOAK_PORT"], os.path.join(folder, "soak.launch")],
                              stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        return run(soak, args, started)
    finally:
        try:
            os.killpg(launch.pid, signal.SIGINT)
            launch.wait(timeout=15)
        except (OSError, subprocess.TimeoutExpired):
            os.killpg(launch.pid, signal.SIGKILL)


def run(soak, args, started):
    deadline = time.monotonic() + 60
    while True:  # the master comes up with roslaunch
        try:
            xmlrpc.client.ServerProxy(os.environ["ROS_MASTER_URI"]).getSystemState("/fleet_soak")
            break
        except OSError:
            if time.monotonic() > deadline:
                raise SystemExit("fleet_soak: no ROS master")
            time.sleep(0.3)
    rospy.init_node("fleet_soak", disable_signals=True)
    rospy.Subscriber("/fleet_planner/execution", FleetExecution, soak.on_execution, queue_size=10)
    tf = tf2_ros.Buffer()
    tf2_ros.TransformListener(tf)
    rospy.wait_for_service("/fleet_planner/plan_fleet", timeout=60)
    plan = rospy.ServiceProxy("/fleet_planner/plan_fleet", PlanFleet)
    totals = dict(collisions=0, goals_reached=0, goals_total=0, deadlocks=0, replans=0, plan_failures=0,
                  execution_replans=0, execution_replans_refused=0)
    latencies, rss_first, plans_done, rounds_done = [], None, 0, 0
    try:
        if args.live_goals:
            rss_first, rounds_done = live_goals(soak, args, plan, tf, totals, latencies)
        else:
            for rnd in range(1, args.rounds + 1):
                rss_first, plans_done = soak_round(soak, args, plan, tf, rnd, totals, latencies, rss_first,
                                                   plans_done)
                rounds_done = rnd
    except KeyboardInterrupt:  # stopped early: the summary of the rounds done
        print("fleet_soak: interrupted after %d rounds" % rounds_done, flush=True)
    rss_last = rss_mb("/fleet_planner")
    result = dict(totals, robots=len(soak.robots), rounds=args.rounds, rounds_done=rounds_done,
                  replan_p50_s=percentile(latencies, 0.5), replan_p95_s=percentile(latencies, 0.95),
                  execution_replan_p50_s=percentile(soak.execution_replan_times, 0.5),
                  execution_replan_p95_s=percentile(soak.execution_replan_times, 0.95),
                  execution_off_path_replans=soak.off_path[0], execution_off_path_refused=soak.off_path[1],
                  rss_mb_first=rss_first, rss_mb_last=rss_last,
                  rss_growth=(rss_last / rss_first - 1.0) if rss_first and rss_last else None,
                  wall_s=time.monotonic() - started)
    line = json.dumps(result, sort_keys=True)
    print(line, flush=True)
    if args.json_out:
        with open(args.json_out, "w") as f:
            f.write(line + "\n")
    return 1 if totals["collisions"] or totals["deadlocks"] else 0


def live_goals(soak, args, plan, tf, totals, latencies):
    """--live-goals: one plan of every robot's first goal, then each robot's next goal through
    ~add_tasks as soon as it arrives, until every robot reached --rounds goals. Latencies are the
    add_tasks calls'. Returns (rss after the first goals, rounds every robot completed)."""
    rospy.wait_for_service("/fleet_planner/add_tasks", timeout=60)
    add = rospy.ServiceProxy("/fleet_planner/add_tasks", AddTasks)
    here = soak.current(tf)
    goals = soak.draw_goals(here)
    if goals is None:
        raise SystemExit("fleet_soak: no room for the first goals")
    tasks = [RobotTask(robot_id=r, start_from_tf=True, goal=Pose2D(*goals[r])) for r, _ in soak.robots]
    request = PlanFleetRequest(tasks=tasks, time_limit=args.time_limit, seed=1)
    for _ in range(100):  # the map and the registry reach the planner asynchronously
        response = plan(request)
        if response.status not in (PlanFleetResponse.NO_MAP, PlanFleetResponse.UNKNOWN_ROBOT):
            break
        time.sleep(0.3)
    totals["replans"] += 1
    if response.status != PlanFleetResponse.SUCCESS:
        raise SystemExit("fleet_soak: the first plan failed: %s" % response.message[:300])
    reached = {r: 0 for r, _ in soak.robots}
    totals["goals_total"] = args.rounds * len(soak.robots)
    rss_first, progress_at, printed, planned = None, time.monotonic(), 0, 0
    retry_at = {}
    try:
        while min(reached.values()) < args.rounds and not rospy.is_shutdown():
            time.sleep(0.2)
            with soak.lock:
                last = soak.last
            if last is None:
                continue
            now = time.monotonic()
            for r in last.robots:
                if r.state != RobotExecution.ARRIVED or reached[r.robot_id] >= args.rounds or r.robot_id not in goals:
                    continue
                if now < retry_at.get(r.robot_id, 0.0):
                    continue
                pose = tf.lookup_transform("map", r.robot_id + "/base_link", rospy.Time(0), rospy.Duration(5))
                x, y = pose.transform.translation.x, pose.transform.translation.y
                goal = goals[r.robot_id]
                if math.hypot(x - goal[0], y - goal[1]) < 0.2 and r.robot_id not in retry_at:
                    reached[r.robot_id] += 1
                    totals["goals_reached"] += 1
                    progress_at = now
                    if min(reached.values()) >= 1 and rss_first is None:
                        rss_first = rss_mb("/fleet_planner")
                retry_at.pop(r.robot_id, None)
                if reached[r.robot_id] >= args.rounds:
                    continue
                new_goal = soak.draw_goal(r.robot_id, (x, y), goals)
                if new_goal is None:
                    retry_at[r.robot_id] = now + 2.0
                    continue
                t0 = time.monotonic()
                answer = add(AddTasksRequest(tasks=[RobotTask(robot_id=r.robot_id, goal=Pose2D(*new_goal))]))
                latencies.append(time.monotonic() - t0)
                totals["replans"] += 1
                if answer.status == AddTasksResponse.SUCCESS:
                    goals[r.robot_id] = new_goal
                    planned += 1
                else:
                    totals["plan_failures"] += 1
                    retry_at[r.robot_id] = now + 2.0  # another goal in a while
            if now - progress_at > args.round_timeout:
                totals["deadlocks"] += 1
                print("fleet_soak: no goal reached for %.0f s: stopping" % args.round_timeout, flush=True)
                break
            done_rounds = min(reached.values())
            if done_rounds > printed:
                printed = done_rounds
                rss = rss_mb("/fleet_planner")
                print("every robot reached %d/%d goals: %d goals, %d collisions, %d new-goal plans (%d failed), %d re-plans "
                      "(%d refused), planner RSS %s MB" % (
                          done_rounds, args.rounds, totals["goals_reached"], last.collisions, totals["replans"],
                          totals["plan_failures"], last.replans, last.replans_refused, "%.1f" % rss if rss else "?"),
                      flush=True)
    except KeyboardInterrupt:  # stopped early: the summary so far
        print("fleet_soak: interrupted with every robot at %d goals or more" % min(reached.values()), flush=True)
    with soak.lock:
        last = soak.last
    totals["collisions"] = last.collisions if last else 0
    totals["new_goals_planned"] = planned
    totals["execution_replans"] = (last.replans if last else 0) - planned  # those of BLOCKED robots
    totals["execution_replans_refused"] = last.replans_refused if last else 0
    return rss_first, min(reached.values())


def soak_round(soak, args, plan, tf, rnd, totals, latencies, rss_first, plans_done):
    """One round: new goals, a plan, its execution. Returns (rss_first, plans_done)."""
    here = soak.current(tf)
    response = None
    for _ in range(3):
        goals = soak.draw_goals(here)
        if goals is None:
            continue
        tasks = [RobotTask(robot_id=r, start_from_tf=True, goal=Pose2D(*goals[r])) for r, _ in soak.robots]
        request = PlanFleetRequest(tasks=tasks, time_limit=args.time_limit, seed=rnd)
        for _ in range(100):  # the map and the registry reach the planner asynchronously
            t0 = time.monotonic()
            response = plan(request)
            if response.status not in (PlanFleetResponse.NO_MAP, PlanFleetResponse.UNKNOWN_ROBOT):
                break
            time.sleep(0.3)
        latencies.append(time.monotonic() - t0)
        totals["replans"] += 1
        if response.status == PlanFleetResponse.SUCCESS:
            break
        totals["plan_failures"] += 1
        print("round %d: plan failed: %s" % (rnd, response.message[:200]), flush=True)
    if response is None or response.status != PlanFleetResponse.SUCCESS:
        return rss_first, plans_done
    t1 = time.monotonic()
    last, done = soak.wait_done(plans_done)
    plans_done = last.plan if last is not None else plans_done
    arrived = sum(r.state == RobotExecution.ARRIVED for r in last.robots) if last else 0
    totals["goals_total"] += len(soak.robots)
    totals["goals_reached"] += arrived
    totals["collisions"] += last.collisions if last else 0
    totals["deadlocks"] += 0 if done else 1
    totals["execution_replans"] += last.replans if last else 0
    totals["execution_replans_refused"] += last.replans_refused if last else 0
    if not done and last is not None:
        for r in last.robots:
            if r.state != RobotExecution.ARRIVED:
                print("  not arrived: %s state %d progress %d/%d released %d blocked by '%s' late %.1f s"
                      % (r.robot_id, r.state, r.progress, r.last_state, r.released, r.blocked_by, r.lateness),
                      flush=True)
    rss = rss_mb("/fleet_planner")
    rss_first = rss if rss_first is None else rss_first
    print("round %d/%d: planned in %.2f s, executed in %.1f s: %d/%d arrived, %d collisions, %d re-plans "
          "(%d refused)%s, planner RSS %s MB"
          % (rnd, args.rounds, latencies[-1], time.monotonic() - t1, arrived, len(soak.robots),
             last.collisions if last else 0, last.replans if last else 0, last.replans_refused if last else 0,
             "" if done else ", NOT DONE", "%.1f" % rss if rss else "?"),
          flush=True)
    return rss_first, plans_done


if __name__ == "__main__":
    sys.exit(main())
