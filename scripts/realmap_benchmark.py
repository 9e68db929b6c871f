#!/usr/bin/python3
"""realmap_benchmark: random fleets of real robots on real SLAM maps, planned with the default
lattice and with lattice step 1 on the same instances.

Usage: scripts/realmap_benchmark.py [--realmaps DIR] [--counts 10 30 50] [--seeds 1 2 3]
                                    [--time-limit 60] [--out results.csv] [--cli PATH]
                                    [--flags SOLVE_FLAGS...]

For every map (DIR/*.yaml, default ../shared/realmaps), count and seed: a scenario of that many
robots of DIR/real_robots.yaml at random free poses and random yaw (scripts/realmap_scenario.py),
solved by `fleet_planner_cli solve` with its defaults (the node's) and again with --lattice-step 1.
A run is answered when it is SUCCESS with a valid plan or INFEASIBLE with a reason. soc_cells is
the sum of costs in the time of a one-cell move (SOC x plan step: plans come on steps of one
cell unless --lattice-timing; SOC x lattice step for a plan on the lattice's steps): it compares
plans made on different lattices. Prints one line per run, then a summary per map and count (answered, median
time, and where both solve: median speed-up and SOC ratio), and writes every run to --out (CSV).
"""
import argparse
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, ".."))
COLUMNS = ["map", "robots", "seed", "config", "status", "valid", "lattice_step", "backward", "time_s", "soc", "soc_cells",
           "makespan", "lattice_notes", "reason", "plan_step"]


def solve(cli, scenario, extra, time_limit):
    argv = [cli, "solve", "--instance", scenario, "--time-limit", str(time_limit)] + extra
    t0 = time.monotonic()
    run = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True,
                         timeout=time_limit + 60)
    wall = time.monotonic() - t0
    try:
        j = json.loads(run.stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        return {"status": "ERROR", "reason": (run.stderr or run.stdout).strip()[:300], "time_s": wall}
    soc = j.get("soc")
    plan_step = j.get("plan_step", j.get("lattice_step", 1))  # the CLI before plan_step: the lattice's
    return {"status": j["status"], "valid": j.get("valid"), "lattice_step": j.get("lattice_step"),
            "backward": j.get("backward"),
            "time_s": j.get("time_s", wall), "soc": soc, "makespan": j.get("makespan"),
            "soc_cells": soc * plan_step if soc is not None else None, "plan_step": plan_step,
            "lattice_notes": " | ".join(j.get("lattice_notes", []))[:300], "reason": (j.get("reason") or "")[:300]}


def answered(row):
    return (row["status"] == "SUCCESS" and row.get("valid")) or (row["status"] == "INFEASIBLE" and row.get("reason"))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--realmaps", default=os.path.normpath(os.path.join(REPO, "..", "shared", "realmaps")))
    p.add_argument("--counts", nargs="+", type=int, default=[10, 30, 50])
    p.add_argument("--seeds", nargs="+", type=int, default=[1, 2, 3])
    p.add_argument("--time-limit", type=float, default=60.0)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--out", default="realmap_benchmark.csv")
    p.add_argument("--flags", nargs=argparse.REMAINDER, default=[],
                   help="further flags of `solve` for both configurations (last on the line), e.g. --flags --lattice-timing")
    p.add_argument("--cli", default=os.path.join(REPO, "build", "devel", "lib", "fleet_planner", "fleet_planner_cli"))
    args = p.parse_args(argv)
    fleet = os.path.join(args.realmaps, "real_robots.yaml")
    maps = sorted(f for f in os.listdir(args.realmaps) if f.endswith(".yaml") and f != "real_robots.yaml")
    rows = []
    with tempfile.TemporaryDirectory(prefix="realmap_") as folder, open(args.out, "w", newline="") as out:
        writer = csv.DictWriter(out, COLUMNS, extrasaction="ignore")
        writer.writeheader()
        for name in maps:
            for count in args.counts:
                for seed in args.seeds:
                    scenario = os.path.join(folder, "%s_%d_%d.yaml" % (name[:-5], count, seed))
                    made = subprocess.run([sys.executable, os.path.join(HERE, "realmap_scenario.py"), "--map",
                                           os.path.join(args.realmaps, name), "--fleet", fleet, "--robots",
                                           str(count), "--seed", str(seed), "--out", scenario],
                                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
                    if made.returncode != 0:
                        print("%s %d robots seed %d: no scenario: %s" % (name, count, seed, made.stdout.strip()))
                        continue
                    for config, extra in (("default", []), ("step1", ["--lattice-step", "1"])):
                        row = solve(args.cli, scenario, extra + ["--threads", str(args.threads)] + args.flags,
                                    args.time_limit)
                        row.update(map=name[:-5], robots=count, seed=seed, config=config)
                        rows.append(row)
                        writer.writerow(row)
                        out.flush()
                        print("%-12s %3d robots seed %d %-7s %-10s step %s %6.2f s SOC %s (cells %s) %s" % (
                            row["map"], count, seed, config, row["status"], row.get("lattice_step"), row["time_s"],
                            row.get("soc"), row.get("soc_cells"), row.get("lattice_notes") or row.get("reason") or ""),
                            flush=True)
    print("\nsummary (answered: SUCCESS with a valid plan or INFEASIBLE with a reason)")
    print("| map | robots | default: answered | median s | step 1: answered | median s | speed-up (both solved) | SOC ratio (cells) |")
    print("|---|---|---|---|---|---|---|---|")
    for name in sorted({r["map"] for r in rows}):
        for count in args.counts:
            def runs(config):
                return [r for r in rows if r["map"] == name and r["robots"] == count and r["config"] == config]
            d, s = runs("default"), runs("step1")
            if not d:
                continue
            both = [(a, b) for a in d for b in s if a["seed"] == b["seed"] and a["status"] == "SUCCESS"
                    and b["status"] == "SUCCESS"]
            med = lambda xs: "%.2f" % statistics.median(xs) if xs else "-"
            print("| %s | %d | %d/%d | %s | %d/%d | %s | %s | %s |" % (
                name, count, sum(bool(answered(r)) for r in d), len(d), med([r["time_s"] for r in d]),
                sum(bool(answered(r)) for r in s), len(s), med([r["time_s"] for r in s]),
                med([b["time_s"] / a["time_s"] for a, b in both]) + "x" if both else "-",
                med([a["soc_cells"] / b["soc_cells"] for a, b in both]) if both else "-"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
