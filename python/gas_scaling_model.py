#!/usr/bin/env python3
"""Communication model of the distributed kinetic solvers (docs/mpi.md).

Reads the JSON lines of bench/bench_gas_scaling (worker lines) and projects the parallel
efficiency of one iteration (COMET: one V-cycle) to 64-512 ranks on a cluster network:

  t_comp(P) = t_cell * n                      n = cells per rank, t_cell measured on 1 rank
                                              (CPU s per cell per iteration), scaled by N
  t_comm(P) = X * nu * alpha                  X ghost exchanges per iteration (measured),
            + E * g(n) * 8 N / beta             nu neighbouring ranks per part
            + R * alpha * log2(P)             E fine-ghost-layer volumes sent per iteration
                                              (measured: bytes / (ghost cells * 8 N)),
                                              R reductions per iteration (measured)
  efficiency(P) = t_comp / (t_comp + t_comm)  (per iteration; no overlap of communication and computation;
                                              the extra iterations of block Jacobi between
                                              parts are not in it: see the measured counts)

Also printed with t_cell / 10 (the point solves being optimised elsewhere make computation,
not communication, cheaper). Surface-to-volume of METIS parts: g(n) = 4 sqrt(n) ghost cells in 2D (square parts), 6 n^(2/3)
in 3D (cubes); nu = 6 (2D) and 14 (3D) neighbours.

Usage: python3 python/gas_scaling_model.py scaling.jsonl
"""
import json
import math
import sys

NETWORKS = {  # latency alpha [s], bandwidth beta [bytes/s] per link
    "10GigE (thesis cluster)": (30e-6, 1.1e9),
    "InfiniBand HDR": (1.5e-6, 12e9),
}
MESHES = {  # name: (cells, dim)
    "2D 1000 x 1000": (1_000_000, 2),
    "3D 64^3": (64 ** 3, 3),
}
N_TARGET = 1000  # 10^3 velocities, as in the thesis


def main(path):
    rows = [json.loads(l) for l in open(path) if l.strip()]
    workers = [r for r in rows if r.get("run") == "worker"]
    for solver in ("comet", "sequential"):
        one = [r for r in workers if r["solver"] == solver and r["ranks"] == 1 and r["width_factor"] == 1]
        many = [r for r in workers if r["solver"] == solver and r["ranks"] > 1 and r["width_factor"] == 1]
        if not one or not many:
            continue
        ref = max(one, key=lambda r: r["cells"][0] * r["cells"][1])
        par = max(many, key=lambda r: r["cells"][0] * r["cells"][1])
        n_v = ref["velocities"]
        cells = ref["cells"][0] * ref["cells"][1]
        t_cell = ref["cpu_s"][0] / (ref["iterations"] * cells) * N_TARGET / n_v
        ghosts = sum(par["ghost_cells"]) / len(par["ghost_cells"])
        exchanges = par["exchanges_per_iteration"][0]
        reductions = par["reductions_per_iteration"][0]
        volumes = sum(par["bytes_per_iteration"]) / len(par["bytes_per_iteration"]) / (ghosts * 8 * n_v)
        print(f"{solver}: measured on {ref['cells']} ({n_v} velocities): t_cell = "
              f"{t_cell * 1e6:.1f} us per cell per iteration at N = {N_TARGET}; on {par['ranks']} ranks "
              f"X = {exchanges:.1f} exchanges, E = {volumes:.2f} ghost-layer volumes, "
              f"R = {reductions:.1f} reductions per iteration")
        for (mesh, (n_cells, dim)), (net, (alpha, beta)), faster in (
                (m, nw, k) for m in MESHES.items() for nw in NETWORKS.items() for k in (1, 10)):
            if True:
                cols = []
                for p in (16, 64, 128, 256, 512):
                    n = n_cells / p
                    g = 4 * math.sqrt(n) if dim == 2 else 6 * n ** (2 / 3)
                    nu = 6 if dim == 2 else 14
                    t_comp = t_cell / faster * n
                    t_comm = (exchanges * nu * alpha + volumes * g * 8 * N_TARGET / beta
                              + reductions * alpha * math.log2(p))
                    cols.append(f"P={p}: {100 * t_comp / (t_comp + t_comm):.0f}%")
                label = "" if faster == 1 else f", point solves {faster}x faster"
                print(f"  {mesh}, {net}{label}: " + ", ".join(cols))


if __name__ == "__main__":
    main(sys.argv[1])
