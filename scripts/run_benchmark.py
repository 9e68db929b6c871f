#!/usr/bin/python3
"""Benchmark driver: sweeps maps x robot counts x methods x backends over fleet_planner_cli.

One CLI process per run, so that time and peak memory are those of the run alone. Each run
becomes one CSV row, written and flushed as soon as it finishes; Ctrl-C stops the sweep and
keeps every finished row; --resume skips the rows already in the CSV.

Solve sweep (default): one row per (map, robots, subset, method, backend, steps, seed).
Decomposition sweep (--decomposition): `decompose --steps 1234 --check` once per (map, robots,
subset, seed), one row per step set 1, 12, 123, 1234 (the steps run in order and each later step
only refines the earlier ones, so the statistics after step k are those of `--steps 1..k`).

Robots: "K mixed" = the first ceil(K/2) circles interleaved with the first floor(K/2) blocks of
the map's pool (the CLI's --agents K). --random-subsets N adds, for every K, N random K-robot
subsets (ceil(K/2) circles and floor(K/2) blocks drawn with seeds 1..N, the same seed passed to
the solver), written as pool files into a temporary folder. --generated N adds, for every K
(even beyond the pool's size), N instances made by `fleet_planner_cli generate` (the paper's
generator distribution) with seeds 1..N; --generated-feasible N the same with `generate
--feasible` (subset "feasible": robots of pairs proven unable to reach both targets drawn again).

Status: the CLI's status (SUCCESS, TIMEOUT, INFEASIBLE, ...), or UNREACHABLE (the CLI rejected
the instance because a robot cannot reach its target: exit 2), BAD_INPUT (other exit 2),
INVALID (the plan failed the independent validator), KILLED (still running at time limit +
grace), CRASH (killed by a signal or no JSON line). Only the standard library is used.
"""
import argparse
import csv
import datetime
import io
import json
import os
import shutil
import platform
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_CLI = os.path.join(REPO, "build", "devel", "lib", "fleet_planner", "fleet_planner_cli")
DEFAULT_BENCHMARK = os.path.normpath(os.path.join(REPO, "..", "shared", "benchmark"))

ALL_MAPS = ["empty-48-48", "maze-128-128-10", "den520d", "Berlin_1_256", "Paris_1_256", "ost003d",
            "AR0044SR", "AR0203SR"]
ALL_COUNTS = [10, 20, 30, 40, 60, 80, 100, 120, 140]
STEP_SETS = ["1", "12", "123", "1234"]

# quick: 4 maps (dense, rooms, maze, city) x K 10/20/40 x 2 methods x 2 backends = 48 solve runs
# at 10 s (at most 48 x (10 + 2 grace) s = 9.6 min), plus the decomposition sweep over every map
# and count (59 runs, each under 3 s on this project's 2-core machine).
PROFILES = {
    "quick": {"maps": ["empty-48-48", "AR0044SR", "maze-128-128-10", "Berlin_1_256"],
              "counts": [10, 20, 40], "time_limit": 10.0, "grace": 2.0, "decomposition_timeout": 30.0,
              "decomposition_maps": ALL_MAPS, "decomposition_counts": ALL_COUNTS},
    "full": {"maps": ALL_MAPS, "counts": ALL_COUNTS, "time_limit": 60.0, "grace": 5.0, "decomposition_timeout": 60.0,
             "decomposition_maps": ALL_MAPS, "decomposition_counts": ALL_COUNTS},
}

SOLVE_COLUMNS = ["map", "robots", "subset", "method", "backend", "steps", "seed", "status", "time_s",
                 "precompute_s", "decompose_s", "solve_s", "soc", "makespan", "subproblems",
                 "largest_subproblem", "decomposition_rate", "merges", "peak_rss_mb", "plan_valid",
                 "wall_s", "wait4_rss_mb", "time_limit", "exit_code", "reason", "refine_s", "waits_removed",
                 "threads"]
