#!/usr/bin/python3
"""Plots of the frogleg varactor creep runs (cases/frogleg_varactor, rfmems-creep result files).

  <PREFIX>_gap.png      gap between the plate and the electrode vs time [h]: g0 + w at the first
                        probe (the plate centre, over the sensing electrode), solid, and the
                        smallest gap over the actuation electrodes (min_gap), dashed; one
                        colour per result file (e.g. coarse / fine mesh, tighter rtol)
  <PREFIX>_stress.png   surface stresses sigma_xx and sigma_yy on the top surface at t = 0
                        (thesis Fig. 4.11), from the elastic moments: sigma = 6 M / h^2 at
                        z = +h/2 (no plastic strain at t = 0), of the first result file

It also prints, per file, the gap at t = 0 and at the last time, the closure, and the largest
surface stresses with where they sit (the leg corners), and, for several files, each file's
last gap relative to the first file's.

Usage: plot_frogleg.py RESULT.h5 [RESULT.h5 ...] [-o PREFIX]  (PREFIX: first RESULT without .h5)
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_creep import creep_history  # noqa: E402
from plot_solid import read_cells  # noqa: E402
from plotting import open_result, prefix_args, run_main, save  # noqa: E402


def read(path):
    with open_result(path) as f:
        t_h, values, columns, s = creep_history(f, path, "plot_frogleg.py")
        if "gap_m" not in s or not s["probes"]:
            sys.exit(f"plot_frogleg.py: {path}: needs a run with a gap and a probe")
        probe = columns[0]  # the case's first probe (the summary's keys are sorted)
        run = {
            "path": path,
            "summary": s,
            "t_h": t_h,
            "probe": probe,
            "gap": s["gap_m"] + values[:, columns.index(probe)],
            "min_gap": values[:, columns.index("min_gap")],
            "cells": s["mesh"]["cells"],
        }
        nodes = f["mesh/nodes"][()]
        run["polygons"] = [nodes[c][:, :2] for c in read_cells(f["mesh/topology"][()])]
        run["centroids"] = f["mesh/cell_centroids"][()]
        run["moment0"] = f["fields/000000/moment"][()]
        return run


def label(run):
    s = run["summary"]
    return f"{os.path.basename(run['path'])}: {run['cells']} cells, {s['steps']} steps"


def stress_map(run, prefix):
    h = run["summary"]["plate_thickness_m"]
    sigma = 6.0 * run["moment0"] / h**2  # top surface, t = 0
    fig, axes = plt.subplots(2, 1, figsize=(8, 8))
    for ax, k, name in ((axes[0], 0, "sigma_xx"), (axes[1], 1, "sigma_yy")):
        v = sigma[:, k] / 1e6
        lim = np.max(np.abs(v))
        pc = PolyCollection([p * 1e6 for p in run["polygons"]], array=v, cmap="RdBu_r",
                            edgecolors="face", linewidths=0.2)
        pc.set_clim(-lim, lim)
        ax.add_collection(pc)
        ax.autoscale()
        ax.set_aspect("equal")
        ax.set_xlabel("x [um]")
        ax.set_ylabel("y [um]")
        ax.set_title(f"{name}, top surface, t = 0 [MPa]")
        plt.colorbar(pc, ax=ax, shrink=0.8)
    print(save(fig, prefix + "_stress.png", dpi=130))
    for k, name in ((0, "sigma_xx"), (1, "sigma_yy")):
        c = int(np.argmax(np.abs(sigma[:, k])))
        x, y = run["centroids"][c][:2] * 1e6
        plate = np.abs(sigma[np.all(np.abs(run["centroids"][:, :2]) <=
                                    [150e-6, 110e-6], axis=1), k])
        print(f"  {name}: max |sigma| {abs(sigma[c, k]) / 1e6:.1f} MPa at ({x:.1f}, {y:.1f}) um; "
              f"largest on the plate itself {plate.max() / 1e6:.1f} MPa")


def main():
    args, prefix = prefix_args(__doc__.splitlines()[0], several=True)
    runs = [read(p) for p in args.results]

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for run in runs:
        line, = ax.plot(run["t_h"], run["gap"] * 1e6, "o-", ms=3,
                        label=f"{label(run)}: {run['probe']}")
        ax.plot(run["t_h"], run["min_gap"] * 1e6, "--", color=line.get_color(),
                label=f"{label(run)}: smallest gap over the actuation electrodes")
    ax.set_xlabel("time [h]")
    ax.set_ylabel("gap [um]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    print(save(fig, prefix + "_gap.png", dpi=130))

    first = runs[0]
    for run in runs:
        g = run["gap"]
        print(f"{label(run)}: {run['probe']} gap {g[0] * 1e6:.6f} um at t = 0, "
              f"{g[-1] * 1e6:.6f} um at {run['t_h'][-1]:.4g} h (closure {(g[0] - g[-1]) * 1e9:.3f} nm); "
              f"smallest gap {run['min_gap'][0] * 1e6:.6f} -> {run['min_gap'][-1] * 1e6:.6f} um")
        if run is not first:
            print(f"  vs {os.path.basename(first['path'])}: last gap {(g[-1] / first['gap'][-1] - 1) * 100:+.4f} %, "
                  f"closure {((g[0] - g[-1]) / (first['gap'][0] - first['gap'][-1]) - 1) * 100:+.3f} %")
    stress_map(first, prefix)


if __name__ == "__main__":
    run_main(main)
