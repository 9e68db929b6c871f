"""Tests of fleet_planner.fleet_simulation (the fleet simulator's model). No ROS master needed.

Run: PYTHONPATH=src /usr/bin/python3 -m unittest discover -s test/python
"""
import math
import unittest

from fleet_planner.fleet_simulation import FleetSimulation, lerp_pose

LINE = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 0.0, 0.0), (2.0, 0.0, 0.0), (2.0, 0.0, math.pi / 2)]


def run(sim, seconds, dt=0.05):
    for _ in range(int(round(seconds / dt))):
        sim.advance(dt)


class Drifts(unittest.TestCase):
    def test_a_drifting_robot_leaves_its_path_sideways_and_comes_back(self):
        sim = FleetSimulation(1.0)
        sim.follow({"a": LINE})
        sim.start_drift("a", 4.0, 0.5)
        run(sim, 2.0)  # halfway: the largest offset, to the robot's left (+y at yaw 0)
        x, y, _ = sim.robots["a"].offset_pose()
        self.assertAlmostEqual(x, 0.0, places=6)
        self.assertAlmostEqual(y, 0.5, places=2)
        self.assertEqual(sim.robots["a"].pose, LINE[0])  # the robot's own place on its path
        run(sim, 2.1)
        self.assertEqual(sim.robots["a"].offset_pose(), LINE[0])


    def test_scheduled_drifts_start_within_the_horizon_and_are_seeded(self):
        def drifted(seed):
            sim = FleetSimulation(1.0, seed=seed)
            sim.follow({"a": LINE, "b": [(5.0, 5.0, 0.0)]})
            sim.schedule_drifts(10, 4.0, 2.0, 0.3)
            starts = []
            for k in range(100):
                sim.advance(0.05)
                starts += [(k, r) for r, robot in sorted(sim.robots.items()) if robot.drift and robot.drift[0] == 0.05]
            return starts, sim.drifts
        starts, left = drifted(7)
        self.assertEqual(left, [])
        self.assertTrue(starts and all(k * 0.05 <= 4.0 for k, _ in starts))
        self.assertEqual({r for _, r in starts}, {"a"})  # b has arrived (a plan of one state): it does not drift
        self.assertEqual(drifted(7)[0], starts)


class FollowsRevisions(unittest.TestCase):
    def test_a_revised_robot_keeps_its_place_and_drives_its_new_states(self):
        sim = FleetSimulation(1.0)
        sim.follow({"a": LINE, "b": [(5.0, 5.0, 0.0), (6.0, 5.0, 0.0)]})
        sim.release("a", 1)
        run(sim, 2.0)
        self.assertEqual(sim.robots["a"].index, 1)
        revised = LINE[:2] + [(1.0, 1.0, 0.0)]
        sim.revise({"a": revised, "b": [(5.0, 5.0, 0.0), (6.0, 5.0, 0.0)]})
        self.assertEqual(sim.robots["a"].index, 1)
        self.assertEqual(sim.robots["a"].pose, LINE[1])
        self.assertEqual(sim.robots["b"].index, 0)
        sim.release("a", 2)
        run(sim, 2.0)
        self.assertTrue(sim.robots["a"].arrived())
        self.assertEqual(sim.robots["a"].pose, (1.0, 1.0, 0.0))


    def test_a_robot_planned_again_from_off_its_path_goes_on_from_there(self):
        sim = FleetSimulation(1.0)
        sim.follow({"a": LINE})
        sim.release("a", 3)
        sim.start_drift("a", 4.0, 0.5)
        run(sim, 1.5)  # on its way along the line, drifted to its left
        x, y, yaw = sim.robots["a"].offset_pose()
        self.assertGreater(y, 0.3)
        # Planned again from where it stands: a rest at its cell, then back to the line's end.
        rest = (round(x), 0.5, 0.0)
        revised = [rest, rest, rest, (2.0, 0.5, 0.0), (2.0, 0.0, 0.0)]
        sim.revise({"a": revised})
        robot = sim.robots["a"]
        self.assertIsNone(robot.drift)
        self.assertEqual((robot.index, robot.pose, robot.released), (0, rest, 0))
        run(sim, 2.0)
        self.assertEqual(robot.pose, rest)  # not released yet
        sim.release("a", 4)
        run(sim, 5.0)
        self.assertTrue(robot.arrived())
        self.assertEqual(robot.offset_pose(), (2.0, 0.0, 0.0))


