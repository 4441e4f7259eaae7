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
from plotting import run_main
from work_error import METRICS, completed_runs, draw, read_input, write


def main():
    args, records = read_input(__doc__.splitlines()[0])
    runs = completed_runs(records, "plot_work_error.py")
    reference = next((r for r in records if r.get("variant") == "reference"), None)

    metrics = METRICS if all("error_max_over_outputs" in r for r in runs) else METRICS[:1]
    fig = draw(runs, metrics)

    title = "Cantilever vibration: work against error"
    if reference:
        title += (f" ({reference.get('nx')} x {reference.get('ny')} cells, "
                  f"t* = {reference.get('t_star')} s, w_ref = {reference.get('w_ref_m'):.6e} m)")
    write(fig, title, args.output)


if __name__ == "__main__":
    run_main(main)
