#!/usr/bin/python3
"""Mesh-refinement table of rfmems-pullin runs of the immersed switch (docs/immersed_switch.md, "Mesh independence").

For three or more runs of one refinement family (coarse to fine), each a --json result with
its .h5 history: pull-in time, tip deflection at fixed times, change per refinement, and the
observed order p and limit t_inf of t = t_inf + C h^p through the finest three (h = 1 / cells
along x of the refined mesh, so a ratio that is not constant is allowed).

Usage: immersed_mesh_study.py --mesh background|beam RUN.json[:RUN.h5][@NXxNY] ... [--times ...]
(the JSON gives the beam's cell count only: @NXxNY names the beam mesh's cells)
"""
import argparse
import json
import math

import h5py
import numpy as np


def load(arg, mesh):
    arg, _, named = arg.partition("@")
    path, _, h5 = arg.partition(":")
    with open(path) as f:
        j = json.load(f)
    im = j["pull_in"]
    h5 = h5 or j["output"]["h5"]
    with h5py.File(h5, "r") as f:
        g = f["dynamic"]["transient"]
        t, control = g["time"][()], g["values"][()][:, 0]
    cells = im["immersed"]["background_cells"] if mesh == "background" else j["mesh"]["cells"]
    if named:
        cells = [int(x) for x in named.split("x")]
    if not isinstance(cells, list):
        raise SystemExit(f"{path}: the beam's cells are a count ({cells}): name them, RUN.json@NXxNY")
    return {"name": path, "cells": cells, "t_pi": im["transient"]["pull_in_time"],
            "steps": im["transient"]["steps"], "cpu": im["counters"], "t": t, "control": control,
            "contact_gap": im["contact_gap"]}


def three_point_fit(h, v):
    """t_inf, C, p of v = t_inf + C h^p through three points (h decreasing)."""
    def ratio_error(p):  # (v0 - v1) / (v1 - v2) against (h0^p - h1^p) / (h1^p - h2^p)
        return (h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p) - (v[0] - v[1]) / (v[1] - v[2])
    if (v[0] - v[1]) * (v[1] - v[2]) <= 0:
        return None  # the changes alternate in sign: no order
    lo, hi = 0.05, 12.0
    if ratio_error(lo) * ratio_error(hi) > 0:
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if ratio_error(lo) * ratio_error(mid) <= 0:
            hi = mid
        else:
            lo = mid
    p = 0.5 * (lo + hi)
    c = (v[1] - v[2]) / (h[1] ** p - h[2] ** p)
    return v[2] - c * h[2] ** p, c, p


def plot(path, mesh, runs, h, fit):
    import matplotlib
    matplotlib.use("Agg")  # files only
    import matplotlib.pyplot as plt
    t_inf, c, p = fit
    hs = np.array([1.0 / r["cells"][0] for r in runs])
    fig, ax = plt.subplots(figsize=(5.6, 3.8))
    ax.plot(hs * 1e3, [r["t_pi"] * 1e6 for r in runs], "o", label="runs")
    x = np.linspace(0, hs.max(), 100)
    ax.plot(x * 1e3, (t_inf + c * x ** p) * 1e6, "-", label=f"fit, p = {p:.2f}")
    ax.axhline(t_inf * 1e6, ls=":", color="gray", label=f"limit {t_inf * 1e6:.5f} us")
    for r in runs:
        ax.annotate(f"{r['cells'][0]}x{r['cells'][1]}", (1e3 / r["cells"][0], r["t_pi"] * 1e6),
                    textcoords="offset points", xytext=(4, 4), fontsize=8)
    ax.set_xlabel(f"1000 / {mesh} cells along x")
    ax.set_ylabel("pull-in time at 125 V [us]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+", help="RUN.json[:RUN.h5][@NXxNY], coarse to fine")
    parser.add_argument("--mesh", choices=["background", "beam"], required=True)
    parser.add_argument("--times", type=float, nargs="+", default=[0.5, 1.0, 1.2], help="us")
    parser.add_argument("--histories", help="write each run's tip history (t, tip [m]) here")
    parser.add_argument("--plot", help="t_PI against h with the fit through the finest three (PNG)")
    args = parser.parse_args()
    runs = [load(a, args.mesh) for a in args.runs]
    if args.histories:
        with open(args.histories, "w") as f:
            json.dump({"mesh": args.mesh, "runs": [
                {"cells": r["cells"], "pull_in_time": r["t_pi"], "time": r["t"].tolist(),
                 "tip": r["control"].tolist()} for r in runs]}, f)
    print("| cells | t_PI [us] | change per refinement | IDA / gas steps | tip at "
          + " / ".join(f"{x:g}" for x in args.times) + " us [nm] | gas CPU rank 0 [s] |")
    print("|---|---|---|---|---|---|")
    prev = None
    for r in runs:
        tips = [np.interp(x * 1e-6, r["t"], r["control"]) * 1e9 for x in args.times]
        change = f"{100 * (r['t_pi'] / prev - 1):+.3f} %" if prev else ""
        prev = r["t_pi"]
        print(f"| {r['cells'][0]} x {r['cells'][1]} | {r['t_pi'] * 1e6:.6f} | {change} | "
              f"{r['steps']} / {r['cpu']['gas_steps']} | "
              + " / ".join(f"{x:.2f}" for x in tips)
              + f" | {r['cpu']['gas_s']:.1f} |")
    gaps = {r["contact_gap"] for r in runs}
    print("contact gaps [m]:", sorted(gaps))
    if len(runs) >= 3:
        last = runs[-3:]
        h = [1.0 / r["cells"][0] for r in last]
        for label, values in [("t_PI", [r["t_pi"] for r in last])] + [
                (f"tip {x:g} us", [np.interp(x * 1e-6, r["t"], r["control"]) for r in last])
                for x in args.times]:
            fit = three_point_fit(h, values)
            if fit is None:
                print(f"{label}: the changes do not fall monotonely (no order in [0.05, 12]): "
                      "no extrapolation")
                continue
            t_inf, _, p = fit
            if label == "t_PI" and args.plot:
                plot(args.plot, args.mesh, runs, h, fit)
            print(f"{label}: order p = {p:.2f}, limit {t_inf:.6e}, finest "
                  f"{100 * (values[-1] / t_inf - 1):+.3f} %, middle "
                  f"{100 * (values[-2] / t_inf - 1):+.3f} % from the limit")


if __name__ == "__main__":
    main()
