#!/usr/bin/env python3
"""Regenerates the tables of the results pages (docs/*.md) from the raw data beside them.

A page marks each generated table:

    <!-- table: NAME -->
    ... (written by this script) ...
    <!-- end table -->

and NAME is one of TABLES below: a function of the data files under docs/data/ (CSV with
'#' comment lines giving the command and the date, or a benchmark's JSON lines with a header
line holding them) and docs/figures/ (the benchmarks' JSON lines). Nothing in a marked table is typed by hand.

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
    """bench_pullin_models --sections laplace_dynamic: the plane + Laplace switch on three meshes
    and the plate + parallel-plate switch; the plane meshes' observed order and Richardson value."""
    first = read_jsonl(FIGURES / "pullin_models_laplace_dynamic.jsonl")
    finest = read_jsonl(FIGURES / "pullin_models_laplace_dynamic_200x16.jsonl")
    plane = [x for x in first + finest if x.get("model") == "plane+laplace"]
    plate = [x for x in finest if x.get("model") == "plate+parallel_plate"]
    v = [x["v_mid"] for x in plane]
    d1, d2 = v[0] - v[1], v[1] - v[2]
    ratio = d1 / d2
    richardson = v[2] - d2 / (ratio - 1)
    rows = [["model", "mesh", "V_dyn bracket [V]", "midpoint [V]", "error against Richardson", "t_PI [us]",
             "runs", "IDA steps", "CPU [s]"]]
    for x in plane + plate:
        err = f"{100 * abs(x['v_mid'] - richardson) / richardson:.3f} %" if x in plane else "-"
        rows.append([x["model"].replace("+", " + ").replace("_", " "), x["mesh"].replace("x", " x ").replace("+gap", ", gap "),
                     f"({x['not_pulling_in']:.3f}, {x['dynamic_v_pi']:.3f}]", f"{x['v_mid']:.3f}", err,
                     f"{1e6 * x['pull_in_time_s']:.2f}", str(x["runs"]), str(x["steps"]), f"{x['cpu_s']:.2f}"])
    summary = next(x for x in finest if x.get("variant") == "laplace_dynamic_summary")
    return markdown(rows) + (
        f"\nPlane + Laplace: successive differences {d1:.3f} and {d2:.3f} V, ratio {ratio:.2f}, observed "
        f"order **{math.log2(ratio):.2f}**, Richardson value **{richardson:.3f} V**. CPU of the finest plane "
        f"+ Laplace run over the plate's, same run: **{summary['ratio_cpu_finest']:.0f}x** "
        f"({summary['ratio_wall_finest']:.0f}x in wall).\n")


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


def coupling_schemes(study):
    """bench_coupling_schemes.py's lines of one study: each run against the monolithic run at rtol
    1e-6 (the deflection at 5 us, or the pull-in time), with its cost."""
    def table():
        lines = read_jsonl(FIGURES / "coupling_schemes.jsonl")
        runs = [x for x in lines if x.get("bench") == "coupling_schemes" and x["study"] == study]
        summary = next(x for x in lines if x.get("bench") == "coupling_schemes_summary")
        key = "final_control" if study == "deflection" else "pull_in_time"
        ref = next(x for x in runs if x["scheme"] == "monolithic" and x["rtol"] == 1e-6)
        head = "w(5 us)" if study == "deflection" else "t_PI"
        rows = [["scheme", "rtol", "gas every", f"{head} [um]" if study == "deflection" else f"{head} [us]",
                 "error", "steps", "residual evals", "gas steps", "coupling iterations", "CPU [s]"]]
        for x in runs:
            c = x["counters"]
            err = "(reference)" if x is ref else f"{abs(x[key] / ref[key] - 1):.1e}"
            partitioned = x["scheme"] != "monolithic"
            rows.append([x["scheme"].replace("_", " "), f"{x['rtol']:g}",
                         str(x["gas_every"]) if partitioned else "-", f"{1e6 * x[key]:.6f}", err,
                         str(x["steps"]), str(x["residual_evals"]),
                         str(c.get("gas_steps", "-")) if partitioned else "-",
                         str(c.get("coupling_iterations", "-")) if x["scheme"] == "strongly_coupled" else "-",
                         f"{x['cpu_s']:.2f}"])
        return markdown(rows) + f"\nCommand: `{summary['commands'][study]}` ({summary['date']}).\n"
    return table


def coupling_schemes_study():
    """bench_coupling_schemes.py's default dynamic study of cases/switch_plate with each scheme."""
    lines = read_jsonl(FIGURES / "coupling_schemes.jsonl")
    runs = [x for x in lines if x.get("bench") == "coupling_schemes" and x["study"] == "study"]
    summary = next(x for x in lines if x.get("bench") == "coupling_schemes_summary")
    mono = next(x for x in runs if x["scheme"] == "monolithic")
    rows = [["scheme", "V_qs [V]", "V_dyn [V]", "t_PI [us]", "t_PI at 0.1 x tolerances [us]",
             "small signal: damping ratio", "frequency [kHz]", "bisection runs", "CPU [s]",
             "CPU / monolithic"]]
    for x in runs:
        rows.append([x["scheme"].replace("_", " "), f"{x['v_qs']:.4f}",
                     f"({x['not_pulling_in']:.4f}, {x['v_dyn']:.4f}]", f"{1e6 * x['pull_in_time']:.3f}",
                     f"{1e6 * x['pull_in_time_check']:.3f}", f"{x['damping_ratio']:.5f}",
                     f"{1e-3 * x['frequency']:.2f}", str(x["runs"]), f"{x['cpu_s']:.1f}",
                     f"{x['cpu_s'] / mono['cpu_s']:.2f}"])
    return markdown(rows) + f"\nCommand: `{summary['commands']['study']}` ({summary['date']}).\n"


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


def gas_mpi_agreement():
    """bench_gas_mpi_agreement.py: 2 ranks against serial per solver tolerance; the largest
    relative field difference and wall difference, and both over the tolerance."""
    rows = [["case", "tolerance", "sweeps 1 -> 2", "fields (max rel. diff.)", "walls: force / heat flow",
             "worst / tolerance"]]
    for x in read_jsonl(FIGURES / "gas_mpi_agreement.jsonl"):
        fields = max(x["fields"].values())
        force = max(w["force"] for w in x["walls"].values())
        heat = max(w["heat_flow"] for w in x["walls"].values())
        case = x["case"] + "".join(f" ({s})" for s in x["sets"])
        rows.append([case, f"{x['tolerance']:.0e}",
                     f"{x['iterations'][0]} -> {x['iterations'][1]}", f"{fields:.1e}",
                     f"{force:.1e} / {heat:.1e}",
                     f"{max(fields, force, heat) / x['tolerance']:.0f}"])
    return markdown(rows)


