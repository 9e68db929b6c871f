#!/usr/bin/python3
"""Draws the Layered LA-MAPF paper's figures from run_benchmark.py CSVs, as PNG files.

Solve CSVs give, per map, solve_<map>.png: time, success rate, makespan and SOC against the
number of robots, raw (dashed) against layered (solid) for each backend. Time is the mean over
the runs, a failed run counting as its time limit; makespan and SOC are means over the
successful runs only. summary.png: success rate and mean time per map and method/backend.

Decomposition CSVs give decomposition_<map>.png (decomposition rate, number of subproblems and
decomposition time after steps 1, 1-2, 1-3 and 1-4 against the number of robots) and
decomposition.png (the same for every map, one column per map, as in the paper's figure).

Markdown tables (summary per map, pooled figures to set beside the paper's, one line per run,
decomposition summary) are printed to stdout and written to <out-dir>/summary.md.
"""
import argparse
import collections
import csv
import os
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)

COMBOS = [("raw", "la_cbs"), ("layered", "la_cbs"), ("raw", "la_lacam"), ("layered", "la_lacam")]
LABEL = {("raw", "la_cbs"): "raw LA-CBS", ("layered", "la_cbs"): "layered LA-CBS",
         ("raw", "la_lacam"): "raw LA-LaCAM", ("layered", "la_lacam"): "layered LA-LaCAM"}
COLOR = {"la_cbs": "tab:blue", "la_lacam": "tab:orange"}
STYLE = {"raw": dict(linestyle="--", marker="x"), "layered": dict(linestyle="-", marker="o")}
STEP_LABEL = {"1": "1", "12": "1,2", "123": "1,2,3", "1234": "1,2,3,4"}
STEP_COLOR = {"1": "tab:gray", "12": "tab:green", "123": "tab:purple", "1234": "tab:red"}


def num(x):
    return float(x) if x not in ("", None) else None


def read_csvs(paths):
    """(solve rows, decomposition rows) of the given CSVs, told apart by their columns."""
    solve, decomposition = [], []
    for path in paths:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            cols = reader.fieldnames or []
            if "method" in cols and "backend" in cols:
                solve += list(reader)
            elif "step_time_s" in cols:
                decomposition += list(reader)
            else:
                sys.exit("plot_benchmark: error: %s is not a run_benchmark.py CSV (columns: %s)" % (path, cols))
    return solve, decomposition


def in_order(names, rows):
    """Map names in order of first appearance."""
    return [n for n in dict.fromkeys(r["map"] for r in rows) if n in names]


# --------------------------------------------------------------------------------------------
# Solve figures

def group(rows):
    """{(map, method, backend): {K: [rows]}} (every subset and seed of a K pooled)."""
    g = collections.defaultdict(lambda: collections.defaultdict(list))
    for r in rows:
        g[(r["map"], r["method"], r["backend"])][int(r["robots"])].append(r)
    return g


def success(r):
    return r["status"] == "SUCCESS" and r["plan_valid"] in ("true", "")


def run_time(r):
    """Time of a run, a failure counting as its limit."""
    return num(r["time_s"]) if success(r) else num(r["time_limit"])


def series(runs_by_k, metric):
    ks, ys = [], []
    for k in sorted(runs_by_k):
        runs = runs_by_k[k]
        if metric == "time":
            y = statistics.mean(run_time(r) for r in runs)
        elif metric == "success":
            y = sum(success(r) for r in runs) / len(runs)
        else:
            ok = [num(r[metric]) for r in runs if success(r)]
            y = statistics.mean(ok) if ok else None
        if y is not None:
            ks.append(k)
            ys.append(y)
    return ks, ys


