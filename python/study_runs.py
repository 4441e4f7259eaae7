"""What the study scripts that run a series of driver runs share (creep_lifetime_study.py,
squeeze_film_study.py): one run of a driver with the study's overrides and the user's extra
--set ones, its --json summary back; and the table of the runs as CSV.
"""
import csv
import json
import subprocess
import sys


def run_driver(cmd, extra_sets, script):
    """The parsed --json summary of the driver command cmd (with --json and the study's own
    --set overrides) run with one more --set per KEY=VALUE of extra_sets (None: none). A run
    that fails ends the study: "<script>: <command>: exit N: <driver's stderr>"."""
    for s in extra_sets or []:
        cmd = cmd + ["--set", s]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"{script}: {' '.join(cmd)}: exit {p.returncode}: {p.stderr.strip()}")
    return json.loads(p.stdout)


def write_csv(path, rows):
    """rows (dicts with the same keys, in the column order) as a CSV file with a header."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
