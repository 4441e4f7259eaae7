#!/usr/bin/python3
"""Work against error of the velocity grids: bench_velocity_grids' JSON lines
(docs/figures/velocity_grids.jsonl) as one panel per problem and delta, |error| against the
number of velocities, one line per grid family (uniform; Gauss-Hermite along the walls with
half-range Gauss-Hermite, sinh-stretched midpoints or Gauss-Hermite across them). The dotted
line is the error of today's uniform grid, the shaded band a quarter of its velocities or fewer;
open markers: half-range runs on more cells than the set-up's (Poiseuille at delta = 10).

  plot_velocity_grids.py docs/figures/velocity_grids.jsonl -o docs/figures/velocity_grids.png
"""
import argparse
import json

from plotting import plt, run_main, save

PROBLEMS = [("couette", "Couette P"), ("heat", "heat flux q*"), ("poiseuille", "Poiseuille G")]
STYLE = {"uniform": ("uniform", "o", "k"),
         "gh+hr": ("GH along, half-range GH across", "s", "tab:blue"),
         "gh+sinh": ("GH along, sinh-stretched across", "^", "tab:orange"),
         "gh": ("GH along and across", "v", "tab:green")}


def today(problem, delta):
    """Points of the uniform grid test_gas_linearised_bgk.sh uses today."""
    along = 12 if problem == "heat" else 8
    return [along, 32 if delta >= 10 else 64, along]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("jsonl")
    ap.add_argument("-o", "--output", default="velocity_grids.png")
    args = ap.parse_args()
    runs = [json.loads(x) for x in open(args.jsonl) if x.strip().startswith("{")]
    runs = [r for r in runs if "error" in r]
    deltas = sorted({r["delta"] for r in runs})
    fig, axes = plt.subplots(len(PROBLEMS), len(deltas), figsize=(3.2 * len(deltas), 8.5),
                             squeeze=False)
    for i, (problem, title) in enumerate(PROBLEMS):
        for j, delta in enumerate(deltas):
            ax = axes[i][j]
            here = [r for r in runs if r["problem"] == problem and r["delta"] == delta]
            # Lines on the set-up's cells; runs on more cells as open markers, one per count.
            cells = min(r["cells"] for r in here)
            for grid, (label, marker, colour) in STYLE.items():
                pts = sorted((r["ordinates"], abs(r["error"])) for r in here
                             if r["grid"] == grid and r["cells"] == cells)
                if pts:
                    ax.loglog(*zip(*pts), marker=marker, color=colour, label=label, ms=4)
                for more in sorted({r["cells"] for r in here if r["grid"] == grid} - {cells}):
                    pts = sorted((r["ordinates"], abs(r["error"])) for r in here
                                 if r["grid"] == grid and r["cells"] == more)
                    ax.loglog(*zip(*pts), marker=marker, color=colour, ls=":", mfc="none", ms=5,
                              label=f"{label}, {more} cells")
                    ax.legend(fontsize=5, loc="lower left")
            base = [r for r in here if r["grid"] == "uniform" and r["points"] == today(problem, delta)]
            if base:
                n0, e0 = base[0]["ordinates"], abs(base[0]["error"])
                ax.axhline(e0, color="k", ls=":", lw=0.8)
                ax.axvspan(ax.get_xlim()[0], n0 / 4, color="tab:green", alpha=0.08)
            ax.axhline(2e-3, color="r", ls="--", lw=0.6)
            ax.set_title(f"{title}, delta = {delta:g}", fontsize=9)
            if i == len(PROBLEMS) - 1:
                ax.set_xlabel("velocities")
            if j == 0:
                ax.set_ylabel("|error| against the reference")
            ax.tick_params(labelsize=7)
    axes[0][0].legend(fontsize=6, loc="lower left")
    fig.suptitle("Velocity grids: error against velocities (dotted: today's uniform grid; "
                 "dashed: 0.2 %; shaded: <= 1/4 of its velocities)", fontsize=9)
    save(fig, args.output, dpi=130)


if __name__ == "__main__":
    run_main(main)
