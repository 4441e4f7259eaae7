#!/usr/bin/python3
"""Maps and profiles of a kinetic gas result file written by rfmems-gas.

  <PREFIX>_fields.png     density, temperature, speed |u| (with velocity arrows) and the heat
                          flux magnitude over the mesh (cell-centred maps)
  <PREFIX>_profile.png    one-column meshes (quasi-1D, e.g. Couette): velocity components and
                          temperature against y
  <PREFIX>_residual.png   the solver's residual ratio ||r|| / ||r_0|| per iteration

Fields read: /fields/000000/{density, temperature, velocity, heat_flux} (n_cells x 1 or 3);
cells from /mesh; /solver/residual/{iteration, values}.

Usage: plot_gas.py RESULT.h5 [-o PREFIX]     (PREFIX defaults to RESULT without .h5)
"""
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_solid import read_cells  # noqa: E402
from plotting import prefix_args, run_main, save  # noqa: E402


def draw_map(ax, polygons, nodes, values, title, cmap="viridis"):
    collection = PolyCollection(polygons, array=values, cmap=cmap, edgecolors="face",
                                linewidths=0.2)
    ax.add_collection(collection)
    ax.set_xlim(nodes[:, 0].min(), nodes[:, 0].max())
    ax.set_ylim(nodes[:, 1].min(), nodes[:, 1].max())
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(title)
    plt.colorbar(collection, ax=ax, shrink=0.8)


def main():
    args, prefix = prefix_args(__doc__.splitlines()[0])

    with h5py.File(args.result, "r") as f:
        nodes = f["mesh/nodes"][()]
        polygons = [nodes[c][:, :2] for c in read_cells(f["mesh/topology"][()])]
        centroids = f["mesh/cell_centroids"][()]
        step = f["fields/000000"]
        rho = step["density"][()].ravel()
        T = step["temperature"][()].ravel()
        u = step["velocity"][()].reshape(-1, 3)
        q = step["heat_flux"][()].reshape(-1, 3)
        its = f["solver/residual/iteration"][()] if "solver/residual" in f else None
        ratios = f["solver/residual/values"][()].ravel() if its is not None else None

    fig, axes = plt.subplots(2, 2, figsize=(11, 9))
    draw_map(axes[0, 0], polygons, nodes, rho, "density [kg/m³]")
    draw_map(axes[0, 1], polygons, nodes, T, "temperature [K]", cmap="inferno")
    speed = np.linalg.norm(u, axis=1)
    draw_map(axes[1, 0], polygons, nodes, speed, "speed |u| [m/s]", cmap="plasma")
    if len(centroids) <= 4000 and np.any(speed[:] > 0):
        axes[1, 0].quiver(centroids[:, 0], centroids[:, 1], u[:, 0], u[:, 1], color="w",
                          scale=None, width=0.002)
    draw_map(axes[1, 1], polygons, nodes, np.linalg.norm(q, axis=1), "|heat flux| [W/m²]",
             cmap="magma")
    save(fig, prefix + "_fields.png", dpi=120)

    if np.allclose(centroids[:, 0], centroids[0, 0]):  # one column: profiles along y
        order = np.argsort(centroids[:, 1])
        y = centroids[order, 1]
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
        for d, name in enumerate("xyz"):
            if np.any(u[:, d]):
                ax1.plot(u[order, d], y, "o-", ms=2, label=f"u_{name}")
        ax1.set_xlabel("velocity [m/s]")
        ax1.set_ylabel("y [m]")
        ax1.legend()
        ax2.plot(T[order], y, "o-", ms=2)
        ax2.set_xlabel("temperature [K]")
        save(fig, prefix + "_profile.png", dpi=120)

    if its is not None and len(its):
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.semilogy(its, ratios)
        ax.set_xlabel("iteration")
        ax.set_ylabel("||r|| / ||r0||")
        ax.grid(True, which="both", alpha=0.3)
        save(fig, prefix + "_residual.png", dpi=120)
    profile = os.path.exists(prefix + "_profile.png")
    print(f"wrote {prefix}_fields.png" + (", _profile.png" if profile else "") + ", _residual.png")


if __name__ == "__main__":
    run_main(main)
