#!/usr/bin/python3
"""rfmems-gas's plane Poiseuille flow rate G and plane Couette shear P at the deltas of the
published linearised-BGK solutions (docs/data/kinetic_published_bgk.csv), and ES-BGK's (Pr = 2/3)
at delta = delta_B / Pr (problems poiseuille_esbgk, couette_esbgk: the exact relations of
test/drivers/test_gas_linearised_bgk.sh carry the BGK value at delta_B there), on the driver
test's grids and on finer ones, read from the driver's JSON summary; writes
docs/data/kinetic_published_runs.csv (docs/kinetic.md "Against published tables" is generated from
it by python/results_pages.py).

Set-up as test/drivers/test_gas_linearised_bgk.sh: BGK or ES-BGK, diffuse walls H = 1 m apart,
second-order transport, solver to 1e-6, Gauss-Hermite along the walls (3 points) and half-range
Gauss-Hermite across them, Kn = sqrt(pi) / (2 delta). Poiseuille: cases/gas_poiseuille (body
force, periodic sides, sequential solver). Couette: cases/gas_couette with the walls at -+0.5 m/s
(U / v0 = 0.003) and velocity_grid.extent = 4; delta = 1 / k at Jiang & Luo's k = 0.3, 0.1, 0.03
(BGK), 1.5 / k (ES-BGK).

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

# problem, delta, cells across, points across, solver, role: the driver test's grid, then a finer
# one (cells and points both refined) that says how far the test's grid is from the converged
# answer.
RUNS = [("poiseuille", 0.1, 10, 48, "sequential", "test"),
        ("poiseuille", 0.1, 20, 96, "sequential", "finer"),
        ("poiseuille", 1, 40, 12, "sequential", "test"),
        ("poiseuille", 1, 160, 24, "sequential", "finer"),
        ("poiseuille", 10, 200, 12, "sequential", "test"),
        ("poiseuille", 10, 400, 16, "sequential", "finer"),
        ("couette", 1 / 0.3, 20, 8, "sequential", "test"),
        ("couette", 1 / 0.3, 160, 24, "sequential", "finer"),
        ("couette", 1 / 0.1, 50, 8, "comet", "test"),
        ("couette", 1 / 0.1, 200, 12, "comet", "finer"),
        ("couette", 1 / 0.03, 100, 8, "comet", "test"),
        ("couette", 1 / 0.03, 400, 12, "comet", "finer"),
        ("poiseuille_esbgk", 0.15, 10, 48, "sequential", "test"),
        ("poiseuille_esbgk", 0.15, 20, 96, "sequential", "finer"),
        ("poiseuille_esbgk", 1.5, 40, 24, "sequential", "test"),
        ("poiseuille_esbgk", 1.5, 160, 48, "sequential", "finer"),
        ("poiseuille_esbgk", 15, 200, 12, "sequential", "test"),
        ("poiseuille_esbgk", 15, 400, 16, "sequential", "finer"),
        ("couette_esbgk", 5, 20, 8, "sequential", "test"),
        ("couette_esbgk", 5, 160, 24, "sequential", "finer"),
        ("couette_esbgk", 15, 50, 8, "comet", "test"),
        ("couette_esbgk", 15, 200, 12, "comet", "finer"),
        ("couette_esbgk", 50, 100, 8, "comet", "test"),
        ("couette_esbgk", 50, 400, 12, "comet", "finer")]

# The JSON key of each problem's normalised answer.
VALUE = {"poiseuille": lambda d: d["flow_rate"]["normalised_flow_rate"],
         "couette": lambda d: d["walls"]["bottom"]["normalised_shear"]}


def run(driver, problem, delta, cells, across, solver):
    kn = math.sqrt(math.pi) / (2 * delta)
    flow, _, collision = problem.partition("_")
    cmd = [str(driver), str(ROOT / "cases" / f"gas_{flow}" / "case.yaml"),
           "--set", f"gas.collision={collision or 'bgk'}",
           "--set", f"initial.knudsen={kn:.17g}", "--set", f"mesh.cells=[1, {cells}]",
           "--set", f"velocity_grid.points=[3, {across}, 3]",
           "--set", "velocity_grid.type=gauss_hermite",
           "--set", "velocity_grid.y={type: half_range_hermite}", "--set", f"solver.type={solver}"]
    if flow == "couette":
        cmd += ["--set", "velocity_grid.extent=4",
                "--set", "solver.transport=second_order",
                "--set", "boundaries.bottom.velocity=[0 m/s, 0 m/s, -0.5 m/s]",
                "--set", "boundaries.top.velocity=[0 m/s, 0 m/s, 0.5 m/s]"]
    cmd += ["-o", "/tmp/kinetic_published_runs.h5", "--json", "--quiet"]
    d = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    assert d["solver"]["converged"] and d["collision"] == (collision or "bgk"), d["solver"]
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
    lines = ["# rfmems-gas's plane Poiseuille G (JSON flow_rate.normalised_flow_rate) and plane",
             "# Couette P (JSON walls.bottom.normalised_shear) at the deltas of",
             "# docs/data/kinetic_published_bgk.csv, BGK, and ES-BGK (problems *_esbgk, Pr = 2/3)",
             "# at those deltas over Pr; grids: Gauss-Hermite along the walls (3 points),",
             "# half-range Gauss-Hermite across (points), cells across H; role 'test' is the grid of",
             "# test/drivers/test_gas_linearised_bgk.sh, 'finer' a refinement of both. Iterations:",
             "# sweeps, or COMET's outer iterations (method). Seconds: the solve's wall time on the",
             "# shared 2-core machine.",
             f"# Command: /usr/bin/python3 python/kinetic_published_runs.py --bin {args.bin}, "
             f"{datetime.date.today()} (commit {commit}; 1-minute load average {load}).",
             "problem,delta,role,cells,velocity_points,velocities,method,iterations,seconds,value"]
    for problem, delta, cells, across, solver, role in RUNS:
        d = run(driver, problem, delta, cells, across, solver)
        s = d["solver"]
        lines.append(f"{problem},{delta:.10g},{role},{cells},3x{across}x3,"
                     f"{d['velocity_grid']['ordinates']},{s['method']},{s['iterations']},"
                     f"{s['seconds']:.3g},{VALUE[problem.partition('_')[0]](d):.7f}")
        print(lines[-1], file=sys.stderr)
    OUT.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
