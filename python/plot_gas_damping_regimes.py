#!/usr/bin/python3
"""One plot, damping ratio vs pressure, all gas models (docs/gas_damping.md).

Reads the JSON lines of python/gas_damping_regimes_study.py (ESBGK runs; the references are
recomputed on a dense pressure grid by the same module's formulas) and writes a PNG.

Usage: plot_gas_damping_regimes.py [out/gas_damping_regimes.jsonl] [-o docs/figures/gas_damping_regimes.png]
"""
import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gas_damping_regimes_study as study  # noqa: E402
from plotting import run_main  # noqa: E402


def richardson(rows):
    """Extrapolation of the continuum-end runs refined as a whole (refine r): c(h) = c0 + A h^q
    from the two finest, q the observed order of the three finest where there are three (within
    [1, the scheme's order]: the beam's corners hold second order to ~1.6 at 1e5 Pa,
    docs/gas_damping.md), else the scheme's order (1, or 2 for transport second_order)."""
    rs = sorted((r for r in rows if r["gap_refine"] == 1 and r["points"] == rows[0]["points"]),
                key=lambda r: r["refine"])
    if len(rs) < 2:
        return None
    c = [r["esbgk"] for r in rs]
    ratio = rs[-1]["refine"] / rs[-2]["refine"]
    scheme = 2 if rs[-1].get("transport") == "second_order" else 1
    order = None
    if len(rs) >= 3 and (c[-2] - c[-1]) != 0:
        order = np.log(abs((c[-3] - c[-2]) / (c[-2] - c[-1]))) / np.log(ratio)
    q = min(max(order, 1), scheme) if order is not None else scheme
    extrapolated = (ratio**q * c[-1] - c[-2]) / (ratio**q - 1)
    return {"pressure": rs[-1]["pressure"], "extrapolated": extrapolated, "order": order,
            "assumed_order": q,
            "refines": [r["refine"] for r in rs], "values": c}


