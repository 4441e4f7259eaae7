#!/usr/bin/env python3
"""The immersed ESBGK gas on MPI ranks (wall time serial and on 2 ranks).

Runs rfmems-pullin on cases/cantilever_switch with gas: esbgk (transient, a step voltage, a
short end time: ~20 coupled steps), serially and under `mpirun --bind-to none -np P`, one after
the other in the same session, and prints one JSON line per run: wall seconds, CPU seconds of
all the run's processes (getrusage of the children), the driver's own figures (its per-physics
CPU split on the root, structural and gas steps, tip deflection, the root's communication
counters), the load average before and after. The ratios between the lines are the result;
absolute times on the shared machine are noisy.

Usage:
  bench/bench_immersed_gas_mpi.py --driver build/drivers/rfmems-pullin --ranks 1 2 \\
      --end-time 0.01us [--set key=value ...] > out.jsonl
"""
import argparse
import json

import h5py
import numpy as np
import os
import resource
import subprocess
import sys
import tempfile
import time


def run(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    load0 = os.getloadavg()[0]
    t0 = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        sys.exit(f"failed ({p.returncode}): {' '.join(cmd)}\n{p.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return json.loads(p.stdout), wall, cpu, load0, os.getloadavg()[0]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--driver", default="build/drivers/rfmems-pullin")
    ap.add_argument("--case", default="cases/cantilever_switch/case.yaml")
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--end-time", default="0.01us")
    ap.add_argument("--voltage", default="80V")
    ap.add_argument("--set", action="append", default=[], dest="sets")
    ap.add_argument("--mca", action="append", default=[], nargs=2, metavar=("NAME", "VALUE"),
                    help="an Open MPI parameter for the mpirun runs (e.g. mpi_yield_when_idle 1)")
    a = ap.parse_args()
    sets = ["gas.model=esbgk", "pull_in.mode=transient",
            f"pull_in.transient.voltage={a.voltage}", f"pull_in.transient.end_time={a.end_time}"]
    sets += a.sets
    reference = None
    with tempfile.TemporaryDirectory() as work:
        for ranks in a.ranks:
            cmd = [a.driver, a.case, "-o", f"{work}/np{ranks}.h5", "--json", "--quiet"]
            for s in sets:
                cmd += ["--set", s]
            if ranks > 1:
                mca = [x for name, value in a.mca for x in ("--mca", name, value)]
                cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
                       *mca, "-np", str(ranks)] + cmd
            j, wall, cpu, load0, load1 = run(cmd)
            im = j["pull_in"]
            line = {
                "bench": "immersed_gas_mpi",
                "date": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
                "ranks": ranks, "sets": sets, "mca": a.mca if ranks > 1 else [], "wall_s": wall, "cpu_s": cpu,
                "load_before": load0, "load_after": load1,
                "driver_wall_s": j["wall_time_s"],
                "cpu_root": im["counters"], "transient": im["transient"],
                "background_cells": im["immersed"]["background_cells"],
            }
            if "communication_rank0" in j:
                line["communication_rank0"] = j["communication_rank0"]
            with h5py.File(f"{work}/np{ranks}.h5") as f:
                history = f["dynamic/transient/values"][:]
            line["final_tip_m"] = float(history[-1, 0])
            line["final_gas_force"] = float(history[-1, 3])
            if reference is None:
                reference = history
            elif reference.shape == history.shape:
                scale = np.max(np.abs(reference[:, 0]))
                line["tip_history_vs_first_run"] = float(
                    np.max(np.abs(history[:, 0] - reference[:, 0])) / scale)
            print(json.dumps(line), flush=True)


if __name__ == "__main__":
    main()
