#!/usr/bin/python3
"""First natural frequency of the switch against DC bias, from bench_modal's raw output.

  <PREFIX>.png   f / f0 of the plate (bench/bench_modal.cpp, section "bias": the plate linearised
                 about each state of its quasi-static pull-in curve) against V / V_PI, and the
                 1-DOF parallel-plate actuator's closed form (f / f0)^2 = 1 - (8/27) v^2 / x^3

Read: the JSON lines of `bench_modal` (docs/data/modal_bench.jsonl), its "bias" lines.

Usage: plot_modal_bias.py BENCH.jsonl [-o PREFIX]    (PREFIX defaults to BENCH without .jsonl)
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import finish, prefix_args, run_main  # noqa: E402


def lumped_ratio(v):
    """The 1-DOF actuator's f / f0 at v = V / V_PI (x = g / g0 on the stable branch)."""
    x = np.array([max(r.real for r in np.roots([-1, 1, 0, -4 / 27 * vi * vi]) if abs(r.imag) < 1e-12)
                  for vi in v])
    return np.sqrt(np.maximum(0, 1 - 8 / 27 * v * v / x**3))


def main():
    args, prefix = prefix_args(__doc__.splitlines()[0])
    if prefix.endswith(".jsonl"):
        prefix = prefix[:-len(".jsonl")]
    try:
        with open(args.result) as f:
            rows = [json.loads(line) for line in f if line.strip()]
    except OSError as e:
        raise OSError(f"{args.result}: {e}") from e
    except (UnicodeDecodeError, json.JSONDecodeError) as e:
        print(f"plot_modal_bias.py: {args.result}: not JSON lines ({e})", file=sys.stderr)
        sys.exit(2)
    bias = [r for r in rows if r.get("section") == "bias"]
    if not bias:
        print(f"plot_modal_bias.py: {args.result}: no 'bias' lines (not bench_modal output?)",
              file=sys.stderr)
        sys.exit(2)
    v = np.array([r["voltage"] / r["pull_in_voltage"] for r in bias])
    ratio = np.array([r["frequency_ratio"] for r in bias])
    fig, ax = plt.subplots(figsize=(6, 4))
    dense = np.linspace(0, 1, 400)
    ax.plot(dense, lumped_ratio(dense), "-", color="0.5", label="1-DOF parallel-plate actuator")
    ax.plot(v, ratio, "o", ms=4,
            label=f"plate, {bias[0]['case']} (f0 = {bias[0]['frequency_hz'] / 1e3:.1f} kHz, "
                  f"V_PI = {bias[0]['pull_in_voltage']:.1f} V)")
    ax.set_xlim(0, 1.02)
    ax.set_ylim(0, 1.05)
    ax.set_title("first natural frequency against DC bias")
    print(f"wrote {finish(fig, ax, 'V / V_PI', 'f / f0', prefix + '.png', fontsize=8)}")


if __name__ == "__main__":
    run_main(main)