def stokes_points(path):
    """The Maxwell-slip limits of a bench_stokes_damping run (its first Richardson line):
    pressures, c, and a label naming the open sides."""
    if not os.path.exists(path):
        return None
    lines = [json.loads(line) for line in open(path) if line.strip()]
    first = lines[0]
    limits = next((x for x in lines if "richardson_h_um" in x), None)
    if limits is None:
        return None
    keys = sorted((k for k in limits if k.startswith("c_slip_")), key=lambda k: -float(k[7:]))
    kinetic = first.get("open_impedance", 0) > 0
    label = ("Stokes + Maxwell slip, h $\\to$ 0, sides: "
             + ("kinetic pressure boundary (impedance)" if kinetic else "open (continuum)"))
    return [float(k[7:]) for k in keys], [limits[k]["extrapolated"] for k in keys], label


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("jsonl", nargs="?", default=os.path.join(root, "out", "gas_damping_regimes.jsonl"))
    ap.add_argument("--tpmc", default=os.path.join(root, "docs", "figures",
                                                   "gas_damping_regimes_tpmc.jsonl"),
                    help="free_molecular_beam_tpmc.py output (JSON lines), if present")
    ap.add_argument("--stokes", nargs="*", default=[
        os.path.join(root, "docs", "figures", f) for f in
        ("stokes_damping.jsonl", "stokes_damping_kinetic_open.jsonl")],
        help="bench_stokes_damping outputs: their extrapolated slip points, if present")
    ap.add_argument("-o", dest="png", default=os.path.join(root, "docs", "figures",
                                                           "gas_damping_regimes.png"))
    args = ap.parse_args()
    rows = [json.loads(line) for line in open(args.jsonl) if line.strip()]
    rows = [r for r in rows if not r.get("extra")]  # variants (--set ...) are tables, not curves
    # Rows of the other transport than the first row's: shown as points only.
    scheme = rows[0].get("transport", "first_order")
    other = [r for r in rows if r.get("transport", "first_order") != scheme]
    rows = [r for r in rows if r.get("transport", "first_order") == scheme]
    base = min(r["points"] for r in rows)
    sweep = sorted((r for r in rows if r.get("refine", 1) == 1 and r["gap_refine"] == 1
                    and r["points"] == base), key=lambda r: r["pressure"])
    p_max = max(r["pressure"] for r in sweep)
    top = [r for r in rows if r["pressure"] == p_max and r["points"] == base]
    for r in top:
        r.setdefault("refine", 1)
    extrapolation = richardson(top)

    p = np.logspace(-1, 5, 200)
    zeta = study.damping_ratio
    kn = np.array([study.knudsen(x) for x in p])
    fig, ax = plt.subplots(figsize=(7.5, 5))
    ax.loglog(p, [zeta(study.free_molecular_continuous(x)) for x in p], "k--", lw=1,
              label="free molecular, isolated beam (closed form)")
    if os.path.exists(args.tpmc):
        tp = [json.loads(line) for line in open(args.tpmc) if line.strip()]
        tp = [t for t in tp if t["substrate"]]
        if tp:
            t = max(tp, key=lambda t: t["particles"] * t["batches"])
            low = p[kn >= 10]
            ax.loglog(low, [zeta(t["c"] / t["pressure"] * x) for x in low], "k-", lw=2.5,
                      alpha=0.35, label="free molecular, beam over substrate (test-particle MC)")
    ax.loglog(p, [zeta(study.reynolds(x, edge=False)) for x in p], "C1-",
              label="Reynolds film, Veijola $\\mu_{eff}$")
    edge = kn <= 1
    ax.loglog(p[edge], [zeta(study.reynolds(x, edge=True)) for x in p[edge]], "C2-",
              label="Reynolds, Veijola $\\mu_{eff}$ + edge elongation (Kn $\\leq$ 1)")
    cont = kn <= 0.1
    ax.loglog(p[cont], [zeta(study.reynolds(x, edge=True, rarefied=False)) for x in p[cont]],
              "C2:", label="continuum Reynolds + elongation (no slip)")
    ax.loglog([r["pressure"] for r in sweep], [r["damping_ratio_esbgk"] for r in sweep], "C0o-",
              label=f"ESBGK, {sweep[0]['cells']} cells, {base}$^3$ velocities"
              + (", 2nd-order transport" if sweep[0].get("transport") == "second_order" else ""))
    for r in rows:
        r.setdefault("refine", 1)
    meshed = [r for r in rows if r["refine"] > 1 and r["points"] == base]
    ax.loglog([r["pressure"] for r in meshed], [r["damping_ratio_esbgk"] for r in meshed], "C0^",
              mfc="none", ls="none", label="ESBGK, whole mesh refined 2, 4, 8, ... (r)")
    for r in meshed:
        ax.annotate(f"r={r['refine']}", (r["pressure"], r["damping_ratio_esbgk"]), fontsize=7,
                    xytext=(-22, -3), textcoords="offset points")
    gapped = [r for r in rows if r["gap_refine"] > 1 and r["points"] == base]
    if gapped:
        ax.loglog([r["pressure"] for r in gapped], [r["damping_ratio_esbgk"] for r in gapped],
                  "C0.", ls="none", label="ESBGK, gap cells only refined 2, 4, 8")
    if extrapolation:
        ax.loglog([extrapolation["pressure"]], [zeta(extrapolation["extrapolated"])], "C3*",
                  ms=12, label="ESBGK, Richardson h $\\to$ 0 (refine "
                  + ", ".join(str(x) for x in extrapolation["refines"][-2:]) + ")")
    vel = [r for r in rows if r["points"] != base]
    if vel:
        ax.loglog([r["pressure"] for r in vel], [r["damping_ratio_esbgk"] for r in vel], "C4s",
                  mfc="none", ls="none", label="ESBGK, " + ", ".join(
                      f"{n}$^3$" for n in sorted({r["points"] for r in vel})) + " velocities")
    if other:
        ax.loglog([r["pressure"] for r in other], [r["damping_ratio_esbgk"] for r in other], "C7x",
                  ls="none", label="ESBGK, " + other[0].get("transport", "first_order").replace(
                      "_", " ") + f", {other[0]['cells']} cells")
    for path, style in zip(args.stokes, ("C5D", "C3D")):
        point = stokes_points(path)
        if point:
            ax.loglog(point[0], [zeta(c) for c in point[1]], style, mfc="none", ms=7, ls="none",
                      label=point[2])
    ax.set_xlabel("pressure [Pa] (argon, 273.15 K)")
    ax.set_ylabel("damping ratio $\\zeta = c / (2 m \\omega_0)$")
    ax.set_title("Beam 45 x 1.5 $\\mu$m, 7 $\\mu$m over the substrate, moving at 0.1 m/s", fontsize=10)
    secax = ax.secondary_xaxis("top", functions=(lambda x: study.knudsen(1.0) / np.maximum(x, 1e-30),
                                                 lambda k: study.knudsen(1.0) / np.maximum(k, 1e-30)))
    secax.set_xlabel("Kn = $\\lambda$ / g")
    ax.grid(True, which="major", color="0.85", lw=0.5)
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    tmp = args.png + ".tmp.png"
    fig.savefig(tmp, dpi=130)
    os.replace(tmp, args.png)
    if extrapolation:
        print(json.dumps({"richardson": extrapolation}))


if __name__ == "__main__":
    run_main(main)
