#!/usr/bin/python3
"""Work-error plot of bench_vibration_work_error (bench/bench_vibration_work_error.cpp).

Reads the benchmark's JSON lines (a file, or stdin with "-" or no argument) and draws log-log
panels: columns are wall time and residual evaluations; the first row is the relative error
|w - w_ref| / |w_ref| of the tip deflection at t*, the second (when the input has it) the
largest error over the output times relative to the largest |w_ref| there. One series per
method (IDA adaptive orders <= 2, IDA orders <= 5, fixed-step backward Euler, fixed-step BDF2
through IDA and in the bench's own loop), each point labelled with its tolerance or step. Runs
that did not complete (stopped at the wall-time cap) and skipped runs are left out; the
reference line, if present, gives the title.

Usage: plot_work_error.py [RESULTS.jsonl | -] -o FIGURE.png
"""
import argparse
import json
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

# method -> (legend label, marker); unknown methods get a default style.
STYLE = {
    "ida": ("IDA adaptive, order <= 2", "o"),
    "ida_order5": ("IDA adaptive, order <= 5", "*"),
    "be": ("backward Euler, fixed dt", "s"),
    "bdf2": ("BDF2, fixed dt (IDA fixed-step mode)", "^"),
    "bdf2_exact": ("BDF2, fixed dt, exact step solves (own loop)", "v"),
}


def read_lines(source):
    """All JSON objects of a JSON-lines stream (blank and non-JSON lines ignored)."""
    records = []
    for line in source:
        line = line.strip()
        if not line.startswith("{"):
            continue
        try:
            records.append(json.loads(line))
        except json.JSONDecodeError:
            continue
    return records


def point_label(run):
    if "rtol" in run:
        return f"rtol {run['rtol']:.0e}"
    if "dt" in run:
        return f"dt {run['dt']:.0e}"
    return ""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input", nargs="?", default="-", help="JSON lines file, or - for stdin")
    parser.add_argument("-o", "--output", required=True, help="PNG file to write")
    args = parser.parse_args()

    if args.input == "-":
        records = read_lines(sys.stdin)
    else:
        with open(args.input, encoding="utf-8") as f:
            records = read_lines(f)

    runs = [r for r in records if r.get("variant") == "run" and r.get("completed") and "error" in r]
    if not runs:
        sys.exit("plot_work_error.py: no completed runs in the input")
    reference = next((r for r in records if r.get("variant") == "reference"), None)

    series = {}
    for run in runs:
        series.setdefault(run["method"], []).append(run)

    metrics = [("error", "|w - w_ref| / |w_ref| at t*")]
    if all("error_max_over_outputs" in r for r in runs):
        metrics.append(("error_max_over_outputs", "max |w - w_ref| / max |w_ref| over outputs"))
    fig, axes = plt.subplots(len(metrics), 2, figsize=(12, 5 * len(metrics)), squeeze=False,
                             constrained_layout=True)
    for row, (metric, ylabel) in enumerate(metrics):
        for col, (key, xlabel) in enumerate((("wall_s", "wall time [s]"),
                                             ("residual_evals", "residual evaluations"))):
            ax = axes[row][col]
            for method, points in series.items():
                label, marker = STYLE.get(method, (method, "x"))
                points = sorted(points, key=lambda r: r[key])
                xs = [r[key] for r in points]
                # An exact hit would be off a log axis; floor it at a tiny value instead.
                ys = [max(r[metric], 1e-16) for r in points]
                ax.loglog(xs, ys, marker=marker, label=label)
                for x, y, r in zip(xs, ys, points):
                    ax.annotate(point_label(r), (x, y), textcoords="offset points",
                                xytext=(4, 4), fontsize=6)
            ax.set_xlabel(xlabel)
            ax.set_ylabel(ylabel)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8, loc="lower left")

    title = "Cantilever vibration: work against error"
    if reference:
        title += (f" ({reference.get('nx')} x {reference.get('ny')} cells, "
                  f"t* = {reference.get('t_star')} s, w_ref = {reference.get('w_ref_m'):.6e} m)")
    fig.suptitle(title)
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    try:
        main()
    except OSError as e:  # a missing or unreadable file: bad input, one line and exit 2
        print(f"{sys.argv[0].rsplit('/', 1)[-1]}: {e}", file=sys.stderr)
        sys.exit(2)