def plot_solve_map(name, g, limits, out_dir):
    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5))
    ks = sorted({k for (m, _, _), runs in g.items() if m == name for k in runs})
    panels = [("time", "time (s), failures = limit"), ("success", "success rate"),
              ("makespan", "makespan (successes only)"), ("soc", "SOC (successes only)")]
    span = max(ks) - min(ks) or 10
    for ax, (metric, ylabel) in zip(axes.flat, panels):
        for i, (method, backend) in enumerate(COMBOS):
            runs = g.get((name, method, backend))
            if runs:
                xs, ys = series(runs, metric)
                if metric == "success":  # dodge, so that equal rates stay visible
                    xs = [x + (i - 1.5) * 0.008 * span for x in xs]
                ax.plot(xs, ys, color=COLOR[backend], label=LABEL[(method, backend)], **STYLE[method])
        ax.set_xlabel("robots")
        ax.set_ylabel(ylabel)
        ax.set_xticks(ks)
        ax.set_xlim(min(ks) - 0.05 * span, max(ks) + 0.05 * span)
        ax.grid(alpha=0.3)
        if metric == "time":
            ax.set_yscale("log")
        if metric == "success":
            ax.set_ylim(-0.05, 1.05)
    axes[0, 1].legend(fontsize=8)
    fig.suptitle("%s: %s s limit. Time: mean, a failure counts as the limit; makespan, SOC: mean over "
                 "successful runs only" % (name, "/".join(limits)), fontsize=10)
    fig.tight_layout()
    path = os.path.join(out_dir, "solve_%s.png" % name)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_summary(maps, rows, out_dir):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(13, 4.5))
    groups = maps + ["all maps"]
    width = 0.8 / len(COMBOS)
    for i, (method, backend) in enumerate(COMBOS):
        rates, times = [], []
        for m in groups:
            runs = [r for r in rows if r["method"] == method and r["backend"] == backend
                    and (m == "all maps" or r["map"] == m)]
            rates.append(sum(map(success, runs)) / len(runs) if runs else 0)
            times.append(statistics.mean(map(run_time, runs)) if runs else 0)
        xs = [j + (i - 1.5) * width for j in range(len(groups))]
        kw = dict(width=width, color=COLOR[backend], label=LABEL[(method, backend)],
                  hatch="//" if method == "raw" else None, edgecolor="white" if method == "raw" else None)
        a1.bar(xs, rates, **kw)
        a2.bar(xs, times, **kw)
    for ax, ylabel in ((a1, "success rate"), (a2, "mean time (s), failures = limit")):
        ax.set_xticks(range(len(groups)))
        ax.set_xticklabels(groups, rotation=30, ha="right", fontsize=8)
        ax.set_ylabel(ylabel)
        ax.grid(axis="y", alpha=0.3)
    a1.set_ylim(0, 1.05)
    a1.legend(fontsize=8)
    limits = "/".join(sorted({r["time_limit"].rstrip("0").rstrip(".") for r in rows}))
    fig.suptitle("Success rate and mean time (a failure counts as the %s s limit) per map, pooled over the robot "
                 "counts run" % limits, fontsize=10)
    fig.tight_layout()
    path = os.path.join(out_dir, "summary.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


# --------------------------------------------------------------------------------------------
# Decomposition figures

def decomposition_series(rows, name, steps, column):
    by_k = collections.defaultdict(list)
    for r in rows:
        if r["map"] == name and r["steps"] == steps and r["status"] == "OK":
            by_k[int(r["robots"])].append(num(r[column]))
    ks = sorted(by_k)
    return ks, [statistics.mean(by_k[k]) * (1000 if column == "decompose_s" else 1) for k in ks]


DECOMP_PANELS = [("rate", "decomposition rate"), ("subproblems", "subproblems"),
                 ("decompose_s", "time (ms), steps 1..k")]


def draw_decomposition(axes, rows, name):
    ks = sorted({int(r["robots"]) for r in rows if r["map"] == name and r["status"] == "OK"})
    for ax, (column, ylabel) in zip(axes, DECOMP_PANELS):
        ax.set_xticks(ks)
        for steps in STEP_LABEL:
            ks, ys = decomposition_series(rows, name, steps, column)
            ax.plot(ks, ys, marker="o", markersize=3, color=STEP_COLOR[steps], label=STEP_LABEL[steps])
        ax.set_xlabel("robots", fontsize=8)
        ax.set_ylabel(ylabel, fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(alpha=0.3)
        if column == "rate":
            ax.set_ylim(0, 1.05)


def plot_decomposition(maps, rows, out_dir):
    paths = []
    note = "steps 1 / 1,2 / 1,2,3 / 1,2,3,4; time includes the relation graphs, not the state graphs"
    for name in maps:
        fig, axes = plt.subplots(1, 3, figsize=(12, 3.4))
        draw_decomposition(axes, rows, name)
        axes[0].legend(fontsize=8, title="steps", title_fontsize=8)
        fig.suptitle("%s: decomposition (%s)" % (name, note), fontsize=9)
        fig.tight_layout()
        paths.append(os.path.join(out_dir, "decomposition_%s.png" % name))
        fig.savefig(paths[-1], dpi=110)
        plt.close(fig)
    fig, axes = plt.subplots(3, len(maps), figsize=(2.6 * len(maps), 7.5), squeeze=False)
    for j, name in enumerate(maps):
        draw_decomposition(axes[:, j], rows, name)
        axes[0, j].set_title(name, fontsize=9)
    axes[0, 0].legend(fontsize=7, title="steps", title_fontsize=7)
    fig.suptitle("Decomposition per map (%s)" % note, fontsize=10)
    fig.tight_layout()
    paths.append(os.path.join(out_dir, "decomposition.png"))
    fig.savefig(paths[-1], dpi=100)
    plt.close(fig)
    return paths


# --------------------------------------------------------------------------------------------
# Markdown tables

def mean_or_dash(values, fmt="%.2f"):
    values = [v for v in values if v is not None]
    return fmt % statistics.mean(values) if values else "-"


def solve_tables(maps, rows):
    combos = [c for c in COMBOS if any(r["method"] == c[0] and r["backend"] == c[1] for r in rows)]
    out = ["### Success per map (solved / runs; mean time in s, a failure counting as the limit)", "",
           "| map | K | " + " | ".join(LABEL[c] for c in combos) + " |",
           "|---|---|" + "---|" * len(combos)]
    for name in maps + ["all maps"]:
        mine = [r for r in rows if name == "all maps" or r["map"] == name]
        ks = sorted({int(r["robots"]) for r in mine})
        cells = []
        for method, backend in combos:
            runs = [r for r in mine if r["method"] == method and r["backend"] == backend]
            ok = sum(map(success, runs))
            cells.append("%d/%d, %s s" % (ok, len(runs), mean_or_dash(map(run_time, runs))) if runs else "-")
        krange = "%d-%d" % (ks[0], ks[-1]) if len(ks) > 1 else str(ks[0])
        label = "**all maps**" if name == "all maps" else name
        out.append("| %s | %s | %s |" % (label, krange, " | ".join(cells)))
    out += ["", "### Pooled over every run (the paper's averages)", "",
            "| method | success rate | mean time s (failure = limit) | makespan / SOC, successes only "
            "| makespan / SOC, failures as 0 |", "|---|---|---|---|---|"]
    for method, backend in combos:
        runs = [r for r in rows if r["method"] == method and r["backend"] == backend]
        ok = [r for r in runs if success(r)]
        ms = [num(r["makespan"]) for r in ok]
        soc = [num(r["soc"]) for r in ok]
        out.append("| %s | %.2f (%d/%d) | %s | %s / %s | %.1f / %.1f |" % (
            LABEL[(method, backend)], len(ok) / len(runs), len(ok), len(runs), mean_or_dash(map(run_time, runs)),
            mean_or_dash(ms, "%.1f"), mean_or_dash(soc, "%.1f"), sum(ms) / len(runs), sum(soc) / len(runs)))
    out += ["", "### Every run (solved: time, SOC, peak memory; otherwise the status)", "",
            "| map | K | " + " | ".join(LABEL[c] for c in combos) + " |", "|---|---|" + "---|" * len(combos)]
    index = collections.defaultdict(list)
    for r in rows:
        index[(r["map"], int(r["robots"]), r["method"], r["backend"])].append(r)
    for name in maps:
        for k in sorted({int(r["robots"]) for r in rows if r["map"] == name}):
            cells = []
            for method, backend in combos:
                runs = index.get((name, k, method, backend), [])
                cells.append("; ".join(run_cell(r) for r in runs) or "-")
            out.append("| %s | %d | %s |" % (name, k, " | ".join(cells)))
    return out


def quality_table(maps, rows):
    """Layered against raw, per backend, on the runs where both solved the same instance."""
    index = {}
    for r in rows:
        if success(r):
            index[(r["map"], r["robots"], r["subset"], r["seed"], r["method"], r["backend"])] = r
    backends = [b for b in dict.fromkeys(r["backend"] for r in rows)]
    out = ["### Plan quality: layered / raw on the instances both solve (median ratio, worst ratio, "
           "instances)", "",
           "| map | " + " | ".join("%s SOC | %s makespan" % (b, b) for b in backends) + " |",
           "|---|" + "---|---|" * len(backends)]
    have = False
    for name in maps + ["all maps"]:
        cells = []
        for b in backends:
            soc, mk = [], []
            for (m, k, subset, seed, method, backend), r in index.items():
                if method != "layered" or backend != b or (name != "all maps" and m != name):
                    continue
                raw = index.get((m, k, subset, seed, "raw", b))
                if raw is None or not num(raw["soc"]) or not num(raw["makespan"]):
                    continue
                soc.append(num(r["soc"]) / num(raw["soc"]))
                mk.append(num(r["makespan"]) / num(raw["makespan"]))
            if soc:
                have = True
                cells += ["%.2f (max %.2f, n=%d)" % (statistics.median(soc), max(soc), len(soc)),
                          "%.2f (max %.2f)" % (statistics.median(mk), max(mk))]
            else:
                cells += ["-", "-"]
        label = "**all maps**" if name == "all maps" else name
        out.append("| %s | %s |" % (label, " | ".join(cells)))
    return out if have else []


def run_cell(r):
    if success(r):
        return "%.2f s, SOC %s, %.0f MB" % (num(r["time_s"]), r["soc"], num(r["peak_rss_mb"]))
    if r["status"] == "TIMEOUT":
        return "timeout (%s s), %.0f MB" % (r["time_limit"].rstrip("0").rstrip("."), num(r["peak_rss_mb"]))
    return r["status"].lower()


def decomposition_table(maps, rows):
    out = ["### Decomposition after steps 1-4 (legality-checked)", "",
           "| map | K | mean rate | largest subproblem per K | mean / max time s | not decomposed |",
           "|---|---|---|---|---|---|"]
    for name in maps:
        final = [r for r in rows if r["map"] == name and r["steps"] == "1234"]
        ok = sorted((r for r in final if r["status"] == "OK"), key=lambda r: int(r["robots"]))
        bad = ["K=%s %s" % (r["robots"], r["status"].lower()) for r in final if r["status"] != "OK"]
        if not ok:
            out.append("| %s | - | - | - | - | %s |" % (name, ", ".join(bad) or "-"))
            continue
        times = [num(r["decompose_s"]) for r in ok]
        out.append("| %s | %s-%s | %.2f | %s | %.3f / %.3f | %s |" % (
            name, ok[0]["robots"], ok[-1]["robots"], statistics.mean(num(r["rate"]) for r in ok),
            largest_per_k(ok), statistics.mean(times), max(times),
            ", ".join(bad) or "-"))
    return out


def largest_per_k(rows):
    """'K:largest' for each K (the mean over the runs of that K when there are several)."""
    by_k = collections.defaultdict(list)
    for r in rows:
        by_k[int(r["robots"])].append(int(r["largest"]))
    return " / ".join("%d:%s" % (k, ("%d" if len(set(v)) == 1 else "%.1f") % statistics.mean(v))
                      for k, v in sorted(by_k.items()))


# --------------------------------------------------------------------------------------------

def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], epilog=__doc__.split("\n\n", 1)[1],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("csv", nargs="+", help="solve and/or decomposition CSVs of run_benchmark.py")
    p.add_argument("--out-dir", help="folder for the PNGs and summary.md (default: the first CSV's folder)")
    p.add_argument("--maps", nargs="+", metavar="MAP", help="only these maps (default: every map in the CSVs)")
    args = p.parse_args(argv)
    for path in args.csv:
        if not os.path.isfile(path):
            sys.exit("plot_benchmark: error: no CSV at %s" % path)
    out_dir = args.out_dir or os.path.dirname(os.path.abspath(args.csv[0]))
    os.makedirs(out_dir, exist_ok=True)
    solve, decomposition = read_csvs(args.csv)
    names = set(args.maps or [r["map"] for r in solve + decomposition])
    solve = [r for r in solve if r["map"] in names]
    decomposition = [r for r in decomposition if r["map"] in names]
    written, lines = [], []
    if solve:
        maps = in_order(names, solve)
        g = group(solve)
        for name in maps:
            limits = sorted({r["time_limit"].rstrip("0").rstrip(".") for r in solve if r["map"] == name})
            written.append(plot_solve_map(name, g, limits, out_dir))
        written.append(plot_summary(maps, solve, out_dir))
        lines += solve_tables(maps, solve) + [""]
        quality = quality_table(maps, solve)
        if quality:
            lines += quality + [""]
    if decomposition:
        maps = in_order(names, decomposition)
        written += plot_decomposition(maps, decomposition, out_dir)
        lines += decomposition_table(maps, decomposition) + [""]
    if not written:
        sys.exit("plot_benchmark: error: the CSVs hold no rows for these maps")
    with open(os.path.join(out_dir, "summary.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))
    print("wrote %d PNG files and summary.md to %s" % (len(written), out_dir), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
