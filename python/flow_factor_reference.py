#!/usr/bin/python3
"""The linearised BGK reference for a flow-factor table: for every Kn of the table that
rfmems-flow-factor wrote, the normalised Poiseuille flow rate G(delta) of the discrete-ordinates
solution in python/linearised_bgk_reference.py (Richardson-extrapolated from N / 2 and N
intervals across the channel), delta = sqrt(pi) / (2 Kn), and Q = 6 G / delta, written as CSV
with the command and the date in '#' lines (docs/gas_damping.md "Kinetic flow factor against
Veijola's fit" compares the table with it).

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


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("table", help="a flow-factor table (columns knudsen, flow_factor)")
    ap.add_argument("-n", type=int, default=800, help="intervals across the channel (finer: N)")
    ap.add_argument("-o", "--output", help="the CSV to write (default: stdout)")
    args = ap.parse_args()
    with open(args.table, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    lines = [f"# linearised BGK reference for {args.table} (python/linearised_bgk_reference.py "
             "poiseuille, Richardson from N / 2 and N)",
             f"# command: /usr/bin/python3 python/flow_factor_reference.py {' '.join(sys.argv[1:])}",
             f"# date: {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC",
             "knudsen,delta,flow_rate,flow_factor"]
    for r in rows:
        kn = float(r["knudsen"])
        delta = math.sqrt(math.pi) / (2 * kn)
        coarse, fine = poiseuille(delta, args.n // 2), poiseuille(delta, args.n)
        g = fine + (fine - coarse) / 3
        lines.append(f"{r['knudsen']},{delta:.8g},{g:.8g},{6 * g / delta:.8g}")
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
