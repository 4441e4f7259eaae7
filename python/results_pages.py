#!/usr/bin/env python3
"""Regenerates the tables of the results pages (docs/*.md) from the raw data beside them.

A page marks each generated table:

    <!-- table: NAME -->
    ... (written by this script) ...
    <!-- end table -->

and NAME is one of TABLES below: a function of the data files under docs/data/ (CSV with
'#' comment lines giving the command and the date) and docs/figures/ (the benchmarks' JSON
lines). Nothing in a marked table is typed by hand.

  python3 python/results_pages.py            # rewrite every marked table in place
  python3 python/results_pages.py --check    # exit 1 naming each page and table that differ
"""
import argparse
import csv
import json
import math
import pathlib
import re
import statistics
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
DATA = DOCS / "data"
FIGURES = DOCS / "figures"

MARKER = re.compile(r"(<!-- table: (?P<name>[\w-]+) -->\n)(?P<body>.*?)(<!-- end table -->)", re.S)


def markdown(rows):
    """A Markdown table: rows[0] is the header."""
    out = ["| " + " | ".join(rows[0]) + " |", "|" + "---|" * len(rows[0])]
    out += ["| " + " | ".join(r) + " |" for r in rows[1:]]
    return "\n".join(out) + "\n"


def read_csv(name):
    with open(DATA / name, newline="") as f:
        return [r for r in csv.reader(line for line in f if not line.startswith("#"))]


def read_jsonl(path):
    return [json.loads(x) for x in open(path) if x.strip()]


def csv_table(name):
    return lambda: markdown(read_csv(name))


def pullin_laplace_dynamic():
    """The mesh table, and the observed order and Richardson value of the three plane meshes."""
    rows = read_csv("pullin_laplace_dynamic_meshes.csv")
    plane = [float(r[3]) for r in rows[1:] if r[0].startswith("plane")]
    d1, d2 = plane[0] - plane[1], plane[1] - plane[2]
    ratio = d1 / d2
    p = math.log2(ratio)
    richardson = plane[2] - d2 / (ratio - 1)
    errors = [abs(v - richardson) / richardson for v in plane]
    header = rows[0] + ["error against Richardson"]
    body = [r + [f"{100 * e:.2g} %"] for r, e in zip(rows[1:], errors)] + [r + ["-"] for r in rows[4:]]
    return markdown([header] + body) + (
        f"\nPlane + Laplace: successive differences {d1:.3f} and {d2:.3f} V, ratio {ratio:.2f}, "
        f"observed order **{p:.2f}**, Richardson value **{richardson:.3f} V**.\n")


def coupling_default_study_ab():
    """bench_driver_ab.py's lines: per side the median CPU and the figures it found, B / A."""
    lines = read_jsonl(FIGURES / "coupling_default_study_ab.jsonl")
    runs = [x for x in lines if x.get("bench") == "driver_ab"]
    summary = next(x for x in lines if x.get("bench") == "driver_ab_summary")
    rows = [["build", "runs", "median CPU [s]", "CPU range [s]", "V_qs [V]", "V_dyn [V]", "t_PI [us]",
             "bisection runs", "steps"]]
    for side in ("a", "b"):
        r = [x for x in runs if x["side"] == side]
        cpu = [x["cpu_s"] for x in r]
        f = r[0]
        same = all((x["v_qs"], x["v_dyn"], x["t_pi"]) == (f["v_qs"], f["v_dyn"], f["t_pi"]) for x in r)
        rows.append([f["label"], str(len(r)), f"{statistics.median(cpu):.2f}",
                     f"{min(cpu):.2f}-{max(cpu):.2f}", f"{f['v_qs']:.4f}", f"{f['v_dyn']:.4f}",
                     f"{1e6 * f['t_pi']:.4f}" + ("" if same else " (varies)"), str(f["runs"]),
                     str(f["steps"])])
    return markdown(rows) + (f"\nCPU ratio {summary['label_b']} / {summary['label_a']}: "
                             f"**{summary['ratio_b_over_a']:.3f}** (medians; {summary['date']}).\n")


def comet_two_ranks():
    """bench_gas_scaling's strong-scaling summaries on the quiet machine (1 -> 2 ranks)."""
    files = [("gas_scaling_quiet_2026-12-02.jsonl", "paused"),
             ("gas_scaling_quiet_repeats_2026-12-02.jsonl", "paused, repeat"),
             ("gas_scaling_quiet_full_2026-12-02.jsonl", "paused, leaky")]
    rows = [["solver", "mesh", "run", "iterations 1 -> 2", "T_1 [s]", "T_2 [s]", "speed-up",
             "efficiency", "iteration-normalised", "CPU in MPI waits"]]
    for name, run in files:
        for x in read_jsonl(FIGURES / name):
            if x.get("run") != "strong":
                continue
            rows.append([x["solver"] if x["solver"] != "comet" else "COMET",
                         " x ".join(str(c) for c in x["cells_P"]), run,
                         f"{x['iterations_1']:.0f} -> {x['iterations_P']:.0f}", f"{x['cpu_s_1']:.2f}",
                         f"{x['cpu_s_P']:.2f}", f"{x['cpu_s_1'] / x['cpu_s_P']:.2f}",
                         f"{100 * x['efficiency_cpu']:.0f} %",
                         f"{100 * x['efficiency_iteration_normalised']:.0f} %",
                         f"{100 * x['mpi_wait_cpu_share']:.1f} %"])
    return markdown(rows)


TABLES = {
    "verification-checks": csv_table("verification_checks.csv"),
    "performance-ratios": csv_table("performance_ratios.csv"),
    "creep-plate-vs-continuum": csv_table("creep_plate_vs_continuum.csv"),
    "pullin-time-check": csv_table("pullin_time_check.csv"),
    "pullin-laplace-dynamic": pullin_laplace_dynamic,
    "coupling-default-study-ab": coupling_default_study_ab,
    "comet-two-ranks": comet_two_ranks,
}


def regenerate(text, page, errors):
    def rep(m):
        name = m.group("name")
        if name not in TABLES:
            errors.append(f"{page}: table '{name}' is not one results_pages.py knows")
            return m.group(0)
        return m.group(1) + TABLES[name]() + m.group(4)
    return MARKER.sub(rep, text)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true",
                    help="change nothing; exit 1 naming each page and table that differs")
    args = ap.parse_args()
    errors, differ, used = [], [], set()
    for page in sorted(DOCS.glob("*.md")):
        text = page.read_text()
        new = regenerate(text, page.name, errors)
        old_tables = {m.group("name"): m.group("body") for m in MARKER.finditer(text)}
        for m in MARKER.finditer(new):
            used.add(m.group("name"))
            if old_tables.get(m.group("name")) != m.group("body"):
                differ.append(f"{page.relative_to(ROOT)}: table '{m.group('name')}' differs from its data")
        if new != text and not args.check:
            page.write_text(new)
    for name in sorted(set(TABLES) - used):
        errors.append(f"table '{name}' is on no page")
    for e in errors:
        print(f"results_pages: {e}", file=sys.stderr)
    if args.check:
        for d in differ:
            print(f"results_pages: {d}", file=sys.stderr)
        if differ or errors:
            sys.exit(1)
        print(f"results_pages: {len(used)} tables match their data")
    elif errors:
        sys.exit(1)


if __name__ == "__main__":
    main()
