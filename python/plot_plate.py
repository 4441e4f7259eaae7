#!/usr/bin/python3
"""Maps of a plate result file written by rfmems-solid (model.structure: plate).

  <PREFIX>_deflection.png   deflection w over the mid-surface at the last output time
  <PREFIX>_moments.png      bending moments M_xx, M_yy, M_xy [N m/m] at the last output time
  <PREFIX>_probes.png       w of every probe vs time (transients with probes only)

Fields read: /fields/<step>/deflection (n_cells x 3, w in the z column) and
/fields/<step>/moment (n_cells x 3: M_xx, M_yy, M_xy); cells drawn from /mesh.

Usage: plot_plate.py RESULT.h5 [-o PREFIX]     (PREFIX defaults to RESULT without .h5)
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_solid import last_step_with, read_cells, si_scale  # noqa: E402
from plotting import finish, open_result, prefix_args, run_main, save  # noqa: E402


def cell_polygons(f):
    nodes = f["mesh/nodes"][()]
    return [nodes[c][:, :2] for c in read_cells(f["mesh/topology"][()])], nodes


def draw_map(ax, polygons, nodes, values, label, cmap="viridis"):
    scale, unit = si_scale(np.max(np.abs(values)) if np.any(values) else 1.0, label[1])
    collection = PolyCollection([p * 1e6 for p in polygons], array=values * scale, cmap=cmap,
                                edgecolors="face", linewidths=0.2)
    ax.add_collection(collection)
    ax.set_xlim(nodes[:, 0].min() * 1e6, nodes[:, 0].max() * 1e6)
    ax.set_ylim(nodes[:, 1].min() * 1e6, nodes[:, 1].max() * 1e6)
    ax.set_aspect("equal")
    ax.set_xlabel("x [µm]")
    ax.set_ylabel("y [µm]")
    plt.colorbar(collection, ax=ax, label=f"{label[0]} [{unit}]", shrink=0.8)


def main():
    args, prefix = prefix_args(__doc__.splitlines()[0])
    with open_result(args.result) as f:
        step = last_step_with(f, "deflection")
        if step is None:
            sys.exit(f"plot_plate.py: {args.result}: no deflection field (not a plate result?)")
        group = f["fields"][step]
        time = float(group.attrs.get("time", 0.0))
        polygons, nodes = cell_polygons(f)
        w = group["deflection"][()].reshape(-1, 3)[:, 2]

        fig, ax = plt.subplots(figsize=(7, 5))
        draw_map(ax, polygons, nodes, w, ("w", "m"), cmap="coolwarm")
        ax.set_title(f"deflection at t = {time:.4g} s (min {w.min():.4g} m)")
        written = [save(fig, prefix + "_deflection.png")]

        if "moment" in group:
            m = group["moment"][()].reshape(-1, 3)
            fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
            for k, name in enumerate(("M_xx", "M_yy", "M_xy")):
                draw_map(axes[k], polygons, nodes, m[:, k], (name, "N"), cmap="RdBu_r")
                axes[k].set_title(f"{name} [N m/m] at t = {time:.4g} s")
            written.append(save(fig, prefix + "_moments.png"))

        if "probes" in f and len(f["fields/times"][()]) > 1:
            names = sorted(f["probes"].keys())
            fig, ax = plt.subplots(figsize=(8, 4))
            for name in names:
                t = f["probes"][name]["time"][()]
                v = f["probes"][name]["values"][()].reshape(len(t), -1)[:, 0]
                ts, tu = si_scale(t.max() if t.size else 1.0, "s")
                ws, wu = si_scale(np.max(np.abs(v)) if np.any(v) else 1.0, "m")
                ax.plot(t * ts, v * ws, label=name)
            written.append(finish(fig, ax, f"time [{tu}]", f"w [{wu}]", prefix + "_probes.png"))
    print("wrote " + ", ".join(written))


if __name__ == "__main__":
    run_main(main)