SOLVE_KEY = ["map", "robots", "subset", "method", "backend", "steps", "seed"]
DECOMP_COLUMNS = ["map", "robots", "subset", "seed", "steps", "status", "subproblems", "largest",
                  "rate", "step_time_s", "decompose_s", "relations_s", "precompute_s", "wall_s",
                  "peak_rss_mb", "wait4_rss_mb", "legal", "exit_code", "reason"]
DECOMP_KEY = ["map", "robots", "subset", "seed"]


sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_support import (Interrupted, fail, fmt, last_line, map_path, model_args,  # noqa: E402
                               outcome, parse_json_line, pool_path, problem_args, read_pool, run_process)


# --------------------------------------------------------------------------------------------
# Sweeps

def solve_one(args, run, folder):
    name, k, subset, method, backend, steps, seed = run
    plan = os.path.join(folder, "plan.yaml")
    if os.path.exists(plan):
        os.remove(plan)
    problem = problem_args(args.benchmark_dir, name, k, subset, seed, folder, args.cli, args.sweep_tolerance) + model_args(args)
    # "BACKEND+FALLBACK" (e.g. la_lacam+la_lns): the backend with a fallback backend (CLI --fallback).
    primary, _, fallback = backend.partition("+")
    argv = [args.cli, "solve"] + problem + [
        "--backend", primary, "--mode", method, "--time-limit", str(args.time_limit),
        "--seed", str(seed), "--threads", str(args.threads), "--out", plan]
    # Always named: the CLI's own default (the node's, la_lns) would otherwise apply.
    argv += ["--fallback", fallback or "none"]
    for param in args.backend_param:
        argv += ["--backend-param", param]
    if method == "layered":
        argv += ["--steps", steps]
    timeout = args.time_limit + args.grace
    r = run_process(argv, timeout)
    status, reason, j = outcome(r, timeout)
    row = dict(zip(SOLVE_KEY, [name, k, subset, method, backend, steps, seed]))
    row.update(time_s=fmt(r["wall"]), wall_s=fmt(r["wall"]), peak_rss_mb=fmt(r["hwm_mb"], 1), threads=args.threads,
               wait4_rss_mb=fmt(r["wait4_mb"], 1), time_limit=args.time_limit, exit_code=r["code"], reason=reason)
    if j is None:
        row["status"] = status
        return row
    row.update(status=j["status"], time_s=fmt(j.get("time_s")), precompute_s=fmt(j.get("precompute_s")),
               decompose_s=fmt(j.get("decompose_s")), solve_s=fmt(j.get("solve_s")),
               soc=fmt(j.get("soc")), makespan=fmt(j.get("makespan")),
               subproblems=fmt(j.get("subproblems")), largest_subproblem=fmt(j.get("max_subproblem")),
               decomposition_rate=fmt(j.get("decomposition_rate")), merges=len(j.get("merges", [])),
               refine_s=fmt(j.get("refine_s")), waits_removed=fmt(j.get("waits_removed")),
               peak_rss_mb=fmt(max(r["hwm_mb"], j.get("peak_rss_mb") or 0), 1))
    if r["code"] == 1:
        row["status"] = "INVALID"
    if j.get("success"):
        valid = validate(args, problem, plan, row) if args.validate else j.get("valid") is True
        row["plan_valid"] = "true" if valid else "false"
        if args.keep_plans:
            os.makedirs(args.keep_plans, exist_ok=True)
            shutil.copyfile(plan, os.path.join(args.keep_plans, "_".join(str(v) for v in run) + ".yaml"))
    return row


def validate(args, problem, plan, row):
    """The independent validator (`check`) on the written plan; marks the row INVALID if not."""
    r = run_process([args.cli, "check"] + problem + ["--plan", plan], 120)
    j = parse_json_line(r["out"])
    valid = not r["killed"] and r["code"] == 0 and j is not None and j.get("valid") is True
    if not valid:
        row["status"] = "INVALID"
        row["reason"] = "check: " + (j.get("message", "") if j else last_line(r["err"]) or "killed")
    return valid


