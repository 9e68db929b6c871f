"""Simulated robots that drive their released plan steps, late: the fleet simulator's model, without ROS.

Each robot follows its timeline's states (x, y, yaw) one step at a time, but only through the
states the planner's execution has released to it. A step takes seconds_per_step times a random
factor in [1, 1 + slowdown]; a step that repeats the pose (a wait in the plan) takes no time, as
the execution lets a robot skip waits once it is released. A robot may stop: at random, before a
step (probability stop_probability, for stop_seconds), or held on purpose (hold()). Seeded: the
same seed and calls give the same motion. With uncoordinated=True every state is released and a
wait takes its step's time: the plan driven on its own timing, late, as robots that nobody
coordinates would (a negative control for the execution). A robot may drift (drift()): its pose
leaves its path sideways and comes back, as a robot whose localisation or controller errs.
"""
import math
import random


def lerp_pose(a, b, f):
    """The pose a fraction f of the way from a to b; the yaw turns the shorter way."""
    turn = math.remainder(b[2] - a[2], 2 * math.pi)
    return (a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, math.remainder(a[2] + turn * f, 2 * math.pi))


class SimulatedRobot:
    """One robot: its pose, and where it is on its timeline."""

    def __init__(self, robot_id, pose):
        self.robot_id = robot_id
        self.pose = tuple(pose)
        self.states = []        # the running plan's states, (x, y, yaw)
        self.index = 0          # the last state reached
        self.fraction = 0.0     # of the way to state index + 1
        self.step_seconds = 0.0  # the current step's duration (0: not begun)
        self.stopped_for = 0.0  # seconds left standing still
        self.released = 0
        self.drift = None       # (seconds into it, length in seconds, largest offset in metres)

    def offset_pose(self):
        """The pose as seen from outside: shifted to the robot's left while it drifts (up to the
        largest offset halfway through, then back)."""
        if self.drift is None:
            return self.pose
        t, length, peak = self.drift
        d = peak * (1.0 - abs(2.0 * t / length - 1.0))
        x, y, yaw = self.pose
        return (x - d * math.sin(yaw), y + d * math.cos(yaw), yaw)

    def follow(self, states):
        """Starts a new plan: its first state is where the robot stands (the planner started it there)."""
        self.states = [tuple(s) for s in states]
        self.index, self.fraction, self.step_seconds, self.released = 0, 0.0, 0.0, 0
        if self.states:
            self.pose = self.states[0]

    def revise(self, states):
        """The same plan, re-planned from the state the robot was released to: the states up to
        there are unchanged, so the robot keeps where it is on them and what it was released.
        Where the new states differ at the step the robot is on, it was planned again from where
        it stands (off its path): it stops, its drift ends there, and it goes on from the first
        new state nearest to that pose once it is released again."""
        new = [tuple(s) for s in states]
        span = 2 if self.step_seconds > 0.0 else 1  # the step it is doing, or the state it stands at
        here = self.states[self.index:self.index + span]
        if here and new[self.index:self.index + span] != here:
            x, y, _ = self.offset_pose()
            nearest = min(range(len(new)), key=lambda k: (math.hypot(new[k][0] - x, new[k][1] - y), k))
            self.index, self.fraction, self.step_seconds = nearest, 0.0, 0.0
            self.pose, self.drift, self.released = new[nearest], None, nearest
        self.states = new
        self.released = min(self.released, len(self.states) - 1)

    def arrived(self):
        return not self.states or self.index >= len(self.states) - 1


