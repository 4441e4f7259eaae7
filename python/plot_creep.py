#!/usr/bin/python3
"""Plots of rfmems-creep result files (drivers/rfmems-creep.cpp).

  <PREFIX>_creep.png   top: the probes' deflection w [um] vs time [h]; bottom: the smallest gap
                       [um] vs time (runs with a gap) or the plastic part w(t) - w(0) of the
                       probes (pressure-only runs); the end of life marked.

Several result files (e.g. hold voltages of a lifetime study) go on the same axes, labelled
by case name and hold voltage.

Usage: plot_creep.py RESULT.h5 [RESULT.h5 ...] [-o PREFIX]   (PREFIX: the first RESULT without .h5)
"""
import argparse
import json
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read(path):
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise OSError(f"{path}: {e}") from e
    with f:
        if "creep/history" not in f:
            sys.exit(f"plot_creep.py: {path}: no /creep/history (not an rfmems-creep result?)")
        h = f["creep/history"]
        columns = [str(c) for c in h["values"].attrs["components"]]
        summary = json.loads(f["metadata"].attrs["summary"])
        return h["time"][()] / 3600.0, h["values"][()], columns, summary


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", nargs="+", help="result files (.h5)")
    parser.add_argument("-o", "--prefix", help="output prefix (default: first RESULT without .h5)")
    args = parser.parse_args()
    prefix = args.prefix or os.path.splitext(args.results[0])[0]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    has_gap = False
    for path in args.results:
        t, values, columns, s = read(path)
        probes = list(s["probes"].keys())
        label = s["case"] + (f", {s['hold_voltage_V']:g} V" if s["hold_voltage_V"] > 0 else "")
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
    fig.tight_layout()
    out = prefix + "_creep.png"
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    try:
        main()
    except OSError as e:  # a missing or unreadable file: bad input, one line and exit 2
        print(f"{sys.argv[0].rsplit('/', 1)[-1]}: {e}", file=sys.stderr)
        sys.exit(2)
