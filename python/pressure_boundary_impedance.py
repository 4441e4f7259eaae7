#!/usr/bin/python3
"""The normal impedance of the kinetic pressure boundary (docs/gas_damping.md "Why
ESBGK sat 10.5 % above the Stokes reference"), measured with rfmems-gas.

Slab L x L (2 x N quads, specular sides): the bottom a diffuse wall moving along its normal
at +-V into the gas, the top a pressure boundary at p_a (the ambient Maxwellian at rest). The
flow is uniform and the wall's emission is the gas's own drifting Maxwellian, so the wall's
normal traction is the bulk pressure p; its odd part in V gives
    C = (p - p_a) / (p_a V / sqrt(2 R T))
(the linearised condensation jump; 2.13 for BGK, 2.01 collisionless). Prints one JSON line
per SPEC = KN:ROWS:POINTS:TRANSPORT. test_kinetic_pressure_boundary.cpp asserts the 12^3
values.

Usage: pressure_boundary_impedance.py [--driver build/drivers/rfmems-gas] SPEC...
  e.g. 0.05:40:8:second_order 0.01:80:8:second_order 0.05:40:16:second_order
"""
import argparse
import json
import math
import os
import resource
import subprocess
import tempfile

R, T, MU = 208.13, 273.15, 2.117e-5  # argon (KineticGas::argon)
V = 0.1
CASE = """name: pressure_boundary_impedance
mesh: {type: rectangle, size: [1 m, 1 m], cells: [2, 40]}
gas: {collision: esbgk}
initial: {T: 273.15 K, density: 1e-5 kg/m^3}
velocity_grid: {points: [8, 8, 8], extent: 3.5}
boundaries:
  bottom: {type: diffuse_wall, T: 273.15 K, velocity: [0 m/s, 0.1 m/s]}
  top: {type: pressure, p: 1 Pa, T: 273.15 K}
  left: {type: specular_wall}
  right: {type: specular_wall}
solver: {type: comet, tolerance: 1e-9, transport: second_order}
output: {forces: [bottom]}
"""


def bulk_pressure(driver, case, out, kn, rows, points, v, transport):
    p = MU * math.sqrt(math.pi * R * T / 2) / kn  # lambda = kn * (L = 1 m)
    cmd = [driver, case, "--json", "--quiet", "-o", out,
           "--set", f"initial.density={p / (R * T)!r} kg/m^3", "--set", f"mesh.cells=[2,{rows}]",
           "--set", f"velocity_grid.points=[{points},{points},{points}]",
           "--set", f"solver.transport={transport}",
           "--set", f"boundaries.bottom.velocity=[0 m/s, {v!r} m/s]",
           "--set", f"boundaries.top.p={p!r} Pa"]
    d = json.loads(subprocess.run(cmd, capture_output=True, text=True, check=True).stdout)
    return -d["walls"]["bottom"]["force"][1], p, d["solver"]["iterations"]


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--driver", default=os.path.join(root, "build/drivers/rfmems-gas"))
    ap.add_argument("specs", nargs="+")
    args = ap.parse_args()
    c0 = math.sqrt(2 * R * T)
    with tempfile.TemporaryDirectory() as tmp:
        case = os.path.join(tmp, "case.yaml")
        with open(case, "w") as f:
            f.write(CASE)
        for spec in args.specs:
            kn, rows, points, transport = spec.split(":")
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            runs = [bulk_pressure(args.driver, case, os.path.join(tmp, "s.h5"), float(kn),
                                  int(rows), int(points), v, transport) for v in (V, -V)]
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            (up, p, it_up), (down, _, it_down) = runs
            print(json.dumps({"knudsen": float(kn), "rows": int(rows), "points": int(points),
                              "transport": transport, "C": (up - down) / (2 * V) * c0 / p,
                              "even": (up + down) / (2 * p) - 1, "cycles": [it_up, it_down],
                              "cpu_seconds": after.ru_utime + after.ru_stime
                              - before.ru_utime - before.ru_stime}), flush=True)


if __name__ == "__main__":
    main()
