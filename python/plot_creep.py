#!/usr/bin/python3
"""Plots of rfmems-creep result files (drivers/rfmems-creep.cpp).

  <PREFIX>_creep.png   top: the probes' deflection w [um] vs time [h]; bottom: the smallest gap
                       [um] vs time (runs with a gap) or the plastic part w(t) - w(0) of the
                       probes (pressure-only runs); the end of life marked.

Several result files (e.g. hold voltages of a lifetime study) go on the same axes, labelled
by case name and hold voltage (and "von Karman" for runs with model.geometric_nonlinearity).

Usage: plot_creep.py RESULT.h5 [RESULT.h5 ...] [-o PREFIX]   (PREFIX: the first RESULT without .h5)
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import open_result, prefix_args, run_main, save  # noqa: E402


def creep_history(f, path, script):
    """Time [h], values and column names of /creep/history of the open rfmems-creep result f
    (read from path), and its summary; without a history, script ends with a message."""
    if "creep/history" not in f:
        sys.exit(f"{script}: {path}: no /creep/history (not an rfmems-creep result?)")
    h = f["creep/history"]
    columns = [str(c) for c in h["values"].attrs["components"]]
    summary = json.loads(f["metadata"].attrs["summary"])
    return h["time"][()] / 3600.0, h["values"][()], columns, summary


def read(path):
    with open_result(path) as f:
        return creep_history(f, path, "plot_creep.py")


def main():
    args, prefix = prefix_args(__doc__.splitlines()[0], several=True)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    has_gap = False
    for path in args.results:
        t, values, columns, s = read(path)
        probes = list(s["probes"].keys())
        label = s["case"] + (f", {s['hold_voltage_V']:g} V" if s["hold_voltage_V"] > 0 else "")
        if s.get("geometric_nonlinearity"):
            label += ", von Karman"
        for p in probes:
            top.plot(t, values[:, columns.index(p)] * 1e6, label=f"{label}: {p}")
        if "min_gap" in columns:
            has_gap = True
            line, = bottom.plot(t, values[:, columns.index("min_gap")] * 1e6, label=label)
            if s["life_reached"]:
                bottom.plot(t[-1], values[-1, columns.index("min_gap")] * 1e6, "x",
                            color=line.get_color(), ms=9)
                bottom.annotate(f"{s['lifetime_h']:.4g} h ({s['end']})",
                                (t[-1], values[-1, columns.index("min_gap")] * 1e6),
                                textcoords="offset points", xytext=(4, 4), fontsize=8)
        else:
            for p in probes:
                w = values[:, columns.index(p)]
                bottom.plot(t, (w - w[0]) * 1e9, label=f"{label}: {p}")
    top.set_ylabel("deflection w [um]")
    top.legend(fontsize=8)
    top.grid(alpha=0.3)
    bottom.set_ylabel("smallest gap [um]" if has_gap else "creep deflection w(t) - w(0) [nm]")
    bottom.set_xlabel("time [h]")
    bottom.legend(fontsize=8)
    bottom.grid(alpha=0.3)
    print(save(fig, prefix + "_creep.png", dpi=120))


if __name__ == "__main__":
    run_main(main)