def immersed_esbgk_stepper():
    """rfmems-pullin's JSON of the coarse ESBGK switch at 80 V, the gas by sweeps and by IDA."""
    rows = [["gas stepper", "tip extreme [um]", "tip at 1.2 us [um]", "difference to sweeps",
             "coupled steps", "gas CPU [s]", "gas CPU per step [ms]", "CPU / sweeps"]]
    runs = [(name, json.load(open(FIGURES / f"immersed_esbgk_stepper_{name}_80V.json"))["pull_in"])
            for name in ("sweeps", "ida")]
    base = runs[0][1]
    for name, p in runs:
        t, c = p["transient"], p["counters"]
        diff = abs(t["extreme_control"] / base["transient"]["extreme_control"] - 1)
        rows.append([name, f"{-1e6 * t['extreme_control']:.5f}", f"{-1e6 * t['final_control']:.5f}",
                     "-" if p is base else f"{diff:.1e}", str(c["gas_steps"]), f"{c['gas_s']:.1f}",
                     f"{1e3 * c['gas_s'] / c['gas_steps']:.1f}",
                     f"{c['gas_s'] / base['counters']['gas_s']:.1f}"])
    return markdown(rows)


def comet_by_regime():
    """bench_comet_vs_sequential's rows with the default cycle (auto) and the V-cycle beside it."""
    rows = [x for x in read_jsonl(FIGURES / "comet_cycle_by_regime.jsonl") if "case" in x]
    out = [["mesh", "case", "Kn", "method (cycle)", "cycles", "CPU [s]", "fine sweeps",
            "sequential iterations / CPU [s]", "sequential / default (CPU)", "V-cycle: cycles / CPU [s]"]]
    for x in rows:
        if x["cycle"] != "auto":
            continue
        v = next((y for y in rows if y["cycle"] == "V" and (y["cells"], y["case"], y["kn"]) ==
                  (x["cells"], x["case"], x["kn"])), None)
        run = x["comet_cycle_run"] + ("1" if not x["comet_coarse_symmetric"] else "")
        method = (f"COMET ({run})" + (", forced" if x["kn"] >= 0.2 else "") if x["comet_method"] == "comet"
                  else "sequential (the default's hand-over)")
        seq = (f"{x['seq_iterations']} / {x['seq_cpu_seconds']:.1f}" if x.get("seq_cpu_seconds") and
               x["comet_method"] == "comet" else "-")
        speed = f"{x['speedup_cpu']:.2f}" if x.get("speedup_cpu") else "-"
        out.append([f"{x['cells']} x {x['cells']}", x["case"].replace("_", " "), f"{x['kn']:g}", method,
                    str(x["comet_cycles"]), f"{x['comet_cpu_seconds']:.2f}",
                    f"{x['comet_fine_sweep_equivalents']:.1f}" if x["comet_method"] == "comet" else "-",
                    seq, speed, f"{v['comet_cycles']} / {v['comet_cpu_seconds']:.2f}" if v else "-"])
    return markdown(out)


def gas_damping_second_order_sweep():
    """The damping sweep with second-order transport (420 cells, 8^3 velocities) and its ratios."""
    rows = [["p [Pa]", "Kn", "solver", "iterations", "CPU [s]", "c ESBGK [N s/m^2]", "zeta ESBGK",
             "/ free mol. isolated (discrete)", "/ Reynolds-Veijola", "/ R-V + elongation"]]
    seen = set()
    for x in read_jsonl(FIGURES / "gas_damping_regimes_second_order.jsonl"):
        key = x["pressure"]
        if (x["refine"], x["points"], x.get("transport"), x.get("extra")) != (1, 8, "second_order", []) \
                or key in seen:
            continue
        seen.add(key)
        p = x["pressure"]
        ptext = f"{p:g}" if p < 1e4 else f"{p / 10 ** int(math.log10(p)):g}e{int(math.log10(p))}"
        rve = "-" if x["knudsen"] > 1 else f"{x['esbgk'] / x['reynolds_veijola_elongation']:.2f}"
        rows.append([ptext, f"{x['knudsen']:.3g}", x["solver"], str(x["iterations"]), f"{x['cpu_seconds']:.2f}",
                     f"{x['esbgk']:.4e}", f"{x['damping_ratio_esbgk']:.3e}",
                     f"{x['esbgk'] / x['free_molecular_discrete']:.3f}",
                     f"{x['esbgk'] / x['reynolds_veijola']:.2f}", rve])
    return markdown(rows)


def immersed_esbgk_case_keys():
    """rfmems-pullin's JSON of the ESBGK switch at 123 V with the case's keys, serial and 2 ranks."""
    rows = [["run", "pull-in time [us]", "IDA / gas steps", "wall [s]", "gas [s]", "structure [s]",
             "electrostatics [s]", "interpolation [s]", "marking [s]", "MPI wait [s]", "wall per step [s]"]]
    for name, label in (("immersed_esbgk_case_keys_123V_np2_quiet.json", "2 ranks (rank 0's CPU by physics)"),
                        ("immersed_esbgk_case_keys_123V_np1_quiet.json", "serial")):
        d = json.load(open(FIGURES / name))
        im, cpu = d["immersed"], d["immersed"]["cpu"]
        wall = d["wall_time_s"]
        comm = d.get("communication_rank0")
        rows.append([label, f"{1e6 * im['transient']['pull_in_time']:.6f}",
                     f"{cpu['structure_steps']} / {cpu['gas_steps']}",
                     f"{wall:.1f}",
                     f"{cpu['gas_s']:.1f}", f"{cpu['structure_s']:.2f}", f"{cpu['electrostatics_s']:.2f}",
                     f"{cpu['interpolation_s']:.2f}", f"{cpu['marking_s']:.2f}",
                     f"{comm['wait_cpu_s']:.1f}" if comm else "-", f"{wall / cpu['structure_steps']:.3f}"])
    return markdown(rows)


def modal_records(section, name="modal_bench.jsonl"):
    """bench_modal's lines of one section (docs/data/modal_bench.jsonl), and its header."""
    lines = read_jsonl(DATA / name)
    header = next(x for x in lines if x["section"] == "header")
    return [x for x in lines if x["section"] == section], header


def modal_run_line(header):
    return (f"\nCommand: `{header['command']}`, {header['date']} (1-minute load average "
            f"{header['load_average_1min']:g} on 2 cores at the start).\n")


def modal_cost():
    """The lowest modes of the switch plate on 160 and 40,000 cells: time and work."""
    runs, header = modal_records("modes")
    targets = {160: 0.5, 40000: 30.0}
    rows = [["plate", "unknowns", "K nonzeros", "modes", "wall [s]", "CPU [s]", "factorisation",
             "factor [s]", "Arnoldi [s]", "solves", "f1 [Hz]", f"f{runs[0]['modes']} [Hz]",
             "target", "met (CPU; wall)"]]
    for x in runs:
        target = targets.get(x["cells"])
        rows.append([f"{x['cells']} cells", str(x["unknowns"]), str(x["stiffness_nonzeros"]),
                     str(x["modes"]), f"{x['wall_s']:.3g}", f"{x['cpu_s']:.3g}",
                     x["factorization"].upper(), f"{x['factor_s']:.3g}",
                     f"{x['iterate_s']:.3g}", str(x["operator_applications"]),
                     f"{x['frequencies_hz'][0]:.5e}", f"{x['frequencies_hz'][-1]:.5e}",
                     f"< {target:g} s" if target else "-",
                     (("yes" if x["cpu_s"] < target else "no") + "; " +
                      ("yes" if x["wall_s"] < target else "no")) if target else "-"])
    return markdown(rows) + modal_run_line(header)


