#!/usr/bin/env python3
"""Runs bench_creep_plate_vs_continuum once per continuum mesh and linear solver, each in its
own process (so that its peak memory is its own), and appends the runs' JSON lines, each
process's after a header line (command, commit, date, load average), to a data file under
docs/data/ that python/results_pages.py turns into tables.

  # the continuum's linear solvers side by side (docs/creep.md, table creep-continuum-solvers)
  /usr/bin/python3 python/creep_continuum_runs.py --set solvers -o docs/data/creep_continuum_solvers.jsonl
  # the 3D strip on its half span (table creep-3d-half-span)
  /usr/bin/python3 python/creep_continuum_runs.py --set half-span -o docs/data/creep_3d_half_span.jsonl

--solver restricts a set to one solver (two shells can then share the machine's two cores).
"""
import argparse
import datetime
import json
import os
import subprocess

# (model, mesh, half span, solvers); plane meshes are nx,nz, 3D ones nx,nz,nw (the half's cells).
SETS = {
    "solvers": [
        ("plane", "241,8", False, ["krylov", "direct"]),
        ("plane", "481,16", False, ["krylov", "direct"]),
        ("3d", "120,8,3", True, ["krylov", "direct"]),
        ("3d", "240,12,3", True, ["krylov", "direct"]),
        ("3d", "480,16,3", True, ["krylov", "direct"]),
        ("3d", "480,24,3", True, ["krylov", "direct"]),
    ],
    "half-span": [
        ("3d", "480,16,3", True, ["krylov"]),
        ("3d", "480,24,3", True, ["krylov"]),
        ("3d", "960,16,3", True, ["krylov"]),
    ],
}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bin", default="build/bench/bench_creep_plate_vs_continuum")
    ap.add_argument("--set", choices=sorted(SETS), required=True)
    ap.add_argument("--solver", choices=["krylov", "direct"], help="only this solver")
    ap.add_argument("-o", "--output", required=True, help="JSON lines, appended")
    args = ap.parse_args()
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    for model, mesh, half, solvers in SETS[args.set]:
        for solver in solvers:
            if args.solver and solver != args.solver:
                continue
            cmd = [args.bin, "--plate-meshes", "21,3", "--continuum-solver", solver]
            if model == "plane":
                cmd += ["--plane-meshes", mesh]
            else:
                cmd += ["--plane-meshes", "none", "--solid-meshes", mesh]
            if half:
                cmd.append("--half-length")
            started = datetime.datetime.now(datetime.timezone.utc)
            header = {"kind": "header", "command": " ".join(
                          f'"{c}"' if ";" in c or " " in c else c for c in cmd),
                      "commit": commit,
                      "date": started.strftime("%Y-%m-%d, started %H:%M UTC"),
                      "load_average": f"{os.getloadavg()[0]:.2f} at the start"}
            out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
            with open(args.output, "a") as f:
                f.write(json.dumps(header) + "\n")
                for line in out.splitlines():
                    if line.strip():
                        f.write(line.strip() + "\n")
            print(f"{model} {mesh} {solver}: done", flush=True)


if __name__ == "__main__":
    main()
