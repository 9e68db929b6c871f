"""fleet_planner_cli plans like the node: `solve` without backend flags uses the node's backend,
fallback and mode (config/planner.yaml), reports them in its JSON, and rejects unknown backend
options by name. Needs $FLEET_PLANNER_CLI (ctest sets it)."""
import json
import os
import subprocess
import tempfile
import unittest

import yaml

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCENARIO = os.path.join(ROOT, "test", "data", "two_robots_open.yaml")


def solve(*flags):
    cli = os.environ.get("FLEET_PLANNER_CLI")
    if not cli:
        raise AssertionError("set FLEET_PLANNER_CLI to the fleet_planner_cli binary")
    return subprocess.run([cli, "solve", "--instance", SCENARIO] + list(flags), stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True, timeout=120)


class CliDefaultsTest(unittest.TestCase):
    def test_solve_without_flags_plans_like_the_node(self):
        with open(os.path.join(ROOT, "config", "planner.yaml")) as f:
            node = yaml.safe_load(f)
        run = solve()
        self.assertEqual(run.returncode, 0, run.stderr)
        j = json.loads(run.stdout)
        self.assertEqual(j["status"], "SUCCESS", j)
        self.assertTrue(j["valid"])
        self.assertEqual(j["backend"], node["backend"])
        self.assertEqual(j["fallback"], node["fallback"])
        self.assertEqual(j["mode"], "layered" if node["decomposition"] else "raw")
        self.assertEqual(j["steps"], "1234"[:node["decomposition_steps"]])
        # A MovingAI map plans in the paper's model: forward moves and turns in place only.
        self.assertFalse(j["backward"])

    def test_the_node_inputs_plan_with_backward_moves_as_the_node_does(self):
        with open(os.path.join(ROOT, "config", "planner.yaml")) as f:
            node = yaml.safe_load(f)
        inputs = ["--map", os.path.join(ROOT, "maps", "warehouse.yaml"),
                  "--fleet", os.path.join(ROOT, "config", "demo_fleet.yaml"),
                  "--tasks", os.path.join(ROOT, "config", "demo_tasks.yaml")]
        for flags, backward in (([], node["allow_backward"]), (["--forward-only"], False)):
            cli = os.environ["FLEET_PLANNER_CLI"]
            run = subprocess.run([cli, "solve"] + inputs + flags, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                 universal_newlines=True, timeout=120)
            self.assertEqual(run.returncode, 0, run.stderr)
            j = json.loads(run.stdout)
            self.assertEqual((j["status"], j["valid"], j["backward"]), ("SUCCESS", True, backward), flags)
        # The plan file says backward moves were allowed, and `check` validates it so; without
        # that line the backward moves are illegal (the demo's plan backs forklift_2 out at its
        # first step).
        with tempfile.TemporaryDirectory() as folder:
            plan = os.path.join(folder, "plan.yaml")
            cli = os.environ["FLEET_PLANNER_CLI"]
            run = subprocess.run([cli, "solve"] + inputs + ["--out", plan], stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, universal_newlines=True, timeout=120)
            self.assertEqual(run.returncode, 0, run.stderr)
            with open(plan) as f:
                text = f.read()
            self.assertIn("\nbackward_moves: true\n", text)
            check = [cli, "check"] + inputs + ["--plan", plan]
            run = subprocess.run(check, stdout=subprocess.PIPE, universal_newlines=True, timeout=120)
            self.assertEqual(run.returncode, 0, run.stdout)
            self.assertTrue(json.loads(run.stdout)["valid"])
            with open(plan, "w") as f:
                f.write(text.replace("backward_moves: true\n", ""))
            run = subprocess.run(check, stdout=subprocess.PIPE, universal_newlines=True, timeout=120)
            self.assertEqual(run.returncode, 1, run.stdout)
            self.assertEqual(json.loads(run.stdout)["violation"], "illegal action")
        run = solve("--backward", "--forward-only")
        self.assertEqual(run.returncode, 2, run.stdout)
        self.assertIn("--forward-only", run.stderr)

    def test_fallback_none_and_backend_options(self):
        run = solve("--mode", "raw", "--backend", "la_cbs", "--fallback", "none",
                    "--backend-param", "la_cbs.max_candidate_conflicts=1")
        self.assertEqual(run.returncode, 0, run.stderr)
        j = json.loads(run.stdout)
        self.assertEqual((j["status"], j["backend"], j["fallback"], j["mode"]), ("SUCCESS", "la_cbs", "", "raw"))

    def test_an_unknown_backend_option_is_named(self):
        run = solve("--backend-param", "la_lns.neighbourhood=3")
        self.assertEqual(run.returncode, 2, run.stdout)
        self.assertIn("neighbourhood", run.stderr)
        self.assertIn("neighborhood_size", run.stderr)  # the known names are listed
        run = solve("--backend-param", "la_lns.neighborhood_size")
        self.assertEqual(run.returncode, 2, run.stdout)
        self.assertIn("BACKEND.OPTION=VALUE", run.stderr)

    def test_generate_feasible_takes_the_solves_sweep_tolerance_and_a_pair_budget(self):
        cli = os.environ["FLEET_PLANNER_CLI"]
        with tempfile.TemporaryDirectory() as folder:
            out = os.path.join(folder, "fleet.yaml")
            base = [cli, "generate", "--map", os.path.join(ROOT, "test", "data", "open_12x8.map"), "--agents", "6",
                    "--seed", "3", "--feasible", "--out", out]
            run = subprocess.run(base + ["--sweep-tolerance", "0.2", "--pair-expansions", "100000"],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True, timeout=120)
            self.assertEqual(run.returncode, 0, run.stderr)
            j = json.loads(run.stdout)
            self.assertTrue(j["feasible_check"])
            self.assertTrue(j["check_clean"], j)
            with open(out) as f:
                self.assertEqual(len(yaml.safe_load(f)["robots"]), 6)
            for bad in (["--sweep-tolerance", "0.3"], ["--pair-expansions", "0"]):
                run = subprocess.run(base + bad, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                     universal_newlines=True, timeout=120)
                self.assertEqual(run.returncode, 2, bad)
                self.assertIn(bad[0], run.stderr + run.stdout)


if __name__ == "__main__":
    unittest.main()