def decompose_one(args, run, folder):
    name, k, subset, seed = run
    problem = problem_args(args.benchmark_dir, name, k, subset, seed, folder, args.cli, args.sweep_tolerance) + model_args(args)
    argv = [args.cli, "decompose"] + problem + ["--steps", "1234", "--threads", str(args.threads)]
    if args.validate:
        argv.append("--check")
    r = run_process(argv, args.decomposition_timeout)
    status, reason, j = outcome(r, args.decomposition_timeout)
    base = dict(zip(DECOMP_KEY, [name, k, subset, seed]))
    base.update(wall_s=fmt(r["wall"]), peak_rss_mb=fmt(r["hwm_mb"], 1), wait4_rss_mb=fmt(r["wait4_mb"], 1),
                exit_code=r["code"], reason=reason)
    if j is None:
        return [dict(base, steps="1234", status=status)]
    base["peak_rss_mb"] = fmt(max(r["hwm_mb"], j.get("peak_rss_mb") or 0), 1)
    if r["code"] == 1:
        base.update(status="ILLEGAL", reason=j.get("illegal", ""))
    rows, total = [], j["relations_s"]
    for s in j["per_step"]:
        total += s["time_s"]
        rows.append(dict(base, steps=STEP_SETS[s["step"] - 1], status=base.get("status", "OK"),
                         subproblems=s["subproblems"], largest=s["largest"], rate=fmt(s["largest"] / k),
                         step_time_s=fmt(s["time_s"]), decompose_s=fmt(total),
                         relations_s=fmt(j["relations_s"]), precompute_s=fmt(j["precompute_s"]),
                         legal={True: "true", False: "false"}.get(j.get("legal"), "")))
    return rows


def plan_runs(args, decomposition):
    """Every run of the sweep, in order, as key tuples."""
    runs = []
    for name in args.maps:
        circles, blocks = read_pool(pool_path(args.benchmark_dir, name))
        pool = len(circles) + len(blocks)
        for k in args.counts:
            subsets = []
            if k <= pool:
                subsets += [("mixed", s) for s in (args.seeds if not decomposition else [0])]
                subsets += [("random", s) for s in range(1, args.random_subsets + 1)]
            subsets += [("generated", s) for s in range(1, args.generated + 1)]
            subsets += [("feasible", s) for s in range(1, args.generated_feasible + 1)]
            for subset, seed in subsets:
                if decomposition:
                    runs.append((name, k, subset, seed))
                    continue
                for method in args.methods:
                    for backend in args.backends:
                        for steps in (args.steps if method == "layered" else ["-"]):
                            runs.append((name, k, subset, method, backend, steps, seed))
    return runs


