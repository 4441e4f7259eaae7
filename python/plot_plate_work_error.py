#!/usr/bin/python3
"""Work-error plot of bench_plate_work_error (bench/bench_plate_work_error.cpp).

Reads the benchmark's JSON lines and draws log-log panels: columns are wall time and residual
evaluations; the first row is the relative error |w - w_ref| / |w_ref| of the centre
deflection at t*, the second the largest error over the output times relative to the largest
|w_ref| there. One series per method (IDA adaptive orders <= 2 and <= 5, fixed-step backward
Euler and BDF2), each point labelled with its tolerance or step; dotted horizontal lines at
the error targets of the bench's summary line. Runs that did not complete and skipped runs
are left out. The JSON format is that of bench_vibration_work_error, so the reading and the
styles are shared with plot_work_error.py.

Usage: plot_plate_work_error.py [RESULTS.jsonl | -] -o FIGURE.png
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

from plot_work_error import STYLE, point_label, read_lines  # noqa: E402

METRICS = [("error", "|w - w_ref| / |w_ref| at t*"),
           ("error_max_over_outputs", "max |w - w_ref| / max |w_ref| over outputs")]
WORK = [("wall_s", "wall time [s]"), ("residual_evals", "residual evaluations")]


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
        sys.exit("plot_plate_work_error.py: no completed runs in the input")
    reference = next((r for r in records if r.get("variant") == "reference"), None)
    summary = next((r for r in records if r.get("variant") == "summary"), None)
    targets = sorted({t["target"] for t in summary.get("work_to_reach", [])}) if summary else []

    series = {}
    for run in runs:
        series.setdefault(run["method"], []).append(run)

    fig, axes = plt.subplots(len(METRICS), len(WORK), figsize=(12, 10), squeeze=False,
                             constrained_layout=True)
    for row, (metric, ylabel) in enumerate(METRICS):
        for col, (key, xlabel) in enumerate(WORK):
            ax = axes[row][col]
            for method, points in series.items():
                label, marker = STYLE.get(method, (method, "x"))
                points = sorted(points, key=lambda r: r[key])
                xs = [r[key] for r in points]
                ys = [max(r[metric], 1e-16) for r in points]  # an exact hit stays on the axis
                ax.loglog(xs, ys, marker=marker, label=label)
                for x, y, r in zip(xs, ys, points):
                    ax.annotate(point_label(r), (x, y), textcoords="offset points",
                                xytext=(4, 4), fontsize=6)
            for target in targets:
                ax.axhline(target, color="grey", linestyle=":", linewidth=1)
            ax.set_xlabel(xlabel)
            ax.set_ylabel(ylabel)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8, loc="lower left")

    title = "Fixed-fixed plate strip (L/h = 200), step load: work against error"
    if reference:
        title += (f"\n{reference.get('nx')} x {reference.get('ny')} cells, "
                  f"t* = {reference.get('t_star') * 1e6:g} us, "
                  f"w_ref = {reference.get('w_ref_m'):.6e} m (modal superposition)")
    fig.suptitle(title)
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    try:
        main()
    except OSError as e:  # a missing or unreadable file: bad input, one line and exit 2
        print(f"{sys.argv[0].rsplit('/', 1)[-1]}: {e}", file=sys.stderr)
        sys.exit(2)
