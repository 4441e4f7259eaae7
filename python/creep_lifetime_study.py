#!/usr/bin/python3
"""Creep life of a held switch vs hold voltage: a derating curve.

Runs rfmems-creep on a switch creep case (default cases/creep_switch_hold/case.yaml) at each
hold voltage (--set actuation.voltage=V, end time long enough for the life to be reached),
and writes
  <PREFIX>.csv    voltage [V], life [h], how the life ended, initial and final smallest gap [um],
                  IDA steps, wall time [s]
  <PREFIX>.png    life vs hold voltage (log scale), with the derating read-off for --target
and prints the table and the highest hold voltage whose life reaches --target hours
(log-linear interpolation between the bracketing runs).

Usage: creep_lifetime_study.py [--driver build/drivers/rfmems-creep] [--case CASE]
           [--voltages 100,120,...] [--end-time-h 100000] [--target-h 1000] [-o out/creep_lifetime]
           [--set KEY=VALUE ...]
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from study_runs import run_driver, write_csv  # noqa: E402


def run(args, voltage):
    out = f"{args.prefix}_V{voltage:g}.h5"
    cmd = [args.driver, args.case, "--json", "--quiet", "-o", out,
           "--set", f"actuation.voltage={voltage} V",
           "--set", f"creep.end_time={args.end_time_h} h"]
    return run_driver(cmd, args.set, "creep_lifetime_study.py")


def derating(rows, target):
    """Highest voltage with life >= target, interpolating log(life) linearly in V."""
    rows = sorted((r for r in rows if r["life_h"] is not None), key=lambda r: r["voltage"])
    best = None
    for lo, hi in zip(rows, rows[1:]):
        if lo["life_h"] >= target > hi["life_h"]:
            f = (math.log(target) - math.log(lo["life_h"])) / (math.log(hi["life_h"]) - math.log(lo["life_h"]))
            best = lo["voltage"] + f * (hi["voltage"] - lo["voltage"])
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--driver", default="build/drivers/rfmems-creep")
    parser.add_argument("--case", default="cases/creep_switch_hold/case.yaml")
    parser.add_argument("--voltages", default="100,120,140,150,160,170,175,180,184,186,188")
    parser.add_argument("--end-time-h", type=float, default=100000.0)
    parser.add_argument("--target-h", type=float, default=1000.0)
    parser.add_argument("-o", "--prefix", default="out/creep_lifetime")
    parser.add_argument("--set", action="append", help="extra case override (repeatable)")
    args = parser.parse_args()
    os.makedirs(os.path.dirname(args.prefix) or ".", exist_ok=True)

    rows = []
    print(f"{'V':>7} {'life [h]':>11} {'end':>16} {'gap0 [um]':>10} {'gap end [um]':>12} {'steps':>6} {'wall [s]':>8}")
    for v in (float(x) for x in args.voltages.split(",")):
        s = run(args, v)
        life = s["lifetime_h"] if s["life_reached"] else None
        gap0 = s["initial_min_gap"] * 1e6
        r = {"voltage": v, "life_h": life, "end": s["end"], "initial_gap_um": gap0,
             "final_gap_um": s["final"]["min_gap"] * 1e6, "steps": s["steps"],
             "wall_time_s": s["wall_time_s"]}
        rows.append(r)
        print(f"{v:7.1f} {life if life is not None else float('nan'):11.5g} {s['end']:>16} "
              f"{gap0:10.4f} {r['final_gap_um']:12.4f} {s['steps']:6d} {s['wall_time_s']:8.2f}")
    write_csv(args.prefix + ".csv", rows)

    limit = derating(rows, args.target_h)
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    pts = [(r["voltage"], r["life_h"]) for r in rows if r["life_h"]]
    ax.semilogy([p[0] for p in pts], [p[1] for p in pts], "o-", label="creep life")
    ax.axhline(args.target_h, color="gray", ls="--", lw=1)
    if limit is not None:
        ax.axvline(limit, color="gray", ls=":", lw=1)
        ax.annotate(f"{args.target_h:g} h: V <= {limit:.1f} V", (limit, args.target_h),
                    textcoords="offset points", xytext=(-120, 10), fontsize=9)
    ax.set_xlabel("hold voltage [V]")
    ax.set_ylabel("creep life [h]")
    ax.set_title(os.path.basename(os.path.dirname(os.path.abspath(args.case))))
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(args.prefix + ".png", dpi=120)
    if limit is not None:
        print(f"life >= {args.target_h:g} h for hold voltages up to {limit:.2f} V")
    else:
        print(f"no bracket of {args.target_h:g} h among the voltages run")
    print(f"wrote {args.prefix}.csv, {args.prefix}.png")


if __name__ == "__main__":
    main()
