#!/usr/bin/python3
"""How closely rfmems-gas on P ranks reproduces the serial answer, against the solver tolerance.

On ranks the sequential solver is a different iteration (block Jacobi between the METIS parts,
Gauss-Seidel sweeps within each), converging to the same discrete steady state; so is COMET
with per-part coarse levels. Each run stops when ||r|| / ||r_0|| <= tolerance, so the two
answers are two points within about `tolerance` (times the problem's conditioning) of that
state, not the same iterate. This runs a case serially and under `mpirun -np P` at each
tolerance and prints one JSON line per (case, tolerance): the largest relative difference of
each field (max |a - b| / max |a| over the cells) and of each wall's force and heat flow,
and the iterations of both runs.

Usage:
  bench/bench_gas_mpi_agreement.py --driver build/drivers/rfmems-gas --ranks 2 \\
      --case cases/gas_couette/case.yaml --tolerances 1e-6 1e-8 1e-10 [--set key=value ...]
"""
import argparse
import json
import subprocess
import sys
import tempfile

import h5py
import numpy as np

FIELDS = ("density", "velocity", "temperature", "pressure")


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"failed ({p.returncode}): {' '.join(cmd)}\n{p.stderr}")
    return json.loads(p.stdout)


def fields(path):
    with h5py.File(path, "r") as f:
        step = sorted(k for k in f["fields"] if k[0].isdigit())[0]
        return {name: f["fields"][step][name][()] for name in FIELDS}


def relative(a, b):
    scale = float(np.max(np.abs(a)))
    return float(np.max(np.abs(np.asarray(b) - np.asarray(a)))) / scale if scale > 0 else 0.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--driver", default="build/drivers/rfmems-gas")
    ap.add_argument("--case", required=True)
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--tolerances", type=float, nargs="+", default=[1e-6, 1e-8, 1e-10])
    ap.add_argument("--set", action="append", default=[], dest="sets")
    a = ap.parse_args()
    mpirun = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
              "--mca", "mpi_yield_when_idle", "1", "-np", str(a.ranks)]
    with tempfile.TemporaryDirectory() as work:
        for tol in a.tolerances:
            args = [a.case, "--json", "--quiet", "--set", f"solver.tolerance={tol:g}"]
            for s in a.sets:
                args += ["--set", s]
            serial = run([a.driver, *args, "-o", f"{work}/serial.h5"])
            ranks = run(mpirun + [a.driver, *args, "-o", f"{work}/ranks.h5"])
            fa, fb = fields(f"{work}/serial.h5"), fields(f"{work}/ranks.h5")
            walls = {}
            for wall, w in serial["walls"].items():
                wb = ranks["walls"][wall]
                walls[wall] = {"force": relative(w["force"], wb["force"]),
                               "heat_flow": relative([w["heat_flow"]], [wb["heat_flow"]])}
            print(json.dumps({
                "case": serial["case"], "sets": a.sets, "ranks": a.ranks, "tolerance": tol,
                "solver": serial["solver"]["type"],
                "iterations": [serial["solver"]["iterations"], ranks["solver"]["iterations"]],
                "residual_ratio": [serial["solver"]["residual_ratio"],
                                   ranks["solver"]["residual_ratio"]],
                "fields": {name: relative(fa[name], fb[name]) for name in FIELDS},
                "walls": walls}), flush=True)


if __name__ == "__main__":
    main()
