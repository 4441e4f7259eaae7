"""What the work-error plots of the time-integration benchmarks share (plot_work_error.py,
plot_plate_work_error.py, plot_pullin_work_error.py): the methods' legend labels and markers,
the reading of a benchmark's JSON lines, and the log-log panels of error against work.
"""
import argparse
import json
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

# method -> (legend label, marker), over the benchmarks' method names (bench_vibration_work_error
# and bench_plate_work_error: ida, ida_order5, be, bdf2, bdf2_exact; bench_pullin_work_error:
# ida_o2, ida_o5, be, bdf2, be_cut, bdf2_cut); unknown methods get a default style.
STYLE = {
    "ida": ("IDA adaptive, order <= 2", "o"),
    "ida_order5": ("IDA adaptive, order <= 5", "*"),
    "ida_o2": ("IDA adaptive, order <= 2, scalar atol", "o"),
    "ida_o5": ("IDA adaptive, order <= 5, scalar atol", "*"),
    "be": ("backward Euler, fixed dt", "s"),
    "bdf2": ("BDF2, fixed dt (IDA fixed-step mode)", "^"),
    "bdf2_exact": ("BDF2, fixed dt, exact step solves (own loop)", "v"),
    "be_cut": ("backward Euler, fixed dt, cuts at touch-down", "D"),
    "bdf2_cut": ("BDF2, fixed dt, cuts at touch-down", "v"),
}

# The rows of the panels: the error at t* and, where a benchmark has it, the largest error over
# the output times relative to the largest |w_ref| there.
METRICS = [("error", "|w - w_ref| / |w_ref| at t*"),
           ("error_max_over_outputs", "max |w - w_ref| / max |w_ref| over outputs")]
# The columns: the work axes.
WORK = [("wall_s", "wall time [s]"), ("residual_evals", "residual evaluations")]


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


def read_input(description):
    """The command line [RESULTS.jsonl | -] -o FIGURE.png and the records of its input (a file,
    or stdin with "-" or no argument)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("input", nargs="?", default="-", help="JSON lines file, or - for stdin")
    parser.add_argument("-o", "--output", required=True, help="PNG file to write")
    args = parser.parse_args()
    if args.input == "-":
        return args, read_lines(sys.stdin)
    with open(args.input, encoding="utf-8") as f:
        return args, read_lines(f)


def completed_runs(records, script):
    """The runs that completed and have an error (skipped and capped ones left out); none: the
    script ends with a message."""
    runs = [r for r in records if r.get("variant") == "run" and r.get("completed") and "error" in r]
    if not runs:
        sys.exit(f"{script}: no completed runs in the input")
    return runs


def draw(runs, metrics, targets=()):
    """The figure of log-log panels: a row per (metric, label) of metrics, a column per work
    axis; one series per method, each point labelled with its tolerance or step; a dotted
    horizontal line at each of targets."""
    series = {}
    for run in runs:
        series.setdefault(run["method"], []).append(run)

    fig, axes = plt.subplots(len(metrics), len(WORK), figsize=(12, 5 * len(metrics)),
                             squeeze=False, constrained_layout=True)
    for row, (metric, ylabel) in enumerate(metrics):
        for col, (key, xlabel) in enumerate(WORK):
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
            for target in targets:
                ax.axhline(target, color="grey", linestyle=":", linewidth=1)
            ax.set_xlabel(xlabel)
            ax.set_ylabel(ylabel)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8, loc="lower left")
    return fig


def write(fig, title, output):
    fig.suptitle(title)
    fig.savefig(output, dpi=120)
    print(f"wrote {output}")
