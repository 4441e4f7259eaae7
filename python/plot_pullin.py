#!/usr/bin/python3
"""Plots of an rfmems-pullin result file (coupling/pull_in_study.hpp).

  <PREFIX>_curve.png     control deflection vs voltage: stable branch, unstable branch, fold
  <PREFIX>_dynamic.png   control deflection vs time for the recorded step voltages (dynamic)
  <PREFIX>_forces.png    electrostatic and gas force vs time for the same runs (dynamic)
  <PREFIX>_release.png   with pull_in.release: smallest gap and voltage vs time through
                         touch-down, rest on the dielectric, the drop to the hold voltage and
                         the release; the contact branch (pull-out) is added to the curve plot
  <PREFIX>_harmonic.png  mode harmonic: the control's response per volt of AC amplitude about
                         the DC bias (amplitude and phase) against frequency and, with a film,
                         the film's spring and damping coefficients against frequency

Usage: plot_pullin.py RESULT.h5 [-o PREFIX]     (PREFIX defaults to RESULT without .h5)
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import finish, open_result, prefix_args, run_main  # noqa: E402

# The y label of the voltage curve and of the dynamic histories.
DEFLECTION = "control deflection towards the electrode [µm]"


def main():
    args, prefix = prefix_args(__doc__.splitlines()[0])
    written = []
    with open_result(args.result) as f:
        if "pull_in/curve" not in f:
            sys.exit(f"plot_pullin.py: {args.result}: no /pull_in/curve (not an rfmems-pullin result?)")
        summary = json.loads(f["metadata"].attrs["summary"])["pull_in"]
        curve = f["pull_in/curve"]
        delta = curve["control_displacement"][()] * 1e6
        values = curve["values"][()]
        voltage, stable = values[:, 0], values[:, 2] > 0.5
        fig, ax = plt.subplots(figsize=(7, 4.5))
        ax.plot(voltage[stable], -delta[stable], "-", color="C0", label="stable branch")
        ax.plot(voltage[~stable], -delta[~stable], "--", color="C1", label="unstable branch")
        v_pi = summary["quasi_static"]["pull_in_voltage"]
        w_pi = -summary["quasi_static"]["pull_in_displacement"] * 1e6
        ax.plot([v_pi], [w_pi], "o", color="k", label=f"fold: V_PI = {v_pi:.2f} V")
        if "pull_in/contact_branch" in f:
            branch = f["pull_in/contact_branch"]
            bv = branch["voltage"][()]
            bw = -branch["values"][()][:, 0] * 1e6
            v_po = summary["quasi_static"]["pull_out_voltage"]
            ax.plot(bv, bw, "-", color="C2", label="in contact (voltage decreasing)")
            ax.plot([bv[0]], [bw[0]], "s", color="C2", label=f"pull-out: V_PO = {v_po:.2f} V")
        if "dynamic" in summary:
            ax.axvline(summary["dynamic"]["pull_in_voltage"], color="C3", lw=0.8,
                       label=f"dynamic V_PI = {summary['dynamic']['pull_in_voltage']:.2f} V")
        written.append(finish(fig, ax, "voltage [V]", DEFLECTION, prefix + "_curve.png"))

        if "dynamic" in f:
            runs = sorted((k for k in f["dynamic"].keys() if k[0] == "V" and k[1:].isdigit()),
                          key=lambda k: int(k[1:]))
            histories = summary["dynamic"]["histories"]
            fig, ax = plt.subplots(figsize=(7, 4.5))
            fig2, ax2 = plt.subplots(figsize=(7, 4.5))
            for k, name in enumerate(runs):
                t = f["dynamic"][name]["time"][()] * 1e6
                v = f["dynamic"][name]["values"][()]
                label = f"{histories[k]['voltage']:.1f} V" + (" (pulls in)" if histories[k]["pulled_in"] else "")
                ax.plot(t, -v[:, 0] * 1e6, label=label)
                ax2.plot(t, -v[:, 2] * 1e6, color=f"C{k}", label=f"electrostatic, {label}")
                ax2.plot(t, v[:, 3] * 1e6, "--", color=f"C{k}", label=f"gas, {label}")
            written += [finish(fig, ax, "time [µs]", DEFLECTION, prefix + "_dynamic.png"),
                        finish(fig2, ax2, "time [µs]", "force [µN]: electrostatic pull, gas push",
                               prefix + "_forces.png", fontsize="small")]

        if "dynamic/release" in f:
            rel = summary["dynamic"]["release"]
            t = f["dynamic/release/time"][()] * 1e6
            v = f["dynamic/release/values"][()]
            fig, ax = plt.subplots(figsize=(7, 4.5))
            ax.plot(t, v[:, 1] * 1e6, color="C0", label="smallest gap")
            ax.axhline(summary["contact"]["gap"] * 1e6, color="k", lw=0.6, ls=":",
                       label="contact gap")
            ax.axvline(rel["pull_in_time"] * 1e6, color="C3", lw=0.8, ls="--", label="touch-down")
            ax.axvline(rel["drop_time"] * 1e6, color="C1", lw=0.8, ls="--",
                       label=f"drop to {rel['hold_voltage']:.1f} V")
            if rel["released"]:
                ax.axvline((rel["drop_time"] + rel["release_time"]) * 1e6, color="C2", lw=0.8,
                           ls="--", label="release")
            axv = ax.twinx()
            axv.plot(t, v[:, 5], color="C7", lw=0.8)
            axv.set_ylabel("voltage [V] (grey)")
            title = f"step to {rel['voltage']:.1f} V, hold {rel['hold_voltage']:.1f} V"
            if "pull_out_voltage" in rel:
                title += f"; dynamic pull-out {rel['pull_out_voltage']:.2f} V"
            ax.set_title(title, fontsize="medium")
            written.append(finish(fig, ax, "time [µs]", "smallest gap [µm]",
                                  prefix + "_release.png", fontsize="small", loc="center right"))
        if "pull_in/harmonic" in f:
            written.append(plot_harmonic(f["pull_in/harmonic"], summary["harmonic"],
                                         prefix + "_harmonic.png"))
    print("wrote " + ", ".join(written))


def plot_harmonic(group, summary, path):
    """Bode plot of the control's response per AC volt; the film's spring and damping."""
    freq = group["frequency"][()]
    values = group["values"][()]
    names = [n.decode() if isinstance(n, bytes) else str(n) for n in group["values"].attrs["components"]]
    column = {n: values[:, i] for i, n in enumerate(names)}
    response = column["control_real"] + 1j * column["control_imag"]
    film = "film_spring" in column
    fig, axes = plt.subplots(3 if film else 2, 1, figsize=(7, 8 if film else 6), sharex=True)
    axes[0].loglog(freq, abs(response) * 1e9, "-", color="C0")
    axes[0].set_ylabel("control amplitude [nm/V]")
    axes[0].set_title(f"small-signal response about {summary['bias']:.2f} V DC", fontsize="medium")
    axes[1].semilogx(freq, np.degrees(np.angle(response)), "-", color="C0")
    axes[1].set_ylabel("phase to the AC voltage [deg]")
    if film:
        axes[2].loglog(freq, np.abs(column["film_spring"]), "-", color="C1",
                       label="spring k_film [N/m]")
        axes[2].loglog(freq, column["film_damping"] * 2 * np.pi * freq, "--", color="C2",
                       label="damping x omega, omega c_film [N/m]")
        axes[2].set_ylabel("film impedance per mean gap [N/m]")
        axes[2].legend(fontsize="small")
    axes[-1].set_xlabel("frequency [Hz]")
    for ax in axes:
        ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


if __name__ == "__main__":
    run_main(main)
