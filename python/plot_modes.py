#!/usr/bin/python3
"""Natural frequencies and mode shapes of a modal result file (rfmems-solid, analysis.type modal).

  <PREFIX>_frequencies.png   frequency [Hz] of each mode against its number (a complex
                             eigenvalue marked)
  <PREFIX>_shapes.png        one panel per mode (the first six): a plate's deflection w
                             over its mid-surface; a continuum's cell centres displaced by the
                             shape (largest component scaled to 10 % of the body), coloured by |u|

Read: /modal/modes/mode and /modal/modes/values (frequency, ..., complex, residual, as the
result file's "components" attribute names them), /fields/<k>/deflection (plate) or
/fields/<k>/displacement (continuum) for mode k + 1, and /mesh.

Usage: plot_modes.py RESULT.h5 [-o PREFIX]
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_plate import cell_polygons, draw_map  # noqa: E402
from plot_solid import si_scale  # noqa: E402
from plotting import finish, open_result, prefix_args, run_main, save  # noqa: E402


def read_modes(f, path):
    """(numbers, {component: values}) of /modal/modes; exits 2 if the file has none."""
    if "modal/modes" not in f:
        print(f"plot_modes.py: {path}: no /modal/modes (not a modal result?)", file=sys.stderr)
        sys.exit(2)
    group = f["modal/modes"]
    values = group["values"][()]
    names = [n.decode() if isinstance(n, bytes) else str(n)
             for n in group["values"].attrs["components"]]
    return group["mode"][()].astype(int), {n: values[:, i] for i, n in enumerate(names)}


def plot_frequencies(numbers, modes, path):
    fig, ax = plt.subplots(figsize=(6, 4))
    real = modes["complex"] == 0
    ax.semilogy(numbers[real], modes["frequency"][real], "o", label="real eigenvalue")
    if np.any(~real):
        ax.semilogy(numbers[~real], modes["frequency"][~real], "x", color="C3", ms=9,
                    label="complex eigenvalue")
    for n, freq in zip(numbers, modes["frequency"]):
        ax.annotate(f"{freq:.4g}", (n, freq), textcoords="offset points", xytext=(4, 4),
                    fontsize=7)
    ax.set_xticks(numbers)
    ax.set_title("natural frequencies")
    return finish(fig, ax, "mode", "frequency [Hz]", path, fontsize=8)


SHOWN_MODES = 6


def plot_shapes(f, numbers, modes, path):
    shown = list(range(min(len(numbers), SHOWN_MODES)))
    columns = min(3, len(shown))
    rows = math.ceil(len(shown) / columns)
    plate = "deflection" in f["fields/000000"]
    fig, axes = plt.subplots(rows, columns, figsize=(5.5 * columns, 3.2 * rows), squeeze=False)
    polygons, nodes = cell_polygons(f)
    centres = f["mesh/cell_centroids"][()]
    extent = np.ptp(nodes[:, :2], axis=0).max()
    for k, ax in zip(shown, axes.flat):
        group = f["fields"][f"{k:06d}"]
        title = f"mode {numbers[k]}: {modes['frequency'][k]:.4g} Hz"
        if plate:
            w = group["deflection"][()].reshape(-1, 3)[:, 2]
            draw_map(ax, polygons, nodes, w, ("w (unit max)", ""), cmap="coolwarm")
        else:
            u = group["displacement"][()].reshape(-1, 3)
            scale = 0.1 * extent / max(np.abs(u).max(), 1e-300)
            moved = centres[:, :2] + scale * u[:, :2]
            factor, unit = si_scale(extent, "m")
            points = ax.scatter(moved[:, 0] * factor, moved[:, 1] * factor,
                                c=np.linalg.norm(u, axis=1), s=2, cmap="viridis")
            ax.set_aspect("equal")
            ax.set_xlabel(f"x [{unit}]")
            ax.set_ylabel(f"y [{unit}]")
            plt.colorbar(points, ax=ax, label="|u| (unit max component)", shrink=0.8)
        ax.set_title(title, fontsize=9)
    for ax in list(axes.flat)[len(shown):]:
        ax.axis("off")
    return save(fig, path)


def main():
    args, prefix = prefix_args(__doc__.splitlines()[0])
    with open_result(args.result) as f:
        numbers, modes = read_modes(f, args.result)
        written = [plot_frequencies(numbers, modes, prefix + "_frequencies.png"),
                   plot_shapes(f, numbers, modes, prefix + "_shapes.png")]
    for path in written:
        print(f"wrote {path}")


if __name__ == "__main__":
    run_main(main)
