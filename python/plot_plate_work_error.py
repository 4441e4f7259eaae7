#!/usr/bin/python3
"""Work-error plot of bench_plate_work_error (bench/bench_plate_work_error.cpp).

Reads the benchmark's JSON lines and draws log-log panels: columns are wall time and residual
evaluations; the first row is the relative error |w - w_ref| / |w_ref| of the centre
deflection at t*, the second the largest error over the output times relative to the largest
|w_ref| there. One series per method (IDA adaptive orders <= 2 and <= 5, fixed-step backward
Euler and BDF2), each point labelled with its tolerance or step; dotted horizontal lines at
the error targets of the bench's summary line. Runs that did not complete and skipped runs
are left out. The JSON format is that of bench_vibration_work_error, so the reading, the
styles and the panels are shared with plot_work_error.py (work_error.py).

Usage: plot_plate_work_error.py [RESULTS.jsonl | -] -o FIGURE.png
"""
from plotting import run_main
from work_error import METRICS, completed_runs, draw, read_input, write


def main():
    args, records = read_input(__doc__.splitlines()[0])
    runs = completed_runs(records, "plot_plate_work_error.py")
    reference = next((r for r in records if r.get("variant") == "reference"), None)
    summary = next((r for r in records if r.get("variant") == "summary"), None)
    targets = sorted({t["target"] for t in summary.get("work_to_reach", [])}) if summary else []

    fig = draw(runs, METRICS, targets)

    title = "Fixed-fixed plate strip (L/h = 200), step load: work against error"
    if reference:
        title += (f"\n{reference.get('nx')} x {reference.get('ny')} cells, "
                  f"t* = {reference.get('t_star') * 1e6:g} us, "
                  f"w_ref = {reference.get('w_ref_m'):.6e} m (modal superposition)")
    write(fig, title, args.output)


if __name__ == "__main__":
    run_main(main)
