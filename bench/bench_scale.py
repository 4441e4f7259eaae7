#!/usr/bin/python3
"""Cost against size of rfmems-solid's static solves: the linear solvers on growing meshes.

Runs rfmems-solid on a case at each mesh and linear solver (solver.linear: direct, KLU; or
multigrid, GMRES with hypre's BoomerAMG) and prints one JSON line per run: the unknowns, the
wall and CPU seconds and the peak resident memory of the run (the child's rusage), the solver's
iterations and multigrid hierarchy, the probe's deflection and its error against a reference.
Each run is its own process, so the peak memory is that run's alone. With --ranks P > 1 a run
is repeated under mpirun with solver.distributed and its displacement field compared with the
serial run's (max |u_P - u_1| / max |u_1|).

Usage:
  bench/bench_scale.py --case cases/cantilever_box_3d/case.yaml --meshes 80,8,8 160,16,16 \\
      --linear multigrid --reference=-2.016e-4 [--component uy] [--ranks 2]
      [--solver 'tolerance: 1e-10'] [--set key=value ...]
"""
import argparse
import datetime
import json
import os
import shlex
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np


def run_measured(cmd):
    """Runs cmd with its own rusage: (JSON summary, wall s, CPU s, peak RSS GiB)."""
    start = time.monotonic()
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        pid = os.fork()
        if pid == 0:
            os.dup2(out.fileno(), 1)
            os.dup2(err.fileno(), 2)
            os.execvp(cmd[0], cmd)
        _, status, usage = os.wait4(pid, 0)
        wall = time.monotonic() - start
        out.seek(0)
        err.seek(0)
        if os.waitstatus_to_exitcode(status) != 0:
            sys.exit(f"failed: {' '.join(cmd)}\n{err.read()}")
        summary = json.loads(out.read())
    # ru_maxrss is in KiB on Linux; under mpirun it is the largest process's (the launcher
    # waits for its children), not the sum over ranks.
    return summary, wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 2**20


def field(path):
    with h5py.File(path, "r") as f:
        step = sorted(k for k in f["fields"] if k[0].isdigit())[-1]
        return f["fields"][step]["displacement"][()]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--driver", default="build/drivers/rfmems-solid")
    ap.add_argument("--case", required=True)
    ap.add_argument("--meshes", nargs="+", required=True, help="cells per axis, e.g. 80,8,8")
    ap.add_argument("--linear", nargs="+", default=["multigrid"], choices=["direct", "multigrid"])
    ap.add_argument("--probe", default="tip")
    ap.add_argument("--component", default="uy")
    ap.add_argument("--reference", type=float, required=True, help="the probe's reference value")
    ap.add_argument("--ranks", type=int, default=1, help="> 1: also under mpirun, distributed")
    ap.add_argument("--solver", default="", help="more solver keys, e.g. 'tolerance: 1e-10'")
    ap.add_argument("--set", action="append", default=[], dest="sets")
    a = ap.parse_args()
    print(json.dumps({"section": "header", "date": datetime.date.today().isoformat(),
                      "command": shlex.join(["bench/bench_scale.py"] + sys.argv[1:]),
                      "load_average": os.getloadavg()[0]}), flush=True)
    mpirun = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
              "-np", str(a.ranks)]
    with tempfile.TemporaryDirectory() as work:
        for mesh in a.meshes:
            for linear in a.linear:
                extra = ", " + a.solver if a.solver else ""
                solver = "{linear: " + linear + extra + "}"
                base = [a.case, "--json", "--quiet", "--set", f"mesh.cells=[{mesh}]"]
                for s in a.sets:
                    base += ["--set", s]
                serial_out = os.path.join(work, "serial.h5")
                cmd = [a.driver] + base + ["--set", "solver=" + solver, "-o", serial_out]
                summary, wall, cpu, rss = run_measured(cmd)
                s = summary["solver"]
                value = summary["probes"][a.probe][a.component]
                line = {"section": "run", "case": summary["case"], "mesh": mesh,
                        "unknowns": summary.get("unknowns"), "linear": linear,
                        "linear_solver": s.get("linear_solver"), "wall_s": round(wall, 3), "cpu_s": round(cpu, 3),
                        "max_rss_gib": round(rss, 3), "newton_iterations": s["newton_iterations"],
                        "krylov_iterations": s.get("krylov_iterations"),
                        "multigrid_levels": s.get("multigrid_levels"),
                        "multigrid_operator_complexity": s.get("multigrid_operator_complexity"),
                        "probe": value, "relative_error": value / a.reference - 1}
                if a.ranks > 1:
                    dist_out = os.path.join(work, "dist.h5")
                    dsolver = "{distributed: true, linear: " + linear + extra + "}"
                    dcmd = mpirun + [a.driver] + base + ["--set", "solver=" + dsolver,
                                                         "-o", dist_out]
                    d_summary, d_wall, d_cpu, d_rss = run_measured(dcmd)
                    u1, u2 = field(serial_out), field(dist_out)
                    line.update({"ranks": a.ranks, "ranks_wall_s": round(d_wall, 3),
                                 "ranks_max_rss_gib": round(d_rss, 3),
                                 "ranks_krylov_iterations":
                                     d_summary["solver"].get("krylov_iterations"),
                                 "ranks_field_difference":
                                     float(np.max(np.abs(u2 - u1)) / np.max(np.abs(u1)))})
                print(json.dumps(line), flush=True)


if __name__ == "__main__":
    main()
