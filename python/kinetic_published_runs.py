#!/usr/bin/python3
"""rfmems-gas's plane Poiseuille flow rate G at the deltas of the published linearised-BGK table
(docs/data/kinetic_published_bgk.csv), on the driver test's grids and on finer ones, read from the
driver's JSON summary; writes docs/data/kinetic_published_runs.csv (docs/kinetic.md "Against
published tables" is generated from it by python/results_pages.py).

Set-up: cases/gas_poiseuille (BGK, diffuse walls H = 1 m apart, body force, periodic sides,
second-order transport, sequential solver to 1e-6), Gauss-Hermite along the walls (3 points) and
half-range Gauss-Hermite across them; Kn = sqrt(pi) / (2 delta).

  /usr/bin/python3 python/kinetic_published_runs.py --bin build/drivers
"""
import argparse
import datetime
import json
import math
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "docs" / "data" / "kinetic_published_runs.csv"

# delta, cells across, points across, role: the driver test's grid, then a finer one (cells and
# points both refined) that says how far the test's grid is from the converged answer.
RUNS = [(0.1, 10, 48, "test"), (0.1, 20, 96, "finer"),
        (1, 40, 12, "test"), (1, 160, 24, "finer"),
        (10, 200, 12, "test"), (10, 400, 16, "finer")]


def run(driver, delta, cells, across):
    kn = math.sqrt(math.pi) / (2 * delta)
    cmd = [str(driver), str(ROOT / "cases" / "gas_poiseuille" / "case.yaml"),
           "--set", f"initial.knudsen={kn:.17g}", "--set", f"mesh.cells=[1, {cells}]",
           "--set", f"velocity_grid.points=[3, {across}, 3]",
           "--set", "velocity_grid.type=gauss_hermite",
           "--set", "velocity_grid.y={type: half_range_hermite}",
           "-o", "/tmp/kinetic_published_runs.h5", "--json", "--quiet"]
    d = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    assert d["solver"]["converged"], d["solver"]
    assert abs(d["reference"]["rarefaction_parameter"] / delta - 1) < 1e-9, d["reference"]
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bin", required=True, help="directory of the drivers (build/drivers)")
    args = ap.parse_args()
    driver = Path(args.bin) / "rfmems-gas"
    commit = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    with open("/proc/loadavg") as f:
        load = f.read().split()[0]
    lines = ["# rfmems-gas's plane Poiseuille G (JSON flow_rate.normalised_flow_rate) at the deltas of",
             "# docs/data/kinetic_published_bgk.csv; grids: Gauss-Hermite along the walls (3 points),",
             "# half-range Gauss-Hermite across (points), cells across H; role 'test' is the grid of",
             "# test/drivers/test_gas_linearised_bgk.sh, 'finer' a refinement of both. Seconds: the",
             "# solve's wall time on the shared 2-core machine.",
             f"# Command: /usr/bin/python3 python/kinetic_published_runs.py --bin {args.bin}, "
             f"{datetime.date.today()} (commit {commit}; 1-minute load average {load}).",
             "problem,delta,role,cells,velocity_points,velocities,sweeps,seconds,value"]
    for delta, cells, across, role in RUNS:
        d = run(driver, delta, cells, across)
        s = d["solver"]
        lines.append(f"poiseuille,{delta:g},{role},{cells},3x{across}x3,"
                     f"{d['velocity_grid']['ordinates']},{s['iterations']},{s['seconds']:.3g},"
                     f"{d['flow_rate']['normalised_flow_rate']:.6f}")
        print(lines[-1], file=sys.stderr)
    OUT.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