def modal_vs_transient():
    """The first frequency of the 160-cell plate by the modal route and by transient-and-fit."""
    (x,), header = modal_records("transient")
    f = x["modal_frequency_hz"]
    rows = [["route", "f1 [Hz]", "against modal", "wall [s]", "CPU [s]", "work"],
            ["modal (shift-invert, 1 mode)", f"{f:.6e}", "-", f"{x['modal_wall_s']:.3g}",
             f"{x['modal_cpu_s']:.3g}", "1 factorisation, a few solves"],
            ["transient + step-response fit", f"{x['fit_frequency_hz']:.6e}",
             f"{100 * x['fit_over_modal']:+.3f} %", f"{x['transient_wall_s'] + x['fit_wall_s']:.3g}",
             f"{x['transient_cpu_s']:.3g} (+ fit)",
             f"{x['steps']} IDA steps, {x['samples']} samples"],
            ["transient + spacing of the extrema", f"{x['extrema_frequency_hz']:.6e}",
             f"{100 * x['extrema_over_modal']:+.3f} %", f"{x['transient_wall_s']:.3g}",
             f"{x['transient_cpu_s']:.3g}", f"the same run, {x['extrema_swings']} half-swings"]]
    ratio = x["transient_wall_s"] / x["modal_wall_s"]
    return markdown(rows) + (
        f"\nTransient over modal, wall: **{ratio:.0f}x** ({x['periods']:g} periods at rtol "
        f"{x['rtol']:g}, {x['samples_per_period']} samples per period).\n" + modal_run_line(header))


def modal_bias(name="modal_bench.jsonl"):
    """The first frequency of the 160-cell switch against DC bias, and the 1-DOF forms."""
    runs, header = modal_records("bias", name)
    rows = [["V [V]", "V / V_PI", "control deflection [um]", "f1 [Hz]", "f / f0",
             "1-DOF f / f0", "difference"]]
    for x in runs:
        rows.append([f"{x['voltage']:.2f}", f"{x['voltage'] / x['pull_in_voltage']:.3f}",
                     f"{1e6 * x['control_displacement']:.4f}", f"{x['frequency_hz']:.5e}",
                     f"{x['frequency_ratio']:.4f}", f"{x['lumped_ratio_of_voltage']:.4f}",
                     f"{x['frequency_ratio'] - x['lumped_ratio_of_voltage']:+.4f}"])
    return markdown(rows) + (
        f"\nQuasi-static pull-in voltage of this plate: {runs[0]['pull_in_voltage']:.3f} V.\n"
        + modal_run_line(header))


def residual_stress_sweep():
    """bench_residual_stress: pull-in voltage and modes of the switch plate against sigma_xx."""
    lines = read_jsonl(DATA / "residual_stress_sweep.jsonl")
    header = next(x for x in lines if x["section"] == "header")
    rows = [["sigma_xx [MPa]", "N [N/m]", "N L^2 / D", "V_PI [V]", "V_PI / V_PI(0)", "f1 [kHz]",
             "f1 / f1(0)", "f2 [kHz]", "f3 [kHz]", "lumped sqrt(1 + k_s/k_b)"]]
    for x in lines:
        if x["section"] != "sweep":
            continue
        f = x["frequencies_hz"]
        rows.append([f"{x['residual_stress_mpa']:g}", f"{x['membrane_force_n_per_m']:g}",
                     f"{x['tension_parameter']:.1f}", f"{x['pull_in_voltage']:.3f}",
                     f"{x['voltage_ratio']:.4f}", f"{1e-3 * f[0]:.2f}",
                     f"{x['frequency_ratio']:.4f}", f"{1e-3 * f[1]:.2f}", f"{1e-3 * f[2]:.2f}",
                     f"{x['lumped_ratio']:.4f}"])
    return markdown(rows) + modal_run_line(header)


def residual_stress_switch():
    """The default switch and cases/switch_prestressed side by side (rfmems-pullin --json)."""
    lines = read_jsonl(DATA / "residual_stress_switch_runs.jsonl")
    sweep = {x["residual_stress_mpa"]: x for x in read_jsonl(DATA / "residual_stress_sweep.jsonl")
             if x["section"] == "sweep"}
    rows = [["case", "sigma_xx [MPa]", "V_qs [V]", "V_dyn [V]", "V_dyn / V_qs", "t_PI [us]",
             "t_PI error estimate", "f1 modal [kHz]", "small signal f [kHz], zeta", "wall [s]"]]
    for x in lines:
        p = x["summary"]["pull_in"]
        d = p["dynamic"]
        ss = d["small_signal"]
        rows.append([f"`{x['case']}`", f"{x['residual_stress_mpa']:g}",
                     f"{p['quasi_static']['pull_in_voltage']:.3f}",
                     f"({d['not_pulling_in']:.2f}, {d['pull_in_voltage']:.2f}]",
                     f"{d['ratio_to_quasi_static']:.4f}", f"{1e6 * d['pull_in_time']:.3f}",
                     f"{100 * d['pull_in_time_check']['relative_error_estimate']:.2f} %",
                     f"{1e-3 * sweep[x['residual_stress_mpa']]['frequencies_hz'][0]:.2f}",
                     f"{1e-3 * ss['frequency']:.2f}, {ss['damping_ratio']:.4f}",
                     f"{x['summary']['wall_time_s']:.1f}"])
    commands = "; ".join(f"`{x['command']}`" for x in lines)
    return markdown(rows) + f"\nCommands: {commands}, {lines[0]['date']}.\n"


def quasi_static_trace():
    """bench_quasi_static_trace: the bordered Jacobian's fill by ordering, and the whole curve's
    cost on each mesh with each ordering; the ratio of the finest to the coarsest mesh with the
    factorisation chosen by size (KLU with AMD below 1000 unknowns, UMFPACK's symmetric strategy
    on the nested-dissection order from there on: QuasiStaticOptions::umfpack_from)."""
    lines = read_jsonl(FIGURES / "quasi_static_trace.jsonl")
    header = next(x for x in lines if x["section"] == "header")
    order = [x for x in lines if x["section"] == "orderings"]
    trace = [x for x in lines if x["section"] == "trace"]
    rows = [["mesh", "unknowns", "ordering", "L + U entries", "per unknown", "analyse + factor [s]",
             "refactor [s]", "solve [s]"]]
    for x in order:
        rows.append([f"{x['nx']} x {x['ny']}", str(x["unknowns"]), x["ordering"],
                     f"{x['factor_entries']:.3g}", f"{x['factor_entries'] / x['unknowns']:.0f}",
                     f"{x['analyze_factor_cpu_s']:.3g}", f"{x['refactor_cpu_s']:.3g}",
                     f"{x['solve_cpu_s']:.2g}"])
    out = markdown(rows) + "\n"
    rows = [["mesh", "ordering", "CPU [s]", "solves", "Newton", "fresh factorisations",
             "refactorisations", "V_PI [V]"]]
    for x in trace:
        rows.append([f"{x['nx']} x {x['ny']}", x["ordering"], f"{x['cpu_s']:.3g}", str(x["solves"]),
                     str(x["newton_iters"]), str(x["fresh_factorizations"]),
                     str(x["refactorizations"]), f"{x['pull_in_voltage']:.4f}"])
    out += markdown(rows)

    def chosen(x):
        return x["ordering"] == ("amd" if x["unknowns"] < 1000 else "umfpack")

    picked = sorted((x for x in trace if chosen(x)), key=lambda x: x["unknowns"])
    if len(picked) >= 2:
        a, b = picked[0], picked[-1]
        out += (f"\nWith the factorisation chosen by size, {b['nx']} x {b['ny']} costs "
                f"**{b['cpu_s'] / a['cpu_s']:.0f}x** the CPU of {a['nx']} x {a['ny']} "
                f"({b['unknowns'] / a['unknowns']:.0f}x the unknowns).\n")
    return out + f"\nCommand: `{header['command']}`, {header['date']}.\n"


