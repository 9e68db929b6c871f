"""Helpers of scripts/run_benchmark.py: the benchmark's maps, pools and instances, and running
one CLI process with its time limit and peak memory. Not a script of its own."""
import json
import os
import random
import signal
import subprocess
import sys
import tempfile
import time


class Interrupted(Exception):
    """Ctrl-C during a run: the run is dropped, the rows so far are kept."""


def fail(message):
    sys.exit("run_benchmark: error: " + message)


# --------------------------------------------------------------------------------------------
# Maps, pools and instances

def pool_path(bench, name):
    return os.path.join(bench, "instances", name + "_la.txt")


def map_path(bench, name):
    return os.path.join(bench, "maps", name + ".map")


def read_pool(path):
    """The pool's robot lines, split into circles and blocks, in file order."""
    circles, blocks = [], []
    with open(path) as f:
        for line in f:
            if line.strip():
                (circles if line.split()[0] == "Circle" else blocks).append(line.strip())
    return circles, blocks


def interleave(circles, blocks, k):
    """ceil(k/2) circles interleaved with floor(k/2) blocks, the other kind where one runs out."""
    nc = min(len(circles), max(k - len(blocks), (k + 1) // 2))
    nb = k - nc
    out = []
    for i in range(max(nc, nb)):
        if i < nc:
            out.append(circles[i])
        if i < nb:
            out.append(blocks[i])
    return out


def random_subset_file(bench, name, k, seed, folder):
    """Writes a random 'K mixed' subset of the pool (drawn with `seed`) and returns its path."""
    circles, blocks = read_pool(pool_path(bench, name))
    rng = random.Random("%s:%d:%d" % (name, k, seed))
    nc = min(len(circles), max(k - len(blocks), (k + 1) // 2))
    lines = interleave(rng.sample(circles, nc), rng.sample(blocks, k - nc), k)
    path = os.path.join(folder, "%s_K%d_seed%d.txt" % (name, k, seed))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def generated_file(cli, bench, name, k, seed, folder, feasible=False, sweep_tolerance=0.0):
    """Generates (once) a K-robot instance of the map with `seed` and returns its path; `feasible`:
    with `generate --feasible` (robots of pairs not shown possible drawn again), decided with the
    solves' `sweep_tolerance`."""
    tag = "feas" if feasible else "gen"
    if feasible and sweep_tolerance:
        tag += "_t%g_" % sweep_tolerance
    path = os.path.join(folder, "%s_K%d_%s%d.yaml" % (name, k, tag, seed))
    if not os.path.exists(path):
        extra = ["--feasible"] if feasible else []
        if feasible and sweep_tolerance:
            extra += ["--sweep-tolerance", str(sweep_tolerance)]
        r = subprocess.run([cli, "generate", "--map", map_path(bench, name), "--agents", str(k), "--seed", str(seed),
                            "--out", path] + extra,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
        if r.returncode != 0:
            fail("generate %s K=%d seed %d: %s" % (name, k, seed, last_line(r.stderr)))
    return path


def problem_args(bench, name, k, subset, seed, folder, cli=None, sweep_tolerance=0.0):
    """CLI arguments naming the map and the robots of one run."""
    args = ["--map", map_path(bench, name)]
    if subset in ("generated", "feasible"):
        path = generated_file(cli, bench, name, k, seed, folder, feasible=subset == "feasible",
                              sweep_tolerance=sweep_tolerance)
        return args + ["--instance", path, "--agents", "0"]
    if subset == "mixed":
        return args + ["--instance", pool_path(bench, name), "--agents", str(k)]
    return args + ["--instance", random_subset_file(bench, name, k, seed, folder), "--agents", "0"]


def model_args(args):
    """CLI arguments of the discretisation, the same for solving and checking."""
    return ["--sweep-tolerance", str(args.sweep_tolerance)] if args.sweep_tolerance else []


# --------------------------------------------------------------------------------------------
# One process per run

def run_process(argv, timeout):
    """Runs argv in its own session and kills it after `timeout` seconds. Returns a dict: code
    (exit status, or -signal), out, err, wall (s), killed, hwm_mb (the child's VmHWM, polled from
    /proc while it runs: its peak resident set since exec, up to the last poll) and wait4_mb
    (ru_maxrss from wait4: Linux folds the forking process's own high-water mark into it at exec,
    so it never reads below this driver's resident set). On Ctrl-C the child is killed and
    Interrupted raised."""
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        t0 = time.monotonic()
        proc = subprocess.Popen(argv, stdout=out, stderr=err, stdin=subprocess.DEVNULL,
                                start_new_session=True)
        killed, hwm, delay = False, 0.0, 0.001
        try:
            while True:
                pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
                if pid:
                    break
                hwm = max(hwm, vm_hwm_mb(proc.pid))
                if time.monotonic() - t0 > timeout:
                    os.killpg(proc.pid, signal.SIGKILL)
                    killed = True
                    _, status, usage = os.wait4(proc.pid, 0)
                    break
                time.sleep(delay)
                delay = min(delay * 2, 0.02)
        except KeyboardInterrupt:
            os.killpg(proc.pid, signal.SIGKILL)
            os.wait4(proc.pid, 0)
            proc.returncode = -signal.SIGKILL
            raise Interrupted()
        wall = time.monotonic() - t0
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        return {"code": proc.returncode, "out": out.read(), "err": err.read(), "wall": wall, "killed": killed,
                "hwm_mb": hwm, "wait4_mb": usage.ru_maxrss / 1024.0}


def vm_hwm_mb(pid):
    """VmHWM of a running process in MB (0 once it has exited)."""
    try:
        with open("/proc/%d/status" % pid) as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024.0
    except (OSError, ValueError):
        pass
    return 0.0


def parse_json_line(text):
    for line in reversed(text.splitlines()):
        line = line.strip()
        if line.startswith("{"):
            try:
                return json.loads(line)
            except ValueError:
                return None
    return None


def outcome(r, timeout):
    """(status, reason, json or None) of a finished process (a run_process result)."""
    code, out, err, killed = r["code"], r["out"], r["err"], r["killed"]
    if killed:
        return "KILLED", "still running after %.0f s (killed)" % timeout, None
    if code < 0:
        return "CRASH", "killed by signal %d: %s" % (-code, last_line(err)), None
    j = parse_json_line(out)
    if code == 2:
        message = last_line(err)
        return ("UNREACHABLE" if "not reachable" in message else "BAD_INPUT"), message, None
    if j is None or code not in (0, 1):
        return "CRASH", "exit %d%s: %s" % (code, "" if j else " without a JSON line", last_line(err)), None
    return None, j.get("reason", ""), j


def last_line(text):
    lines = [l for l in text.strip().splitlines() if l.strip()]
    return lines[-1].strip() if lines else ""


def fmt(x, digits=4):
    if x is None or x == "":
        return ""
    if isinstance(x, float):
        return ("%." + str(digits) + "g") % x if abs(x) < 1e-3 else str(round(x, digits))
    return str(x)