class FleetSimulation:
    """The fleet's motion: advance(dt) moves every robot along its released states."""

    def __init__(self, seconds_per_step, slowdown=0.0, stop_probability=0.0, stop_seconds=0.0, seed=0,
                 uncoordinated=False):
        if seconds_per_step <= 0 or slowdown < 0 or not 0 <= stop_probability <= 1 or stop_seconds < 0:
            raise ValueError("seconds_per_step > 0, slowdown >= 0, stop_probability in [0, 1], stop_seconds >= 0")
        self.seconds_per_step = seconds_per_step
        self.slowdown = slowdown
        self.stop_probability = stop_probability
        self.stop_seconds = stop_seconds
        self.rng = random.Random(seed)
        self.robots = {}
        self.uncoordinated = uncoordinated
        self.stops = 0  # random stops so far
        self.clock = 0.0
        self.scheduled = []  # (time, robot id, seconds): stops to come, by time
        self.drifts = []     # (time, robot id, seconds, offset): drifts to come, by time

    def add(self, robot_id, pose):
        self.robots[robot_id] = SimulatedRobot(robot_id, pose)

    def follow(self, timelines, seconds_per_step=None):
        """A new plan: robot id -> [(x, y, yaw), ...]. Robots not in it stand still."""
        if seconds_per_step:
            self.seconds_per_step = seconds_per_step
        for robot_id, states in sorted(timelines.items()):
            if robot_id not in self.robots:
                self.add(robot_id, states[0])
            self.robots[robot_id].follow(states)
            if self.uncoordinated:
                self.robots[robot_id].released = len(states) - 1

    def revise(self, timelines):
        """A re-plan merged into the running plan: robot id -> states; robots whose states
        changed follow their new ones from where they are."""
        for robot_id, states in sorted(timelines.items()):
            robot = self.robots.get(robot_id)
            if robot is not None and robot.states != [tuple(s) for s in states]:
                robot.revise(states)

    def release(self, robot_id, released):
        robot = self.robots.get(robot_id)
        if robot is not None and robot.states:
            robot.released = max(robot.released, min(int(released), len(robot.states) - 1))

    def hold(self, robot_id, seconds):
        """Stops the robot where it is for `seconds` (a fault: a person in the way)."""
        robot = self.robots[robot_id]
        robot.stopped_for = max(robot.stopped_for, seconds)

    def start_drift(self, robot_id, seconds, offset):
        """The robot drifts off its path sideways, up to `offset` metres halfway through
        `seconds`, and back (a fault)."""
        self.robots[robot_id].drift = (0.0, float(seconds), float(offset))

    def schedule_stops(self, count, within, seconds):
        """`count` stops of `seconds`, each of a random robot at a random time in the next
        `within` seconds (a person in the way, a door to open)."""
        ids = sorted(self.robots)
        for _ in range(count if ids else 0):
            self.scheduled.append((self.clock + self.rng.uniform(0.0, within), self.rng.choice(ids), seconds))
        self.scheduled.sort()

    def schedule_drifts(self, count, within, seconds, offset):
        """`count` drifts (start_drift) of a random robot each, at random times in the next
        `within` seconds (a localisation or controller fault while it drives: a robot that has
        arrived by then does not drift)."""
        ids = sorted(self.robots)
        for _ in range(count if ids else 0):
            self.drifts.append((self.clock + self.rng.uniform(0.0, within), self.rng.choice(ids), seconds, offset))
        self.drifts.sort()

    def advance(self, dt):
        self.clock += dt
        while self.scheduled and self.scheduled[0][0] <= self.clock:
            _, robot_id, seconds = self.scheduled.pop(0)
            self.hold(robot_id, seconds)
            self.stops += 1
        while self.drifts and self.drifts[0][0] <= self.clock:
            _, robot_id, seconds, offset = self.drifts.pop(0)
            if not self.robots[robot_id].arrived():
                self.start_drift(robot_id, seconds, offset)
        for robot_id in sorted(self.robots):
            robot = self.robots[robot_id]
            self._advance(robot, dt)
            if robot.drift is not None:
                t, length, peak = robot.drift
                robot.drift = (t + dt, length, peak) if t + dt < length else None

    def _advance(self, robot, dt):
        while dt > 0 and not robot.arrived():
            if robot.stopped_for > 0:
                spent = min(dt, robot.stopped_for)
                robot.stopped_for -= spent
                dt -= spent
                continue
            if robot.index >= robot.released:
                return  # waits for its release
            here, there = robot.states[robot.index], robot.states[robot.index + 1]
            if robot.step_seconds == 0.0:  # the step begins: draw its duration, and maybe a stop
                if here == there and not self.uncoordinated:  # a wait of the plan: nothing to drive
                    robot.index += 1
                    continue
                robot.step_seconds = self.seconds_per_step * (1.0 + self.rng.uniform(0.0, self.slowdown))
                if self.stop_probability and self.rng.random() < self.stop_probability:
                    self.stops += 1
                    robot.stopped_for = self.stop_seconds
                    continue
            left = (1.0 - robot.fraction) * robot.step_seconds
            if dt < left:
                robot.fraction += dt / robot.step_seconds
                robot.pose = lerp_pose(here, there, robot.fraction)
                return
            dt -= left
            robot.index += 1
            robot.fraction, robot.step_seconds = 0.0, 0.0
            robot.pose = there
