#!/usr/bin/python3
"""The Poiseuille flow factor Q(Kn) of a flow-factor table (rfmems-flow-factor) against
Veijola's fit Q = 1 + 9.638 Kn^1.159, the first-order slip form 1 + 6 sigma_P (2 / sqrt(pi)) Kn
(BGK: sigma_P = 1.0162) and, if given, the linearised BGK reference
(python/flow_factor_reference.py): Q on log axes above, below in % the fit's error against the
kinetic Q and the kinetic Q's against the reference.

  plot_flow_factor.py docs/data/flow_factor_bgk.csv \
      --reference docs/data/flow_factor_bgk_reference.csv -o docs/figures/flow_factor.png
"""
import argparse
import csv
import math

import numpy as np

from plotting import plt, run_main, save


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return (np.array([float(r["knudsen"]) for r in rows]),
            np.array([float(r["flow_factor"]) for r in rows]))


def veijola(kn):
    return 1 + 9.638 * kn ** 1.159


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("table")
    ap.add_argument("--reference", help="the linearised BGK reference CSV")
    ap.add_argument("-o", "--output", default="flow_factor.png")
    args = ap.parse_args()
    kn, q = read(args.table)
    fine = np.logspace(math.log10(kn[0]) - 0.3, math.log10(kn[-1]) + 0.3, 200)
    slip = 1 + 6 * 1.0162 * 2 / math.sqrt(math.pi) * fine
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6.4, 7), sharex=True,
                                      gridspec_kw={"height_ratios": [2, 1]})
    top.loglog(fine, veijola(fine), "k-", lw=1, label="Veijola: 1 + 9.638 Kn^1.159")
    top.fill_between(fine, 0.95 * veijola(fine), 1.05 * veijola(fine), color="0.85",
                     label="Veijola +- 5 %")
    top.loglog(fine, slip, "k:", lw=1, label="first-order slip, BGK")
    top.loglog(kn, q, "o", color="C0", label="kinetic (rfmems-flow-factor)")
    bottom.semilogx(kn, 100 * (veijola(kn) / q - 1), "o-", color="C0",
                    label="Veijola's fit against the kinetic Q")
    if args.reference:
        kr, qr = read(args.reference)
        top.loglog(kr, qr, "x", color="C3", label="linearised BGK reference")
        bottom.semilogx(kn, 100 * (q / np.interp(kn, kr, qr) - 1), "s-", color="C3", ms=3,
                        label="kinetic / linearised BGK")
    bottom.axhspan(-5, 5, color="0.9")
    bottom.axhline(0, color="k", lw=0.5)
    top.set_ylabel("flow factor Q = G / (delta / 6)")
    bottom.set_ylabel("deviation [%]")
    bottom.set_xlabel("Kn = lambda / g")
    for ax in (top, bottom):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    print(save(fig, args.output))


if __name__ == "__main__":
    run_main(main)