def velocity_grids():
    """bench_velocity_grids: per problem and delta, today's uniform grid (the driver test's)
    against the cheapest grid of each non-uniform family at least as accurate, and whether that
    takes at most a quarter of the velocities."""
    lines = read_jsonl(FIGURES / "velocity_grids.jsonl")
    header = next(x for x in lines if x.get("section") == "header")
    runs = [x for x in lines if "error" in x]
    families = [("gh+hr", "Gauss-Hermite along, half-range Gauss-Hermite across"),
                ("gh+sinh", "Gauss-Hermite along, sinh-stretched across")]
    names = {"couette": "Couette P", "heat": "heat q*", "poiseuille": "Poiseuille G"}
    rows = [["problem", "delta", "grid", "points", "velocities", "CPU [s]", "error",
             "velocities / today's", "CPU / today's", "quarter"]]
    pct = lambda e: f"{100 * e:+.4f} %"
    points = lambda p: " x ".join(str(n) for n in p)
    for problem in ("couette", "heat", "poiseuille"):
        for delta in sorted({x["delta"] for x in runs}):
            here = [x for x in runs if x["problem"] == problem and x["delta"] == delta]
            along = 12 if problem == "heat" else 8
            today = [along, 32 if delta >= 10 else 64, along]
            base = next(x for x in here if x["grid"] == "uniform" and x["points"] == today)
            target = abs(base["error"])
            # Runs on another number of cells than the set-up's say so.
            where = lambda x: (points(x["points"]) if x["cells"] == base["cells"]
                               else f"{points(x['points'])} on {x['cells']} cells")
            rows.append([names[problem], f"{delta:g}", "uniform (today)", points(base["points"]),
                         str(base["ordinates"]), f"{base['cpu_s']:.3f}", pct(base["error"]),
                         "1", "1", "-"])
            for family, label in families:
                ok = sorted((x for x in here if x["grid"] == family and abs(x["error"]) <= target),
                            key=lambda x: x["ordinates"])
                if not ok:
                    rows.append([names[problem], f"{delta:g}", label, "-", "-", "-",
                                 "none as accurate", "-", "-", "**no**"])
                    continue
                x = ok[0]
                ratio = x["ordinates"] / base["ordinates"]
                rows.append([names[problem], f"{delta:g}", label, where(x),
                             str(x["ordinates"]), f"{x['cpu_s']:.3f}", pct(x["error"]),
                             f"1/{1 / ratio:.1f}", f"1/{base['cpu_s'] / x['cpu_s']:.1f}",
                             "yes" if ratio <= 0.25 else "**no**"])
    return markdown(rows) + (f"\nCommand: `{header['command']}`, {header['date']} "
                             f"(commit {header['commit']}; 1-minute load average "
                             f"{header['load_average_1min']:g} on 2 cores at the start).\n")


def velocity_grids_goal():
    """bench_velocity_grids: per problem and delta, the cheapest grid of each family within 0.2 %
    of the reference (the driver test's tolerance), or the best one run."""
    runs = [x for x in read_jsonl(FIGURES / "velocity_grids.jsonl") if "error" in x]
    families = [("uniform", "uniform"), ("gh+hr", "GH + half-range GH"),
                ("gh+sinh", "GH + sinh-stretched"), ("gh", "GH in every direction")]
    names = {"couette": "Couette P", "heat": "heat q*", "poiseuille": "Poiseuille G"}
    rows = [["problem", "delta"] + [label for _, label in families]]
    for problem in ("couette", "heat", "poiseuille"):
        for delta in sorted({x["delta"] for x in runs}):
            row = [names[problem], f"{delta:g}"]
            for family, _ in families:
                # On the set-up's cells (the fewest run at this delta).
                cells = min(x["cells"] for x in runs if x["delta"] == delta)
                ok = sorted((x for x in runs if x["problem"] == problem and x["delta"] == delta
                             and x["grid"] == family and x["cells"] == cells
                             and abs(x["error"]) <= 2e-3),
                            key=lambda x: x["ordinates"])
                tried = [x for x in runs if x["problem"] == problem and x["delta"] == delta
                         and x["grid"] == family and x["cells"] == cells]
                best = min(tried, key=lambda x: abs(x["error"]))
                x = ok[0] if ok else best
                text = (f"{x['ordinates']} ({' x '.join(map(str, x['points']))}, "
                        f"{100 * x['error']:+.3f} %)")
                row.append(text if ok else "no; best " + text)
            rows.append(row)
    return markdown(rows)


def kinetic_published_tables():
    """rfmems-gas's Poiseuille G and Couette P (docs/data/kinetic_published_runs.csv, from
    python/kinetic_published_runs.py) against the published linearised-BGK solutions
    (docs/data/kinetic_published_bgk.csv) and the in-repo discrete-ordinates reference; ES-BGK's
    (Pr = 2/3) at delta_B / Pr against the same through the exact relations of
    test/drivers/test_gas_linearised_bgk.sh."""
    def rows_of(name):
        with open(DATA / name, newline="") as f:
            return list(csv.DictReader(line for line in f if not line.startswith("#")))
    runs, published = rows_of("kinetic_published_runs.csv"), rows_of("kinetic_published_bgk.csv")
    # python/linearised_bgk_reference.py (N = 1600, Richardson-extrapolated), per problem and delta.
    ordinates = {("poiseuille", 0.1): 2.0327143, ("poiseuille", 1): 1.5386784,
                 ("poiseuille", 10): 2.7686424, ("couette", 1 / 0.3): 0.1868997,
                 ("couette", 10): 0.0831122, ("couette", 1 / 0.03): 0.0282760}
    names = {"poiseuille": "Poiseuille G", "couette": "Couette P"}
    digits = {"poiseuille": 5, "couette": 7}
    out = [["problem", "delta", "ours: test grid", "ours: finer grid", "in-repo reference",
            "published", "source", "test grid - published", "finer - published"]]
    same = lambda a, b: abs(float(a) / float(b) - 1) < 1e-6
    pick = lambda problem, delta, role: next(r for r in runs if r["problem"] == problem
                                             and same(r["delta"], delta) and r["role"] == role)
    # ES-BGK at delta from BGK at Pr delta: P_B / (1 + (1 - Pr) delta P_B), G_B + (1 - Pr) delta / 6.
    pr = 2 / 3
    to_es = {"poiseuille": lambda b, delta: b + (1 - pr) * delta / 6,
             "couette": lambda b, delta: b / (1 + (1 - pr) * delta * b)}
    for model in ("bgk", "esbgk"):
        for (problem, delta_b), reference in ordinates.items():
            delta = delta_b if model == "bgk" else delta_b / pr
            convert = (lambda b: b) if model == "bgk" else (lambda b: to_es[problem](b, delta))
            run = problem if model == "bgk" else problem + "_esbgk"
            test, finer = pick(run, delta, "test"), pick(run, delta, "finer")
            n = digits[problem]
            grid = lambda r: (f"{float(r['value']):.{n}f} "
                              f"({r['velocity_points'].replace('x', ' x ')}, "
                              f"{r['cells']} cells, {float(r['seconds']):.2g} s)")
            for p in (x for x in published if x["problem"] == problem
                      and same(x["delta"], delta_b)):
                v = convert(float(p["published"]))
                shown = (p["published"] if model == "bgk" else
                         f"{v:.{n}f} (BGK {p['published']} at Pr delta = {delta_b:.6g})")
                out.append([names[problem] if model == "bgk" else "ES-BGK " + names[problem],
                            f"{delta:.6g}", grid(test), grid(finer),
                            f"{convert(reference):.{n}f}", shown, p["source"],
                            f"{100 * (float(test['value']) / v - 1):+.3f} %",
                            f"{100 * (float(finer['value']) / v - 1):+.3f} %"])
    head = comment_lines("kinetic_published_runs.csv")
    return markdown(out) + "\n" + next(x for x in head if x.startswith("Command:")) + "\n"


