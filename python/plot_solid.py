#!/usr/bin/python3
"""Plots of a solid-mechanics result file written by rfmems (lib/io/result_writer.hpp).

  <PREFIX>_probes.png    displacement components of every probe in /probes vs time
                         (only if the file has probes)
  <PREFIX>_deformed.png  deformed shape at the last output time, coloured by von Mises stress
                         (or by |u| without a stress field); the displacement is magnified so
                         that the largest one is 10% of the domain size

Fields read: /fields/<step>/displacement (n_cells x 3) and /fields/<step>/stress (n_cells x 6,
Voigt order xx, yy, zz, yz, xz, xy). 2D meshes are drawn cell by cell; 3D meshes as the
cells nearest the z mid-plane, projected on x-y.

Usage: plot_solid.py RESULT.h5 [-o PREFIX]     (PREFIX defaults to RESULT without .h5)
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import open_result, run_main, save  # noqa: E402

# XDMF cell type id -> node count (polygons carry theirs after the id).
XDMF_NODES = {4: 3, 5: 4, 6: 4, 7: 5, 8: 6, 9: 8}
XDMF_POLYGON = 3


def si_scale(magnitude, unit):
    """Factor and label making `magnitude` read naturally, e.g. 3e-6 m -> (1e6, 'µm')."""
    for factor, prefix in ((1.0, ""), (1e3, "m"), (1e6, "µ"), (1e9, "n"), (1e12, "p")):
        if magnitude * factor >= 1.0:
            return factor, prefix + unit
    return 1e12, "p" + unit


def si_scale_pressure(magnitude):
    """Factor and unit for stresses: Pa, kPa, MPa or GPa."""
    for factor, unit in ((1e-9, "GPa"), (1e-6, "MPa"), (1e-3, "kPa")):
        if magnitude * factor >= 1.0:
            return factor, unit
    return 1.0, "Pa"


def read_cells(topology):
    """Node lists of the cells in an XDMF 'Mixed' flat topology list."""
    cells, i = [], 0
    while i < len(topology):
        kind = int(topology[i])
        if kind == XDMF_POLYGON:
            n = int(topology[i + 1])
            i += 2
        else:
            n = XDMF_NODES[kind]
            i += 1
        cells.append(topology[i:i + n].astype(np.int64))
        i += n
    return cells


def von_mises(s):
    xx, yy, zz, yz, xz, xy = (s[:, k] for k in range(6))
    return np.sqrt(0.5 * ((xx - yy) ** 2 + (yy - zz) ** 2 + (zz - xx) ** 2) + 3.0 * (yz**2 + xz**2 + xy**2))


def plot_probes(f, out):
    names = sorted(f["probes"].keys())
    fig, axes = plt.subplots(len(names), 1, figsize=(8, 2.6 * len(names) + 0.6), sharex=True, squeeze=False)
    t_all = np.concatenate([f["probes"][n]["time"][()] for n in names])
    t_factor, t_unit = si_scale(np.max(np.abs(t_all)) if t_all.size else 1.0, "s")
    for ax, name in zip(axes[:, 0], names):
        t = f["probes"][name]["time"][()]
        values = f["probes"][name]["values"]
        v = values[()].reshape(len(t), -1)
        labels = [str(c) for c in values.attrs["components"]] if "components" in values.attrs else \
            (["ux", "uy", "uz"] if v.shape[1] == 3 else [f"u{k}" for k in range(v.shape[1])])
        u_factor, u_unit = si_scale(np.max(np.abs(v)) if v.size and np.max(np.abs(v)) > 0 else 1.0, "m")
        shown = [k for k in range(v.shape[1]) if np.any(v[:, k] != 0)] or list(range(v.shape[1]))
        for k in shown:
            ax.plot(t * t_factor, v[:, k] * u_factor, marker="." if len(t) < 30 else None, label=labels[k])
        ax.set_ylabel(f"displacement [{u_unit}]")
        ax.set_title(f"probe '{name}'")
        ax.grid(True, alpha=0.3)
        if shown:
            ax.legend(loc="best", fontsize="small")
    axes[-1, 0].set_xlabel(f"time [{t_unit}]")
    save(fig, out)


def last_step_with(f, field):
    """Name of the last /fields/<step> group holding `field`, or None."""
    steps = sorted((k for k in f["fields"].keys() if k.isdigit() and field in f["fields"][k]), key=int)
    return steps[-1] if steps else None


def plot_deformed(f, out):
    step = last_step_with(f, "displacement")
    if step is None:
        return False
    group = f["fields"][step]
    time = float(group.attrs.get("time", np.nan))
    u = group["displacement"][()].reshape(-1, 3)
    nodes = f["mesh/nodes"][()]
    centroids = f["mesh/cell_centroids"][()]
    dim = int(f["mesh"].attrs.get("dim", 2))

    if "stress" in group:
        colour, colour_label = von_mises(group["stress"][()].reshape(-1, 6)), "von Mises stress"
        c_factor, c_unit = si_scale_pressure(np.max(colour) if colour.size else 1.0)
    else:
        colour, colour_label = np.linalg.norm(u, axis=1), "|u|"
        c_factor, c_unit = si_scale(np.max(colour) if colour.size and np.max(colour) > 0 else 1.0, "m")

    size = float(np.max(nodes.max(axis=0) - nodes.min(axis=0)))
    u_max = float(np.max(np.linalg.norm(u, axis=1))) if u.size else 0.0
    magnify = 0.1 * size / u_max if u_max > 0 else 1.0
    x_factor, x_unit = si_scale(size, "m")

    fig, ax = plt.subplots(figsize=(10, 4.5))
    if dim == 2:
        cells = read_cells(f["mesh/topology"][()])
        # Cell values averaged onto nodes, so deformed cells still share their corners.
        total = np.zeros((len(nodes), 3))
        count = np.zeros(len(nodes))
        for c, cell in enumerate(cells):
            total[cell] += u[c]
            count[cell] += 1
        u_nodes = total / np.maximum(count, 1)[:, None]
        moved = nodes + magnify * u_nodes
        ax.add_collection(PolyCollection([nodes[c][:, :2] * x_factor for c in cells], facecolors="none",
                                         edgecolors="0.8", linewidths=0.3))
        polys = PolyCollection([moved[c][:, :2] * x_factor for c in cells], array=colour * c_factor,
                               cmap="viridis", edgecolors="face", linewidths=0.2)
        ax.add_collection(polys)
        mappable = polys
        everything = np.vstack([nodes[:, :2], moved[:, :2]]) * x_factor
    else:
        # The layer of cells whose centroid is nearest the mid-plane of the z extent (one layer
        # only, even when the mid-plane falls between two).
        z = centroids[:, 2]
        nearest = z[np.argmin(np.abs(z - 0.5 * (z.min() + z.max())))]
        layer = np.abs(z - nearest) <= 1e-6 * max(size, 1e-300)
        moved = (centroids[layer] + magnify * u[layer]) * x_factor
        ax.scatter(centroids[layer, 0] * x_factor, centroids[layer, 1] * x_factor, s=4, c="0.85", marker="s",
                   linewidths=0)
        mappable = ax.scatter(moved[:, 0], moved[:, 1], c=colour[layer] * c_factor, s=8, marker="s",
                              cmap="viridis", linewidths=0)
        everything = np.vstack([centroids[layer, :2] * x_factor, moved[:, :2]])
        ax.set_title("z mid-plane cells, projected on x-y", fontsize="small", loc="right")

    lo, hi = everything.min(axis=0), everything.max(axis=0)
    pad = 0.05 * max(hi - lo) if np.max(hi - lo) > 0 else 1.0
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(f"x [{x_unit}]")
    ax.set_ylabel(f"y [{x_unit}]")
    t_text = "" if np.isnan(time) else f"t = {time:.4g} s, "
    ax.set_title(f"deformed shape ({t_text}displacement x {magnify:.3g})", loc="left")
    fig.colorbar(mappable, ax=ax, label=f"{colour_label} [{c_unit}]", shrink=0.8)
    save(fig, out)
    return True



def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result", help="result file (.h5)")
    parser.add_argument("-o", "--output", metavar="PREFIX", help="prefix of the PNG files")
    args = parser.parse_args()
    prefix = args.output or (args.result[:-3] if args.result.endswith(".h5") else args.result)
    if os.path.dirname(prefix):
        os.makedirs(os.path.dirname(prefix), exist_ok=True)

    with open_result(args.result) as f:
        wrote = []
        if "probes" in f and len(f["probes"]) > 0:
            plot_probes(f, prefix + "_probes.png")
            wrote.append(prefix + "_probes.png")
        if "fields" in f and plot_deformed(f, prefix + "_deformed.png"):
            wrote.append(prefix + "_deformed.png")
    if not wrote:
        sys.exit(f"plot_solid.py: {args.result}: no probes and no displacement field to plot")
    for name in wrote:
        print(name)


if __name__ == "__main__":
    run_main(main)
