#!/usr/bin/python3
"""Plots of rfmems-pullin results of the immersed cantilever switch (cases/cantilever_switch).

  <PREFIX>_tip.png      tip deflection vs time, one curve per result file
  <PREFIX>_forces.png   electrostatic and gas force on the beam (y) vs time

Each file's /dynamic/<run> history (transient or pull_in) is read; labels are the file names.

Usage: plot_immersed_switch.py RESULT.h5 [RESULT2.h5 ...] -o PREFIX
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import finish, run_main  # noqa: E402


def history(path):
    with h5py.File(path, "r") as f:
        group = f["dynamic"]
        name = "transient" if "transient" in group else list(group.keys())[0]
        t = group[name]["time"][()]
        values = group[name]["values"][()]
    # columns: control, min_gap, electrostatic_force, gas_force, contact_force, voltage
    return t, values


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", nargs="+", help="result files (.h5)")
    parser.add_argument("-o", "--prefix", required=True, help="output prefix")
    args = parser.parse_args()
    runs = [(os.path.basename(p).removesuffix(".h5"), *history(p)) for p in args.results]

    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for label, t, v in runs:
        ax.plot(t * 1e6, v[:, 0] * 1e6, label=label)
    finish(fig, ax, "time [us]", "tip deflection [um]", args.prefix + "_tip.png", dpi=120)

    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for label, t, v in runs:
        ax.plot(t * 1e6, v[:, 2], label=label + " electrostatic")
        if abs(v[:, 3]).max() > 0:
            ax.plot(t * 1e6, v[:, 3], "--", label=label + " gas")
    finish(fig, ax, "time [us]", "force on the beam, y [N/m]", args.prefix + "_forces.png", dpi=120)
    print("wrote", args.prefix + "_tip.png", args.prefix + "_forces.png")


if __name__ == "__main__":
    run_main(main)