def done_keys(path, columns, key):
    """Keys of the rows already in `path` (checking that its header is ours)."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != columns:
            fail("%s has other columns than this sweep writes; use another --out" % path)
        return {tuple(row[c] for c in key) for row in reader}


def progress_text(run, rows, decomposition):
    r = rows[-1]
    if decomposition:
        label = "%s K=%s%s" % (run[0], run[1], "" if run[2] == "mixed" else " (random, seed %d)" % run[3])
        detail = "largest %s, %s subproblems, %s s" % (r.get("largest", "-"), r.get("subproblems", "-"),
                                                      r.get("decompose_s", "-"))
        return "%s: %s %s" % (label, r["status"], detail if r["status"] in ("OK", "ILLEGAL") else r["reason"])
    name, k, subset, method, backend, steps, seed = run
    label = "%s K=%d %s%s %s" % (name, k, method, "" if method == "raw" else "(" + steps + ")", backend)
    if subset != "mixed" or seed != 0:
        label += " (%s, seed %d)" % (subset, seed)
    text = "%s: %s %s s" % (label, r["status"], r["time_s"])
    if r.get("soc"):
        text += " SOC %s" % r["soc"]
    return text + " %s MB" % r["peak_rss_mb"]


def sweep(args):
    decomposition = args.decomposition
    columns, key = (DECOMP_COLUMNS, DECOMP_KEY) if decomposition else (SOLVE_COLUMNS, SOLVE_KEY)
    runs = plan_runs(args, decomposition)
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    exists = os.path.exists(args.out) and os.path.getsize(args.out) > 0
    if exists and not args.resume:
        fail("%s exists: pass --resume to finish it, or choose another --out" % args.out)
    done = done_keys(args.out, columns, key) if exists else set()
    todo = [r for r in runs if tuple(str(x) for x in r) not in done]
    print("%s sweep: %d runs, %d already in %s, %d to do%s" % (
        "decomposition" if decomposition else "solve", len(runs), len(runs) - len(todo), args.out, len(todo),
        "" if decomposition else "; worst case %.1f min (runs x (limit + grace))"
        % (len(todo) * (args.time_limit + args.grace) / 60)), flush=True)
    if args.dry_run:
        for r in todo:
            print(" ", " ".join(str(x) for x in r))
        return 0
    write_meta(args, len(runs))
    t0 = time.monotonic()
    with open(args.out, "a", newline="") as f, tempfile.TemporaryDirectory(prefix="fleet_bench_") as folder:
        if not exists:
            csv.DictWriter(f, fieldnames=columns).writeheader()
            f.flush()
        for i, run in enumerate(todo, 1):
            try:
                rows = decompose_one(args, run, folder) if decomposition else [solve_one(args, run, folder)]
                text = io.StringIO()
                csv.DictWriter(text, fieldnames=columns, extrasaction="raise").writerows(rows)
                f.write(text.getvalue())  # all rows of a run in one write
                f.flush()
                os.fsync(f.fileno())
            except (Interrupted, KeyboardInterrupt):
                print("\ninterrupted: the finished runs are kept in %s; run again with --resume to finish"
                      % args.out, flush=True)
                return 130
            elapsed = time.monotonic() - t0
            eta = elapsed / i * (len(todo) - i)
            print("[%d/%d] %s (eta %s)" % (i + len(runs) - len(todo), len(runs),
                                           progress_text(run, rows, decomposition), duration(eta)), flush=True)
    print("done: %d runs in %s -> %s" % (len(todo), duration(time.monotonic() - t0), args.out), flush=True)
    return 0


def duration(s):
    return "%.0f s" % s if s < 90 else "%.1f min" % (s / 60)


def write_meta(args, runs):
    """<out>.meta.json: when, where and with what the sweep ran (rewritten on --resume)."""
    cpu = ""
    try:
        cpu = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        cpu = next((l.split(":", 1)[1].strip() for l in cpu.splitlines() if l.startswith("Model name")), "")
    except OSError:
        pass
    commit = subprocess.run(["git", "-C", REPO, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip() != ""
    now = datetime.datetime.now().isoformat(timespec="seconds")
    meta = {"date": now, "cpu": cpu,
            "cores": os.cpu_count(), "host": platform.node(), "commit": commit, "dirty": dirty,
            "cli": args.cli, "note": args.note, "benchmark_dir": args.benchmark_dir, "runs": runs,
            "command": " ".join(sys.argv), "settings": {k: v for k, v in vars(args).items() if k != "resume"}}
    path = args.out + ".meta.json"
    if args.resume and os.path.exists(path):
        with open(path) as f:
            old = json.load(f)
        meta["date"] = old.get("date", now)  # when the sweep started
        meta["resumed"] = old.get("resumed", []) + [now]
    with open(path, "w") as f:
        json.dump(meta, f, indent=1)


# --------------------------------------------------------------------------------------------
# Command line

def parse_args(argv):
    p = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="Profiles (explicit flags override them):\n"
               "  quick  solve: empty-48-48, AR0044SR, maze-128-128-10, Berlin_1_256 x K 10, 20, 40 x\n"
               "         {raw, layered} x {la_cbs, la_lacam}, steps 1234, 10 s limit (+2 s grace): 48 runs,\n"
               "         at most 9.6 min even if every run times out; decomposition: all 8 maps, every K\n"
               "         (59 runs, about 1 min).\n"
               "  full   solve: all 8 maps x K 10, 20, 30, 40, 60, 80, 100, 120, 140 up to the pool size x\n"
               "         {raw, layered} x {la_cbs, la_lacam}, 60 s limit (+5 s grace): 236 runs, at most\n"
               "         4.3 h; decomposition: all 8 maps, every K.\n\n"
               "Examples:\n"
               "  scripts/run_benchmark.py --profile quick --out quick.csv\n"
               "  scripts/run_benchmark.py --profile quick --decomposition --out quick-decomposition.csv\n"
               "  scripts/run_benchmark.py --maps den520d --counts 20 40 --methods layered --backends la_lacam \\\n"
               "      --time-limit 60 --random-subsets 5 --out den.csv\n"
               "  scripts/run_benchmark.py --profile full --out full.csv --resume   # after Ctrl-C\n\n"
               "CSV columns: " + ", ".join(SOLVE_COLUMNS) + "\n(--decomposition: " + ", ".join(DECOMP_COLUMNS)
               + ").\nTimes in seconds, memory in MB. peak_rss_mb: the run's peak resident set (VmHWM: the\n"
               "CLI's own figure, or polled from /proc for killed runs); wait4_rss_mb: ru_maxrss from\n"
               "wait4, which Linux never reports below the forking driver's own resident set (~15 MB).\n"
               + __doc__.split("\n\n", 1)[1])
    p.add_argument("--profile", choices=sorted(PROFILES), default="quick", help="preset sweep (default: quick)")
    p.add_argument("--decomposition", action="store_true",
                   help="decomposition-only sweep (decompose --check, steps 1, 12, 123, 1234) instead of solving")
    p.add_argument("--benchmark-dir", default=os.environ.get("FLEET_PLANNER_BENCHMARK", DEFAULT_BENCHMARK),
                   help="folder with maps/ and instances/ (default: $FLEET_PLANNER_BENCHMARK or %s)"
                   % DEFAULT_BENCHMARK)
    p.add_argument("--cli", default=os.environ.get("FLEET_PLANNER_CLI", DEFAULT_CLI),
                   help="fleet_planner_cli binary (default: $FLEET_PLANNER_CLI or %s)" % DEFAULT_CLI)
    p.add_argument("--out", help="CSV file (default: benchmark-<profile>[-decomposition].csv)")
    p.add_argument("--resume", action="store_true", help="append to --out, skipping the runs already in it")
    p.add_argument("--maps", nargs="+", metavar="MAP", help="map names (default: the profile's)")
    p.add_argument("--counts", nargs="+", type=int, metavar="K",
                   help="robot counts, each used up to the map's pool size (default: the profile's)")
    p.add_argument("--methods", nargs="+", choices=["raw", "layered"], default=["raw", "layered"])
    p.add_argument("--backends", nargs="+", default=["la_cbs", "la_lacam"], metavar="BACKEND",
                   help="la_cbs, la_lacam, la_lns, or BACKEND+FALLBACK such as la_lacam+la_lns (the CLI's --fallback; "
                        "default: la_cbs la_lacam)")
    p.add_argument("--steps", nargs="+", choices=STEP_SETS, default=["1234"],
                   help="decomposition steps of the layered runs (default: 1234)")
    p.add_argument("--time-limit", type=float, help="seconds per solve, graphs included (default: the profile's)")
    p.add_argument("--grace", type=float, help="seconds past the limit before a run is killed (default: the profile's)")
    p.add_argument("--decomposition-timeout", type=float,
                   help="seconds before a decomposition run is killed (default: the profile's, 30 or 60)")
    p.add_argument("--seeds", nargs="+", type=int, default=[0], help="solver seeds of the 'K mixed' runs (default: 0)")
    p.add_argument("--random-subsets", type=int, default=0, metavar="N",
                   help="also N random K-robot subsets per K, drawn with seeds 1..N (default: 0)")
    p.add_argument("--generated-feasible", type=int, default=0, metavar="N",
                   help="also N instances per K from `fleet_planner_cli generate --feasible` (robots of pairs proven "
                        "unable to reach both targets drawn again), seeds 1..N")
    p.add_argument("--generated", type=int, default=0, metavar="N",
                   help="also N instances per K from `fleet_planner_cli generate`, seeds 1..N; K may exceed the pool "
                        "(default: 0)")
    p.add_argument("--threads", type=int, default=2, help="CLI --threads (default: 2)")
    p.add_argument("--backend-param", action="append", default=[], metavar="BACKEND.NAME=VALUE",
                   help="CLI --backend-param for every solve (repeatable), e.g. la_cbs.suboptimality=1.2")
    p.add_argument("--sweep-tolerance", type=float, default=0.0,
                   help="CLI --sweep-tolerance: cells a turn may clip beyond its end poses (default: 0, exact; "
                        "0.2 makes every instance of the pools feasible but den520d K=140, see docs/benchmarking.md)")
    p.add_argument("--no-validate", dest="validate", action="store_false",
                   help="skip the independent check of each plan (and decompose --check)")
    p.add_argument("--keep-plans", metavar="DIR",
                   help="copy each returned plan to DIR/<map>_<K>_<subset>_<method>_<backend>_<steps>_<seed>.yaml "
                        "(e.g. to compare two builds' plans byte for byte)")
    p.add_argument("--note", default="", help="free text kept in <out>.meta.json (e.g. where the CLI was built from)")
    p.add_argument("--dry-run", action="store_true", help="list the runs to do and stop")
    args = p.parse_args(argv)

    profile = PROFILES[args.profile]
    if args.maps is None:
        args.maps = profile["decomposition_maps" if args.decomposition else "maps"]
    if args.counts is None:
        args.counts = profile["decomposition_counts" if args.decomposition else "counts"]
    args.time_limit = profile["time_limit"] if args.time_limit is None else args.time_limit
    args.grace = profile["grace"] if args.grace is None else args.grace
    if args.decomposition_timeout is None:
        args.decomposition_timeout = profile["decomposition_timeout"]
    if args.out is None:
        args.out = "benchmark-%s%s.csv" % (args.profile, "-decomposition" if args.decomposition else "")
    check_inputs(args)
    return args


def check_inputs(args):
    args.cli = os.path.abspath(args.cli)
    if not (os.path.isfile(args.cli) and os.access(args.cli, os.X_OK)):
        fail("no fleet_planner_cli at %s: run scripts/build (or pass --cli PATH / set FLEET_PLANNER_CLI)"
             % args.cli)
    args.benchmark_dir = os.path.abspath(args.benchmark_dir)
    if not os.path.isdir(args.benchmark_dir):
        fail("benchmark folder %s not found: pass --benchmark-dir DIR (with maps/ and instances/)"
             % args.benchmark_dir)
    for name in args.maps:
        for path in (map_path(args.benchmark_dir, name), pool_path(args.benchmark_dir, name)):
            if not os.path.isfile(path):
                known = sorted(f[:-7] for f in os.listdir(os.path.join(args.benchmark_dir, "instances"))
                               if f.endswith("_la.txt"))
                fail("map %s: %s not found (maps with a pool: %s)" % (name, path, ", ".join(known)))
    if (args.time_limit <= 0 or args.grace < 0 or args.random_subsets < 0 or args.generated < 0
            or args.generated_feasible < 0 or min(args.counts) < 1):
        fail("--time-limit must be > 0, --grace and --random-subsets >= 0, counts >= 1")
    if len(set(args.seeds)) != len(args.seeds):
        fail("--seeds must not repeat")


def main(argv):
    args = parse_args(argv)
    return sweep(args)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
