#!/usr/bin/python3
"""Dominant oscillation frequency of a probe time series in an rfmems result file.

Reads /probes/<NAME>/time and /probes/<NAME>/values (n_t x 3: ux, uy, uz) written by
rfmems-solid (lib/io/result_writer.hpp) and estimates the frequency from the upward crossings
of the component through its mid-value (halfway between its extremes after the first
`--skip` seconds), each crossing time interpolated linearly between samples:
    f = (number of crossings - 1) / (last crossing - first crossing).
For a beam released into free vibration this is its first natural frequency (higher modes
carry little amplitude and do not add crossings of the mid-value).

Usage: probe_frequency.py RESULT.h5 [--probe tip] [--component uy] [--skip SECONDS] [--json]
"""
import argparse
import json
import sys

import h5py
import numpy as np

COMPONENTS = {"ux": 0, "uy": 1, "uz": 2}


def upward_crossings(t, x, level):
    """Times at which x crosses `level` from below, linearly interpolated."""
    d = x - level
    i = np.nonzero((d[:-1] < 0) & (d[1:] >= 0))[0]
    return t[i] - d[i] * (t[i + 1] - t[i]) / (d[i + 1] - d[i])


def analyse(t, x, skip):
    keep = t >= skip
    t, x = t[keep], x[keep]
    result = {"samples": int(t.size), "max_abs": float(np.max(np.abs(x))) if x.size else 0.0}
    if t.size < 4:
        return result
    level = 0.5 * (np.max(x) + np.min(x))
    crossings = upward_crossings(t, x, level)
    result["mean_level"] = float(level)
    result["periods"] = int(max(crossings.size - 1, 0))
    if crossings.size >= 2:
        result["frequency_hz"] = float((crossings.size - 1) / (crossings[-1] - crossings[0]))
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result", help="result file (.h5)")
    parser.add_argument("--probe", default="tip", help="probe name (default: tip)")
    parser.add_argument("--component", default="uy",
                        help="component name as stored with the probe (ux, uy, uz; w, beta_x, "
                             "beta_y for a plate; default: uy)")
    parser.add_argument("--skip", type=float, default=0.0,
                        help="ignore samples before this time [s], e.g. a load ramp (default 0)")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    args = parser.parse_args()

    try:
        with h5py.File(args.result, "r") as f:
            if "probes" not in f or args.probe not in f["probes"]:
                have = sorted(f["probes"].keys()) if "probes" in f else []
                sys.exit(f"probe_frequency.py: {args.result}: no probe '{args.probe}' (probes: {', '.join(have) or 'none'})")
            t = f["probes"][args.probe]["time"][()]
            values = f["probes"][args.probe]["values"]
            names = [c.decode() if isinstance(c, bytes) else str(c) for c in values.attrs["components"]] \
                if "components" in values.attrs else list(COMPONENTS)
            if args.component not in names:
                sys.exit(f"probe_frequency.py: {args.result}: probe '{args.probe}' has no component "
                         f"'{args.component}' (components: {', '.join(names)})")
            x = values[()].reshape(len(t), -1)[:, names.index(args.component)]
    except OSError as e:
        sys.exit(f"probe_frequency.py: {args.result}: {e}")

    r = analyse(t, x, args.skip)
    r.update(probe=args.probe, component=args.component)
    if args.json:
        print(json.dumps(r))
    elif "frequency_hz" in r:
        print(f"probe '{args.probe}': {args.component} oscillates at {r['frequency_hz']:.4g} Hz "
              f"({r['periods']} periods; max |{args.component}| = {r['max_abs']:.4g} m)")
    else:
        print(f"probe '{args.probe}': fewer than two crossings of the mid-value in {r['samples']} samples; "
              f"no frequency (max |{args.component}| = {r['max_abs']:.4g} m)")


if __name__ == "__main__":
    main()
