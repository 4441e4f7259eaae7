#!/usr/bin/python3
"""Work-error plot of bench_pullin_work_error (bench/bench_pullin_work_error.cpp).

Reads the benchmark's JSON lines and draws log-log panels of the relative error of the
dynamic pull-in time |t_PI - t_ref| / t_ref against residual evaluations (top row) and wall
time (bottom row), one column per gas setting (none, reynolds). One series per method (IDA
adaptive orders <= 2 and <= 5 with the scalar atol, orders 2-5 with the per-kind error
weights, fixed-step backward Euler and BDF2 through IDA's fixed-step mode, with and without
cuts at touch-down), each point labelled with its tolerance or step. Fixed-step runs that failed (IDA could
not converge at touch-down without shrinking the step) are marked on the bottom edge of the
top panels at their step count.

Usage: plot_pullin_work_error.py RESULTS.jsonl -o FIGURE.png [--methods M ...]
"""
import argparse
import json

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

from plotting import run_main  # noqa: E402
from work_error import STYLE  # noqa: E402


def style(method):
    """Label and marker; the weighted families ida_oK_w[x10|off] (state_tolerances.hpp)."""
    if method in STYLE:
        return STYLE[method]
    order, _, rate = method[len("ida_o"):].partition("_w")
    rate = {"": "omega_1", "off": "off"}.get(rate, rate.lstrip("x") + " omega_1")
    return (f"IDA order <= {order}, weights, velocity rate {rate}", "o*+x"[min(3, int(order) - 2)])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--methods", nargs="*", help="only these methods (default: all)")
    args = parser.parse_args()
    with open(args.results) as f:
        records = [json.loads(line) for line in f if line.startswith("{")]
    runs = [r for r in records if r.get("variant") == "run"]
    gases = sorted({r["gas"] for r in runs})
    fig, axes = plt.subplots(2, len(gases), figsize=(6 * len(gases), 8), squeeze=False)
    for col, gas in enumerate(gases):
        methods = list(dict.fromkeys(r["method"] for r in runs if r["gas"] == gas))
        if args.methods:
            methods = [m for m in methods if m in args.methods]
        for method in methods:
            label, marker = style(method)
            pts = [r for r in runs if r["gas"] == gas and r["method"] == method and "error" in r]
            if not pts:
                continue
            pts.sort(key=lambda r: r["residual_evals"])
            tag = [f"{r['rtol']:.0e}" if "rtol" in r else f"{r['dt']:.0e}" for r in pts]
            for row, key in enumerate(("residual_evals", "wall_s")):
                ax = axes[row][col]
                x = [r[key] for r in pts]
                y = [max(r["error"], 1e-12) for r in pts]
                line, = ax.loglog(x, y, marker=marker, label=label)
                for xi, yi, t in zip(x, y, tag):
                    ax.annotate(t, (xi, yi), fontsize=6, xytext=(3, 3), textcoords="offset points")
        for row, key in enumerate(("residual evaluations", "wall time [s]")):
            ax = axes[row][col]
            ax.axhline(1e-3, color="grey", lw=0.8, ls="--")
            ax.axhline(1e-2, color="grey", lw=0.8, ls=":")
            ax.set_xlabel(key)
            ax.set_ylabel("relative error of t_PI")
            ax.set_title(f"gas: {gas}")
            ax.grid(True, which="both", lw=0.3)
        failed = [r for r in records if r.get("variant") == "run" and r["gas"] == gas and "failed" in r]
        if failed:
            axes[0][col].text(0.02, 0.02, "failed at touch-down: " + ", ".join(
                f"{r['method']} dt {r['dt']:.0e}" for r in failed if "dt" in r),
                transform=axes[0][col].transAxes, fontsize=6)
    axes[0][0].legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)


if __name__ == "__main__":
    run_main(main)