def comment_lines(name):
    """The '#' lines of a data file under docs/data/, without the '# '."""
    return [line[2:].rstrip("\n") for line in open(DATA / name) if line.startswith("# ")]


def flow_factor_table():
    """rfmems-flow-factor's Q(Kn) (docs/data/flow_factor_bgk.csv) against the linearised BGK
    reference (python/flow_factor_reference.py) and Veijola's fit Q = 1 + 9.638 Kn^1.159."""
    with open(DATA / "flow_factor_bgk.csv", newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    with open(DATA / "flow_factor_bgk_reference.csv", newline="") as f:
        ref = {r["knudsen"]: r for r in csv.DictReader(line for line in f if not line.startswith("#"))}
    out = [["Kn", "delta", "cells", "velocities", "sweeps", "time [s]", "Q kinetic", "Q linearised BGK",
            "kinetic error", "Q Veijola", "Veijola error"]]
    worst_ref = worst_veijola = seconds = 0.0
    for r in rows:
        kn, q = float(r["knudsen"]), float(r["flow_factor"])
        q_ref = float(ref[r["knudsen"]]["flow_factor"])
        q_v = 1 + 9.638 * kn ** 1.159
        worst_ref = max(worst_ref, abs(q / q_ref - 1))
        worst_veijola = max(worst_veijola, abs(q_v / q - 1))
        seconds += float(r["seconds"])
        out.append([f"{kn:.4g}", f"{float(r['delta']):.4g}", r["cells"], r["velocity_points"].replace("x", " x "),
                    r["sweeps"], r["seconds"], f"{q:.5f}", f"{q_ref:.5f}", f"{100 * (q / q_ref - 1):+.3f} %",
                    f"{q_v:.5f}", f"{100 * (q_v / q - 1):+.2f} %"])
    head = comment_lines("flow_factor_bgk.csv")
    return markdown(out) + (
        f"\nKinetic error: Q against the linearised BGK reference, largest **{100 * worst_ref:.2f} %**. "
        f"Veijola error: his fit against the kinetic Q, largest **{100 * worst_veijola:.2f} %** at the "
        f"nodes (his stated accuracy: 5 %). The solves' time "
        f"summed {seconds:.0f} s. Table: `{head[1].removeprefix('command: ')}`, {head[2].removeprefix('date: ')}; "
        f"reference: `{comment_lines('flow_factor_bgk_reference.csv')[1].removeprefix('command: ')}`.\n")


def flow_factor_strip_damping():
    """bench_reynolds_strip_damping --flow-factor-table: the strip's Reynolds damping with
    Veijola's fit and with the kinetic table."""
    rows = [x for x in read_jsonl(DATA / "flow_factor_strip_damping.jsonl") if "reynolds_table" in x]
    out = [["p [Pa]", "Kn", "Q Veijola", "Q table", "c Veijola [N s/m^2]", "c table [N s/m^2]",
            "table / Veijola"]]
    for x in rows:
        out.append([f"{x['pressure']:g}", f"{x['knudsen']:.3g}", f"{x['flow_factor_veijola']:.4f}",
                    f"{x['flow_factor_table']:.4f}", f"{x['reynolds_veijola']:.4e}",
                    f"{x['reynolds_table']:.4e}", f"{x['table_over_veijola']:.4f}"])
    return markdown(out)


def flow_factor_switch_plate():
    """rfmems-pullin on cases/switch_plate with gas.rarefaction veijola and table
    (docs/data/flow_factor_switch_plate.jsonl: one --json summary per line, each with the
    rarefaction it ran with)."""
    runs = read_jsonl(DATA / "flow_factor_switch_plate.jsonl")
    out = [["film rarefaction", "damping ratio (small signal)", "frequency [kHz]", "V_PI dynamic [V]",
            "t_PI [us]", "V_PI quasi-static [V]"]]
    for x in runs:
        d, q = x["pull_in"]["dynamic"], x["pull_in"]["quasi_static"]
        out.append([x["rarefaction"], f"{d['small_signal']['damping_ratio']:.5f}",
                    f"{d['small_signal']['frequency'] / 1e3:.3f}", f"{d['pull_in_voltage']:.2f}",
                    f"{1e6 * d['pull_in_time']:.3f}", f"{q['pull_in_voltage']:.2f}"])
    a, b = runs[0]["pull_in"]["dynamic"], runs[1]["pull_in"]["dynamic"]
    return markdown(out) + (
        f"\n{runs[1]['rarefaction']} over {runs[0]['rarefaction']}: damping ratio "
        f"{b['small_signal']['damping_ratio'] / a['small_signal']['damping_ratio']:.4f}, pull-in time "
        f"{b['pull_in_time'] / a['pull_in_time']:.4f}.\n")


def scale_runs(name):
    """bench_scale.py: rfmems-solid's static solve against the mesh, by linear solver (direct:
    KLU or UMFPACK, as the run's JSON names it); each row's growth exponent
    d log(CPU) / d log(unknowns) from the previous row of its solver.linear."""
    def table():
        lines = read_jsonl(DATA / name)
        runs = [x for x in lines if x["section"] == "run"]
        rows = [["mesh", "unknowns", "linear solver", "Newton", "GMRES iterations",
                 "levels, complexity", "wall [s]", "CPU [s]", "growth", "peak memory [GiB]",
                 "probe error"]]
        previous = {}
        for x in sorted(runs, key=lambda r: (r["linear"], r["unknowns"])):
            last = previous.get(x["linear"])
            growth = (math.log(x["cpu_s"] / last["cpu_s"]) / math.log(x["unknowns"] / last["unknowns"])
                      if last else None)
            previous[x["linear"]] = x
            mg = x["linear"] == "multigrid"
            rows.append([x["mesh"].replace(",", " x "), f"{x['unknowns']:,}",
                         "BoomerAMG + GMRES" if mg else x.get("linear_solver", "klu").upper(),
                         str(x["newton_iterations"]), str(x["krylov_iterations"]) if mg else "-",
                         f"{x['multigrid_levels']}, {x['multigrid_operator_complexity']:.2f}" if mg else "-",
                         f"{x['wall_s']:.2f}", f"{x['cpu_s']:.2f}",
                         f"n^{growth:.2f}" if growth is not None else "-",
                         f"{x['max_rss_gib']:.2f}", f"{100 * x['relative_error']:+.3f} %"])
        headers = [x for x in lines if x["section"] == "header"]
        commands = "; ".join(f"`{h['command']}` (load average {h['load_average']:.1f})" for h in headers)
        return markdown(rows) + f"\nCommands: {commands}, {headers[0]['date']}.\n"
    return table


def scale_ranks():
    """bench_scale.py --ranks 2: the 3D box serial (one rank, matrix-free) and distributed on
    2 ranks (assembled), by solver.tolerance; their fields' largest difference."""
    lines = read_jsonl(DATA / "scale_box_3d_mpi.jsonl")
    headers = [x for x in lines if x["section"] == "header"]
    rows = [["mesh", "unknowns", "solver.tolerance", "Newton 1 rank", "GMRES 1 -> 2 ranks",
             "wall 1 -> 2 ranks [s]", "peak memory 1 -> 2 ranks [GiB]", "field difference (largest, relative)"]]
    tolerance = None
    for x in lines:
        if x["section"] == "header":
            tolerance = x["command"].split("tolerance: ")[1].strip("'")
            continue
        rows.append([x["mesh"].replace(",", " x "), f"{x['unknowns']:,}", tolerance,
                     str(x["newton_iterations"]),
                     f"{x['krylov_iterations']} -> {x['ranks_krylov_iterations']}",
                     f"{x['wall_s']:.2f} -> {x['ranks_wall_s']:.2f}",
                     f"{x['max_rss_gib']:.2f} -> {x['ranks_max_rss_gib']:.2f}",
                     f"{x['ranks_field_difference']:.1e}"])
    commands = "; ".join(f"`{h['command']}` (load average {h['load_average']:.1f})"
                         for h in headers)
    return markdown(rows) + f"\nCommands: {commands}, {headers[0]['date']}.\n"


def commit_commands(headers):
    """The commands of a benchmark's processes, each with its commit and machine load."""
    return "; ".join(f"`{h['command']}` (commit {h['commit']}, load average "
                     f"{h['load_average']})" for h in headers)


def creep_plate_vs_3d():
    """bench_creep_plate_vs_continuum --solid-meshes (two processes, each with its header line):
    the fixed-fixed strip's creep in the plate and in the 3D continuum. Each run's mesh error
    against its model's finest mesh (elastic and 500 h creep deflection); the elastic deflection
    against the Timoshenko beam; the 3D creep deflection's last changes along the span and
    through the thickness; then the ratios at equal accuracy from the summary line of the
    process that ran the finest 3D mesh."""
    lines = read_jsonl(DATA / "creep_plate_vs_3d.jsonl")
    headers = [x for x in lines if x.get("kind") == "header"]
    plate = [x for x in lines if x.get("kind") == "run" and x["model"] == "plate"]
    plate = plate[:len(plate) // len(headers)]  # every process ran the same plate meshes
    solid = sorted((x for x in lines if x.get("kind") == "run" and x["model"] == "3d"),
                   key=lambda x: (x["mesh"][0], x["mesh"][1], x["mesh"][2]))
    rows = [["model", "mesh", "unknowns", "linear solver", "IDA steps", "factorisations",
             "w elastic [m]", "mesh error", "w creep, 500 h [m]", "mesh error",
             "static solve CPU [s]", "whole run CPU [s]", "peak memory [GiB]"]]
    for model, runs in (("plate", plate), ("3D", solid)):
        finest = max(runs, key=lambda x: x["unknowns"])
        for x in runs:
            ref = "ref." if x is finest else None
            rows.append([model, " x ".join(str(n) for n in x["mesh"]), f"{x['unknowns']:,}",
                         "Schur + GMRES" if model == "plate" else ("UMFPACK" if x["umfpack"] else "KLU"),
                         str(x["steps"]), str(x["linear_setups"]), f"{x['w_elastic']:.4e}",
                         ref or f"{100 * (x['w_elastic'] / finest['w_elastic'] - 1):+.2f} %",
                         f"{x['w_plastic']:.4e}",
                         ref or f"{100 * (x['w_plastic'] / finest['w_plastic'] - 1):+.2f} %",
                         f"{x['elastic_cpu_s']:.3f}", f"{x['cpu_s']:.2f}", f"{x['max_rss_gib']:.2f}"])

    def change(a, b, key):
        """Relative change of key from run a to run b, in %."""
        return 100 * (b[key] / a[key] - 1)

    def run(nx, nz):
        return next(x for x in solid if x["mesh"][0] == nx and x["mesh"][1] == nz)

    # The elastic deflection against the clamped-clamped Timoshenko beam: q L^4 / (32 E h^3)
    # (Euler-Bernoulli, 12 q L^4 / (384 E h^3) per unit width) plus the shear part
    # q L^2 / (8 k G h), k = 5/6, G = E / (2 (1 + nu)); E = 200 GPa, nu = 0.3, L = 240 um (the
    # bench's FixedFixedCreepProblem).
    summary = next(x for x in lines if x.get("kind") == "summary")
    E, nu, L = 200e9, 0.3, 240e-6
    q, h = summary["load"], L / summary["slenderness"]
    timoshenko = -(q * L ** 4 / (32 * E * h ** 3) + q * L ** 2 / (8 * 5 / 6 * E / (2 * (1 + nu)) * h))
    finest = max(solid, key=lambda x: x["unknowns"])
    nx, nz = finest["mesh"][0], finest["mesh"][1]
    notes = (f"Timoshenko beam: elastic w = {timoshenko:.4e} m; the finest 3D mesh "
             f"{100 * (finest['w_elastic'] / timoshenko - 1):+.2f} % from it, the finest plate "
             f"{100 * (plate[-1]['w_elastic'] / timoshenko - 1):+.2f} %. The 3D creep deflection "
             f"changes {change(run(nx // 2 + 1, 12), run(nx, 12), 'w_plastic'):+.2f} % from "
             f"nx = {nx // 2 + 1} to {nx} (nz = 12) and "
             f"{change(run(nx, 12), run(nx, nz), 'w_plastic'):+.2f} % from nz = 12 to {nz} "
             f"(nx = {nx}); plate error against the finest 3D mesh 1 - w_plate / w_3D = "
             f"{100 * (1 - plate[-1]['w_plastic'] / finest['w_plastic']):+.2f} % (creep), "
             f"{100 * (1 - plate[-1]['w_elastic'] / finest['w_elastic']):+.2f} % (elastic).")
    m = next(x for x in lines if x.get("kind") == "summary" and x["model"] == "3d"
             and x["continuum_mesh"][:2] == finest["mesh"][:2])
    mesh = lambda v: " x ".join(str(n) for n in v if n)
    commands = commit_commands(headers)
    return (markdown(rows) +
            f"\n{notes}\n\n"
            f"Ratios in one process, each model at {100 * m['target']:g} % of its finest mesh: "
            f"creep, plate {mesh(m['plate_mesh'])} in {m['plate_cpu_s']:.2f} s CPU against 3D "
            f"{mesh(m['continuum_mesh'])} in {m['continuum_cpu_s']:.0f} s, **{m['cpu_ratio']:.0f}x** "
            f"(wall {m['wall_ratio']:.0f}x); static deflection, plate {mesh(m['plate_static_mesh'])} "
            f"in {m['plate_static_cpu_s']:.4f} s against 3D {mesh(m['continuum_static_mesh'])} in "
            f"{m['continuum_static_cpu_s']:.1f} s, **{m['static_cpu_ratio']:.0f}x**.\n\n"
            f"Commands: {commands}, {headers[0]['date']}.\n")


def amg_rigid_body_modes():
    """bench_amg_rigid_body_modes: one static solve of the thin 3D strip by GMRES with a
    BoomerAMG V-cycle, its interpolation unknown-based (rfmems-solid's setting) or fitted to the
    rigid-body rotations too, mesh by mesh: iterations, hierarchy, CPU, the centre deflection
    against a sparse LU solve's, and the ratios of the two variants."""
    lines = read_jsonl(DATA / "amg_rigid_body_modes.jsonl")
    header = next(x for x in lines if x.get("section") == "header")
    runs = [x for x in lines if x.get("section") == "strip"]
    rows = [["mesh (half span)", "unknowns", "interpolation", "GMRES iterations",
             "levels, complexity", "set-up CPU [s]", "solve CPU [s]", "w centre / LU - 1",
             "iterations unknown / rotations", "CPU unknown / rotations"]]
    for x in runs:
        mate = next(y for y in runs if y["mesh"] == x["mesh"] and y is not x)
        rotations = x["variant"] == "rotations"
        base, rbm = (mate, x) if rotations else (x, mate)
        cpu = lambda r: r["setup_cpu_s"] + r["solve_cpu_s"]
        rows.append([" x ".join(map(str, x["mesh"])), f"{x['unknowns']:,}",
                     "rigid-body rotations" if rotations else "unknown-based",
                     f"{x['iterations']}" + ("" if x["converged"] else " (not converged)"),
                     f"{x['levels']}, {x['operator_complexity']:.2f}", f"{x['setup_cpu_s']:.2f}",
                     f"{x['solve_cpu_s']:.2f}", f"{x['w_centre'] / x['w_centre_lu'] - 1:+.1e}",
                     f"{base['iterations'] / rbm['iterations']:.1f}x" if rotations else "",
                     f"{cpu(base) / cpu(rbm):.1f}x" if rotations else ""])
    return markdown(rows) + (f"\nCommand: `{header['command']}`, {header['date']} (1-minute "
                             f"load average {header['load_average_1min']:.1f} at the start).\n")


CREEP_SOLVER_NAMES = {"krylov": "GMRES, block preconditioner",
                      "direct": "sparse LU of the Jacobian"}


def creep_continuum_solvers():
    """python/creep_continuum_runs.py --set solvers (bench_creep_plate_vs_continuum, one process
    per mesh and solver, each with its header line): the continuum creep runs with IDA's GMRES
    and the block preconditioner (--continuum-solver krylov) beside IDA's sparse LU of the full
    Jacobian (direct), mesh by mesh: CPU, peak memory, IDA steps, GMRES iterations a Newton
    step, and how far apart the two creep deflections are."""
    lines = read_jsonl(DATA / "creep_continuum_solvers.jsonl")
    headers = [x for x in lines if x.get("kind") == "header"]
    runs = {}
    for x in lines:
        if x.get("kind") == "run" and x["model"] != "plate":
            runs[(x["model"], tuple(x["mesh"]), x.get("half_length", False), x["solver"])] = x
    keys = sorted({k[:3] for k in runs}, key=lambda k: (k[0] != "plane_stress", runs[
        k + ("krylov",)]["unknowns"]))
    rows = [["model, mesh (full span)", "unknowns", "GMRES: CPU [s]", "memory [GiB]", "IDA steps",
             "GMRES / Newton step", "sparse LU: CPU [s]", "memory [GiB]", "IDA steps",
             "CPU LU / GMRES", "memory LU / GMRES", "w creep, 500 h: GMRES [m]",
             "GMRES / LU - 1"]]
    for model, mesh, half in keys:
        k, d = runs[(model, mesh, half, "krylov")], runs.get((model, mesh, half, "direct"))
        name = "plane stress" if model == "plane_stress" else "3D"
        cells = [2 * mesh[0] if half else mesh[0]] + list(mesh[1:])
        label = f"{name}, {' x '.join(map(str, cells))}" + (
            f" (half span, {' x '.join(map(str, mesh))})" if half else "")
        row = [label, f"{k['unknowns']:,}", f"{k['cpu_s']:.1f}", f"{k['max_rss_gib']:.2f}",
               str(k["steps"]), f"{k['linear_iters'] / k['newton_iters']:.2f}"]
        if d:
            row += [f"{d['cpu_s']:.1f}", f"{d['max_rss_gib']:.2f}", str(d["steps"]),
                    f"{d['cpu_s'] / k['cpu_s']:.1f}x", f"{d['max_rss_gib'] / k['max_rss_gib']:.1f}x",
                    f"{k['w_plastic']:.6e}", f"{k['w_plastic'] / d['w_plastic'] - 1:+.1e}"]
        else:
            row += ["-"] * 5 + [f"{k['w_plastic']:.6e}", "-"]
        rows.append(row)
    return markdown(rows) + "\n" + runner_footer(headers, "solvers")


def runner_footer(headers, which):
    """The footer of a table from python/creep_continuum_runs.py: the runner's command, the
    commits, the load averages at the processes' starts and the first start."""
    commits = sorted({h["commit"] for h in headers})
    loads = [float(h["load_average"].split()[0]) for h in headers]
    return (f"Command: `/usr/bin/python3 python/creep_continuum_runs.py --set {which}` (one "
            f"process per row and solver, e.g. `{headers[0]['command']}`; commit "
            f"{', '.join(commits)}; 1-minute load average {min(loads):.1f}-{max(loads):.1f} at the "
            f"processes' starts, two running side by side), {headers[0]['date']}.\n")


def creep_3d_half_span():
    """bench_creep_plate_vs_continuum --half-length (one process a mesh, each with its header
    line): the 3D strip on its half span, a symmetry plane at the centre, beside the full-span
    runs of creep_plate_vs_3d.jsonl, every mesh named by its full-span cell count. The creep
    deflection's observed order along the span (nz = 16: 481, 960, 1920 cells) and through the
    thickness (about 960 cells: nz = 12, 16, 24), each direction's Richardson correction added
    to the finest run's (the errors taken as separable), and every run's and the plate's
    distance from that estimate; then the ratio, in one process, of the plate 21 x 3 against
    the cheapest 3D run within 1 % of it."""
    lines = read_jsonl(DATA / "creep_3d_half_span.jsonl")
    full = read_jsonl(DATA / "creep_plate_vs_3d.jsonl")
    headers = [x for x in lines if x.get("kind") == "header"]
    runs = []  # (full-span cells along x, nz, nw, run, half, plate run of the same process)
    plate = None
    for x in lines:
        if x.get("kind") != "run":
            continue
        if x["model"] == "plate":
            plate = x if x["mesh"] == [21, 3] else plate
            continue
        half = x.get("half_length", False)
        runs.append((2 * x["mesh"][0] if half else x["mesh"][0], x["mesh"][1], x["mesh"][2], x,
                     half, plate))
    for x in full:
        if x.get("kind") == "run" and x["model"] == "3d":
            runs.append((x["mesh"][0], x["mesh"][1], x["mesh"][2], x, False, None))
    plate_finest = next(x for x in full if x.get("kind") == "run" and x["model"] == "plate"
                        and x["mesh"] == [81, 5])

    def w(nx, nz):
        return next(r[3]["w_plastic"] for r in runs if r[0] == nx and r[1] == nz and r[2] == 3)

    # Along the span, refinement ratio 2 (481 -> 960 -> 1920 at nz = 16).
    dx1, dx2 = w(960, 16) - w(481, 16), w(1920, 16) - w(960, 16)
    px = math.log(dx1 / dx2) / math.log(2)
    cx = dx2 / (2 ** px - 1)
    # Through the thickness, ratios 4/3 and 3/2: the order p solves
    # (w16 - w12) / (w24 - w16) = (12^-p - 16^-p) / (16^-p - 24^-p).
    dz1, dz2 = w(960, 16) - w(961, 12), w(960, 24) - w(960, 16)
    ratio = lambda p: (12 ** -p - 16 ** -p) / (16 ** -p - 24 ** -p)
    lo, hi = 0.1, 8.0
    for _ in range(100):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if ratio(mid) < dz1 / dz2 else (lo, mid)
    pz = (lo + hi) / 2
    cz = dz2 * 24 ** -pz / (16 ** -pz - 24 ** -pz)
    estimate = w(960, 16) + dx2 + cx + dz2 + cz

    rows = [["3D mesh (full span)", "computed", "unknowns", "linear solver", "w elastic [m]",
             "w creep, 500 h [m]", "from the estimate", "whole run CPU [s]", "peak memory [GiB]"]]
    for nx, nz, nw, x, half, _ in sorted(runs, key=lambda r: (r[0], r[1], r[2])):
        rows.append([f"{nx} x {nz} x {nw}",
                     f"half span, {x['mesh'][0]} x {nz} x {nw}" if half else "full span",
                     f"{x['unknowns']:,}", CREEP_SOLVER_NAMES[x.get("solver", "direct")],
                     f"{x['w_elastic']:.4e}", f"{x['w_plastic']:.4e}",
                     f"{100 * (x['w_plastic'] / estimate - 1):+.2f} %", f"{x['cpu_s']:.0f}",
                     f"{x['max_rss_gib']:.1f}"])
    within = [r for r in runs if r[4] and abs(r[3]["w_plastic"] / estimate - 1) <= 0.01]
    cheapest = min(within, key=lambda r: r[3]["cpu_s"]) if within else None
    ratio_text = (
        f"Ratio in one process: plate 21 x 3 in {cheapest[5]['cpu_s']:.2f} s CPU against 3D "
        f"{cheapest[0]} x {cheapest[1]} x {cheapest[2]} (half span) in {cheapest[3]['cpu_s']:.0f} s, "
        f"the cheapest 3D run within 1 % of the estimate: **{cheapest[3]['cpu_s'] / cheapest[5]['cpu_s']:.0f}x** CPU."
        if cheapest else "No 3D run lies within 1 % of the estimate.")
    commands = commit_commands(headers)
    return (markdown(rows) +
            f"\nObserved orders of the creep deflection: {px:.2f} along the span (changes "
            f"{100 * dx1 / w(481, 16):+.2f} % and {100 * dx2 / w(960, 16):+.2f} %), {pz:.2f} "
            f"through the thickness (changes {100 * dz1 / w(961, 12):+.2f} % and "
            f"{100 * dz2 / w(960, 16):+.2f} %). Estimate w_3D = {estimate:.4e} m (Richardson "
            f"corrections {100 * cx / estimate:+.2f} % along the span, {100 * cz / estimate:+.2f} % "
            f"through the thickness). Plate against it, 1 - w_plate / w_3D: 21 x 3 "
            f"{100 * (1 - plate['w_plastic'] / estimate):+.2f} %, 81 x 5 "
            f"{100 * (1 - plate_finest['w_plastic'] / estimate):+.2f} %.\n\n{ratio_text}\n\n"
            f"Commands: {commands}, {headers[0]['date']}.\n")


TABLES = {
    "verification-checks": csv_table("verification_checks.csv"),
    "performance-ratios": csv_table("performance_ratios.csv"),
    "creep-plate-vs-continuum": csv_table("creep_plate_vs_continuum.csv"),
    "creep-plate-vs-3d": creep_plate_vs_3d,
    "creep-3d-half-span": creep_3d_half_span,
    "creep-continuum-solvers": creep_continuum_solvers,
    "pullin-time-check": csv_table("pullin_time_check.csv"),
    "pullin-laplace-dynamic": pullin_laplace_dynamic,
    "coupling-default-study-ab": coupling_default_study_ab,
    "comet-two-ranks": comet_two_ranks,
    "comet-by-regime": comet_by_regime,
    "gas-mpi-agreement": gas_mpi_agreement,
    "immersed-esbgk-stepper": immersed_esbgk_stepper,
    "gas-damping-second-order-sweep": gas_damping_second_order_sweep,
    "immersed-esbgk-case-keys": immersed_esbgk_case_keys,
    "immersed-switch-figures": csv_table("immersed_switch_figures.csv"),
    "ibm-couette": csv_table("ibm_couette.csv"),
    "kinetic-linearised-bgk": csv_table("kinetic_linearised_bgk.csv"),
    "kinetic-published-tables": kinetic_published_tables,
    "coupling-schemes-deflection": coupling_schemes("deflection"),
    "coupling-schemes-touch-down": coupling_schemes("touch_down"),
    "coupling-schemes-study": coupling_schemes_study,
    "modal-cost": modal_cost,
    "quasi-static-trace": quasi_static_trace,
    "modal-vs-transient": modal_vs_transient,
    "modal-bias": modal_bias,
    "residual-stress-sweep": residual_stress_sweep,
    "residual-stress-bias": lambda: modal_bias("residual_stress_bias.jsonl"),
    "residual-stress-switch": residual_stress_switch,
    "velocity-grids": velocity_grids,
    "velocity-grids-goal": velocity_grids_goal,
    "flow-factor-table": flow_factor_table,
    "flow-factor-strip-damping": flow_factor_strip_damping,
    "flow-factor-switch-plate": flow_factor_switch_plate,
    "scale-box-3d": scale_runs("scale_box_3d.jsonl"),
    "scale-plane-stress": scale_runs("scale_plane_stress.jsonl"),
    "scale-plate": scale_runs("scale_plate.jsonl"),
    "scale-ranks": scale_ranks,
    "amg-rigid-body-modes": amg_rigid_body_modes,
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
