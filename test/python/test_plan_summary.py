"""Tests of fleet_planner.plan_summary on a hand-made response (no ROS needed).

Run: PYTHONPATH=src /usr/bin/python3 -m unittest discover -s test/python
"""
import unittest
from types import SimpleNamespace as S

from fleet_planner.plan_summary import constant_names, format_summary


class FakeResponse:
    """Constants as a generated srv response class has them."""
    SUCCESS = 0
    TIMEOUT = 1
    _has_header = False
    _type = "fleet_planner/PlanFleetResponse"


class FakeResult:
    OK = 0
    INVALID_START = 2


class Summary(unittest.TestCase):
    def test_constant_names(self):
        self.assertEqual(constant_names(FakeResponse), {0: "SUCCESS", 1: "TIMEOUT"})

    def test_summary_lists_status_robots_subproblems_and_statistics(self):
        response = S(
            status=0, message="planned 2 robots",
            robots=[S(robot_id="amr_1", status=0, message="planned"),
                    S(robot_id="tug_1", status=2, message="start in collision")],
            timelines=[S(robot_id="amr_1", cost=12)],
            subproblems=[S(index=0, cluster=1, level=0, robot_ids=["amr_1", "tug_1"],
                           status="SUCCESS", solve_time=0.0123, delay=2)],
            statistics=S(robots=2, precompute_time=0.01, decomposition_time=0.002,
                         solve_time=0.05, total_time=0.07, soc=30, makespan=-1, subproblems=1,
                         largest_subproblem=2))
        text = format_summary(response, constant_names(FakeResponse), constant_names(FakeResult))
        self.assertEqual(text.splitlines(), [
            "status: SUCCESS",
            "message: planned 2 robots",
            "robots (2):",
            "  amr_1  OK             cost   12 steps",
            "  tug_1  INVALID_START  start in collision",
            "subproblems (1), in solving order:",
            "  #0  cluster 1  level 0  SUCCESS  0.012 s  delay 2  robots: amr_1, tug_1",
            "statistics:",
            "  robots 2, subproblems 1, largest subproblem 2",
            "  time: precompute 0.010 s, decomposition 0.002 s, solve 0.050 s, total 0.070 s",
            "  SOC 30 steps, makespan - (no plan)",
        ])

    def test_a_plan_stopped_at_its_limit_shows_its_bound(self):
        response = S(status=0, message="", robots=[], timelines=[],
                     subproblems=[S(index=0, cluster=0, level=0, robot_ids=["a"], status="SUCCESS",
                                    solve_time=1.0, delay=0, lower_bound=63, stopped_early=True),
                                  S(index=1, cluster=0, level=1, robot_ids=["b"], status="SUCCESS",
                                    solve_time=1.0, delay=0, lower_bound=9, stopped_early=False)],
                     statistics=S(robots=2, precompute_time=0, decomposition_time=0, solve_time=0,
                                  total_time=0, soc=74, makespan=40, subproblems=2, largest_subproblem=1))
        lines = format_summary(response, {}, {}).splitlines()
        self.assertEqual(lines[4], "      stopped at its limit: not proven optimal, any plan costs at least 63 steps")
        self.assertTrue(lines[5].startswith("  #1  cluster 0  level 1"))

    def test_unknown_status_numbers_are_shown(self):
        response = S(status=7, message="", robots=[], timelines=[], subproblems=[],
                     statistics=S(robots=0, precompute_time=0, decomposition_time=0,
                                  solve_time=0, total_time=0, soc=-1, makespan=-1,
                                  subproblems=0, largest_subproblem=0))
        self.assertTrue(format_summary(response, {}, {}).startswith("status: UNKNOWN(7)"))


if __name__ == "__main__":
    unittest.main()