class DrivesReleasedSteps(unittest.TestCase):
    def test_stands_still_until_released(self):
        sim = FleetSimulation(1.0)
        sim.follow({"a": LINE})
        run(sim, 3.0)
        self.assertEqual(sim.robots["a"].pose, LINE[0])
        self.assertEqual(sim.robots["a"].index, 0)

    def test_stops_at_its_release_and_skips_the_plans_waits(self):
        sim = FleetSimulation(1.0)
        sim.follow({"a": LINE})
        sim.release("a", 3)
        run(sim, 1.5)  # the wait (state 1 -> 2) takes no time: halfway to state 3
        self.assertEqual(sim.robots["a"].index, 2)
        self.assertAlmostEqual(sim.robots["a"].pose[0], 1.5, places=6)
        run(sim, 5.0)
        self.assertEqual(sim.robots["a"].index, 3)
        self.assertEqual(sim.robots["a"].pose, LINE[3])
        sim.release("a", 4)
        run(sim, 1.0)
        self.assertTrue(sim.robots["a"].arrived())
        self.assertAlmostEqual(sim.robots["a"].pose[2], math.pi / 2)

    def test_slowdown_makes_steps_longer_within_the_bound(self):
        sim = FleetSimulation(1.0, slowdown=0.5, seed=3)
        sim.follow({"a": LINE})
        sim.release("a", 4)
        run(sim, 2.9)  # three steps of at least 1 s each
        self.assertFalse(sim.robots["a"].arrived())
        run(sim, 1.6)  # and at most 1.5 s each
        self.assertTrue(sim.robots["a"].arrived())

    def test_a_held_robot_stands_for_the_time_held(self):
        sim = FleetSimulation(1.0)
        sim.follow({"a": LINE})
        sim.release("a", 4)
        sim.hold("a", 2.0)
        run(sim, 1.9)
        self.assertEqual(sim.robots["a"].pose, LINE[0])
        run(sim, 3.2)
        self.assertTrue(sim.robots["a"].arrived())

    def test_random_stops_are_counted_and_seeded(self):
        def final(seed):
            sim = FleetSimulation(0.5, slowdown=0.5, stop_probability=0.5, stop_seconds=0.3, seed=seed)
            sim.follow({"a": LINE, "b": list(reversed(LINE))})
            sim.release("a", 4)
            sim.release("b", 4)
            run(sim, 1.7)
            return sim.stops, sim.robots["a"].pose, sim.robots["b"].pose
        self.assertEqual(final(5), final(5))
        self.assertGreater(max(final(s)[0] for s in range(5)), 0)

    def test_uncoordinated_robots_drive_the_plans_timing_waits_included(self):
        sim = FleetSimulation(1.0, uncoordinated=True)
        sim.follow({"a": LINE})
        run(sim, 1.5)  # released without asking; the wait (state 1 -> 2) takes its second
        self.assertEqual(sim.robots["a"].index, 1)
        run(sim, 2.6)
        self.assertTrue(sim.robots["a"].arrived())

    def test_scheduled_stops_hold_robots_within_the_horizon(self):
        sim = FleetSimulation(1.0, seed=2)
        sim.follow({"a": LINE, "b": list(reversed(LINE))})
        sim.schedule_stops(3, 2.0, 10.0)
        sim.release("a", 4)
        sim.release("b", 4)
        run(sim, 2.05)
        self.assertEqual(sim.stops, 3)
        run(sim, 3.0)  # each robot is held at least once for 10 s: neither has arrived
        self.assertFalse(sim.robots["a"].arrived() and sim.robots["b"].arrived())

    def test_yaw_turns_the_shorter_way(self):
        pose = lerp_pose((0, 0, 3.0), (0, 0, -3.0), 0.5)
        self.assertAlmostEqual(abs(pose[2]), math.pi, places=6)


if __name__ == "__main__":
    unittest.main()
