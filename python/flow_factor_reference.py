#!/usr/bin/python3
"""The linearised BGK reference for a flow-factor table: for every Kn of the table that
rfmems-flow-factor wrote, the normalised Poiseuille flow rate G(delta) of the discrete-ordinates
solution in python/linearised_bgk_reference.py (Richardson-extrapolated from N / 2 and N
intervals across the channel), delta = sqrt(pi) / (2 Kn), and Q = 6 G / delta, written as CSV
with the command and the date in '#' lines (docs/gas_damping.md "Kinetic flow factor against
Veijola's fit" compares the table with it).

Above delta = 30 (Kn < 0.03) the discrete-ordinates fixed point converges too slowly (its rate
goes as 1 - 1/delta^2); there the reference is the large-delta expansion of the same flow rate,
G = delta / 6 + 1.0162 + 1.0653 / delta - 2.1354 / delta^2 (Fukui and Kaneko's, as Veijola 1995
quotes it), which meets the discrete-ordinates G to 5e-4 at delta = 8.86 and to 1e-5 at 15.8 and
28 (the `--check-expansion` option prints those). The `source` column says which.

Usage: flow_factor_reference.py TABLE.csv [-n 800] [-o REFERENCE.csv]
"""
import argparse
import csv
import datetime
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from linearised_bgk_reference import poiseuille  # noqa: E402


LARGE_DELTA = 30.0


def discrete_ordinates(delta, n):
    """G by the discrete-ordinates solution, Richardson-extrapolated from n / 2 and n."""
    coarse, fine = poiseuille(delta, n // 2), poiseuille(delta, n)
    return fine + (fine - coarse) / 3


def expansion(delta):
    """G = delta / 6 + sigma_P + 1.0653 / delta - 2.1354 / delta^2 (large delta)."""
    return delta / 6 + 1.0162 + 1.0653 / delta - 2.1354 / delta ** 2


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("table", help="a flow-factor table (columns knudsen, flow_factor)")
    ap.add_argument("-n", type=int, default=800, help="intervals across the channel (finer: N)")
    ap.add_argument("-o", "--output", help="the CSV to write (default: stdout)")
    ap.add_argument("--check-expansion", action="store_true",
                    help="print the expansion against the discrete ordinates at delta 8.86, 15.8, 28")
    args = ap.parse_args()
    if args.check_expansion:
        for delta in (8.862269, 15.75959, 28.02496):
            g = discrete_ordinates(delta, args.n)
            print(f"delta = {delta:g}: discrete ordinates {g:.7f}, expansion {expansion(delta):.7f} "
                  f"({expansion(delta) / g - 1:+.1e})")
        return
    with open(args.table, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    lines = [f"# linearised BGK reference for {args.table} (python/linearised_bgk_reference.py "
             "poiseuille, Richardson from N / 2 and N)",
             f"# command: /usr/bin/python3 python/flow_factor_reference.py {' '.join(sys.argv[1:])}",
             f"# date: {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC",
             "knudsen,delta,flow_rate,flow_factor,source"]
    for r in rows:
        kn = float(r["knudsen"])
        delta = math.sqrt(math.pi) / (2 * kn)
        large = delta > LARGE_DELTA
        g = expansion(delta) if large else discrete_ordinates(delta, args.n)
        source = "large-delta expansion" if large else "discrete ordinates"
        lines.append(f"{r['knudsen']},{delta:.8g},{g:.8g},{6 * g / delta:.8g},{source}")
        print(lines[-1], file=sys.stderr, flush=True)
    text = "\n".join(lines) + "\n"
    if args.output:
        tmp = pathlib.Path(args.output + ".tmp")
        tmp.write_text(text)
        tmp.replace(args.output)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
