#!/usr/bin/python3
"""The pressure jump against the normal velocity along the open sides of a gas damping run
(docs/gas_damping.md "Why ESBGK sat 10.5 % above the Stokes reference"): in the cells
next to the right and top pressure boundaries of an rfmems-gas output (the case
cases/gas_damping_regimes), C = (p - p_a) / (p_a u_n / sqrt(2 R T)) by least squares, and the
share of the beam's swept flux V b that leaves through the right side.

Usage: open_side_impedance.py RUN.h5 P_AMBIENT_PA
"""
import sys

import h5py
import numpy as np

R, T = 208.13, 273.15
V, B = 0.1, 22.5e-6


def main():
    path, p_a = sys.argv[1], float(sys.argv[2])
    c0 = np.sqrt(2 * R * T)
    f = h5py.File(path, "r")
    x = f["mesh/cell_centroids"][:]
    volume = f["mesh/cell_volumes"][:]
    fields = f["fields/000000"]
    p = fields["pressure"][:, 0]
    u = fields["velocity"][:]
    for name, axis in (("right", 0), ("top", 1)):
        side = np.isclose(x[:, axis], x[:, axis].max())
        dp, un = p[side] - p_a, u[side, axis]
        c = np.sum(dp * un) / np.sum(un * un) * c0 / p_a
        line = f"{name}: {side.sum()} cells, least-squares C = {c:.3f}"
        if axis == 0:
            columns = np.unique(np.round(x[:, 0], 12))
            width = columns[-1] - columns[-2]  # the last column's cell width (uniform block)
            q = np.sum(un * volume[side] / width)
            line += f", outflow {q:.4e} m^2/s = {q / (V * B):.4f} of V b"
        print(line)


if __name__ == "__main__":
    main()
