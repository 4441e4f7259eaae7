"""rfmems-pullin over the table of what a switch scene can combine (coupling/scene_combinations.hpp):
every supported cell (structure x field x gas x analysis x coupling scheme) runs on a small scene
and its physics is asserted against the other cells of the same scene; every unsupported cell is
bad input (exit 2, one line naming the key, the value and what is allowed instead, no result
file).

Scenes (coarse, seconds a run):
  plate    cases/switch_plate on 20 x 2 cells (parallel-plate law, with or without the film);
  plane    cases/switch_plane_laplace on 25 x 2 cells, 4 gap cells (parallel-plate or Laplace);
  immersed cases/cantilever_switch on 46 x 4 / 101 x 31 (none, reynolds); the esbgk gas on
           45 x 3 / 76 x 26 with 6^3 velocities, 20 ns transients (its dynamic bisection is a
           10-40 min study: `--kinetic-dynamic` runs it, the `study` label).

What each cell asserts:
  the table printed by --scenes is this file's (a change to either is deliberate);
  static and quasi-static agree: the static deflection lies on the quasi-static curve at its
    voltage (the same coupled equilibrium), and the gas does not change an equilibrium;
  dynamic: V_dyn / V_qs in the undamped range of a parallel-plate actuator (0.85-0.95; 0.92 for
    a lumped one, Nielson & Barbastathis 2006), the film raises V_dyn, and the coupling schemes
    of one scene find the same bisection interval;
  transient: the schemes of one scene agree (the partitioned and staggered ones to their lag,
    the implicit and strongly coupled ones closely); a step far below pull-in overshoots to about
    twice its static deflection (the undamped step response of a softening spring: 2.0-2.3x);
    a film lowers the peak;
  harmonic (the parallel-plate scenes): linearised about the static equilibrium at a voltage of
    the quasi-static curve, which it lands on.

Usage: python3 scene_combinations.py <directory of rfmems-pullin> <source directory>
       [--kinetic-dynamic]
"""
import itertools
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

DRIVER = os.path.join(sys.argv[1], "rfmems-pullin")
SRC = sys.argv[2]
KINETIC_DYNAMIC = "--kinetic-dynamic" in sys.argv
CASES = {
    "plate": f"{SRC}/cases/switch_plate/case.yaml",
    "plane": f"{SRC}/cases/switch_plane_laplace/case.yaml",
    "immersed": f"{SRC}/cases/cantilever_switch/case.yaml",
}
COARSE = {
    "plate": ["mesh.cells=[20, 2]"],
    "plane": ["mesh.cells=[25, 2]", "actuation.laplace.gap_cells=4",
              "solver={rtol: 1e-4, error_weights: per_kind, velocity_frequency: 385 kHz}"],
    "immersed": ["mesh.cells=[46, 4]", "actuation.immersed.background.cells=[101, 31]"],
    "kinetic": ["mesh.cells=[45, 3]", "actuation.immersed.background.cells=[76, 26]",
                "gas.velocities=6", "gas.step_tolerance=1e-8"],
}
STRUCTURES = ["plate", "plane"]
FIELDS = ["parallel_plate", "laplace", "immersed"]
GASES = ["none", "reynolds", "esbgk"]
ANALYSES = ["static", "quasi_static", "dynamic", "transient", "harmonic"]
SCHEMES = ["monolithic", "staggered", "implicit", "strongly_coupled"]
TIMED = ("dynamic", "transient")

# The table: (structure, field, gas) -> {analysis: schemes of the timed ones}.
PP = {"quasi_static": [], "dynamic": ["monolithic"], "transient": ["monolithic"], "harmonic": []}
# The fields without exact Jacobian blocks (laplace, immersed): the field-coupled structure's schemes.
LAGGED = {"static": [], "quasi_static": [], "dynamic": ["staggered", "implicit", "strongly_coupled"],
          "transient": ["staggered", "implicit", "strongly_coupled"]}
TABLE = {
    ("plate", "parallel_plate", "none"): PP,
    ("plate", "parallel_plate", "reynolds"): {
        **PP, "dynamic": ["monolithic", "staggered", "strongly_coupled"],
        "transient": ["monolithic", "staggered", "strongly_coupled"]},
    ("plane", "parallel_plate", "none"): PP,
    ("plane", "laplace", "none"): LAGGED,
    ("plane", "immersed", "none"): LAGGED,
    ("plane", "immersed", "reynolds"): LAGGED,
    ("plane", "immersed", "esbgk"): LAGGED,
}

failures = 0
work = tempfile.mkdtemp()


def check(ok, what):
    global failures
    print(("PASS: " if ok else "FAIL: ") + what, flush=True)
    failures += not ok


def scene_of(structure, field, gas):
    """The case and the overrides of a cell's scene."""
    if field == "immersed":
        base = "immersed"
        sets = COARSE["kinetic"] if gas == "esbgk" else COARSE["immersed"]
    else:
        base = "plate" if structure == "plate" else "plane"
        sets = list(COARSE[base])
    sets = list(sets) + [f"model.structure={structure}", f"actuation.electrostatics={field}"]
    if field == "immersed":  # the case's gas section holds the gas's properties
        sets.append(f"gas.model={gas}")
    else:
        sets.append(f"gas={{model: {gas}{', pressure: 1 atm' if gas == 'reynolds' else ''}}}")
    return CASES[base], sets


def run(name, case, sets):
    """The driver's --json summary (None and the error if it failed), and the wall time."""
    cmd = [DRIVER, case, "-o", f"{work}/{name}.h5", "--json", "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode != 0:
        return None, p, wall
    return json.loads(p.stdout), p, wall


# --- the table -------------------------------------------------------------------------------
printed = subprocess.run([DRIVER, "--scenes"], capture_output=True, text=True).stdout
rows = {}
for line in printed.splitlines()[2:]:
    cells = [c.strip() for c in line.strip("|").split("|")]
    analyses = [a.strip() for a in cells[3].split(",")]
    schemes = {a: [] for a in analyses}
    for part in cells[4].split(";"):
        if ":" in part:
            a, names = part.split(":")
            schemes[a.strip()] = [n.strip() for n in names.split(",")]
    rows[tuple(cells[:3])] = schemes
check(rows == TABLE, f"--scenes prints the table this test knows ({len(rows)} combinations of models)")
for page in ("README.md", "docs/running.md"):
    check(printed in open(f"{SRC}/{page}").read(), f"{page} shows the table --scenes prints")

# --- unsupported cells: exit 2, one line with the key and what is allowed --------------------
bad = []
for s, f, g in itertools.product(STRUCTURES, FIELDS, GASES):
    row = TABLE.get((s, f, g))
    if row is None:
        bad.append((s, f, g, "quasi_static", None))
        continue
    for a in ANALYSES:
        if a not in row:
            bad.append((s, f, g, a, None))
        elif a in TIMED:
            bad += [(s, f, g, a, c) for c in SCHEMES if c not in row[a]]
wrong = []
for i, (s, f, g, a, c) in enumerate(bad):
    case, sets = scene_of(s, f, g)
    sets = sets + [f"pull_in.mode={a}"] + ([f"coupling={{scheme: {c}}}"] if c else [])
    summary, p, _ = run(f"bad{i}", case, sets)
    lines = p.stderr.strip().splitlines()
    if (p.returncode != 2 or len(lines) != 1 or "allowed: " not in lines[0] or
            os.path.exists(f"{work}/bad{i}.h5")):
        wrong.append(f"{s}/{f}/{g}/{a}/{c}: exit {p.returncode}: {p.stderr.strip()[:200]}")
check(not wrong, f"{len(bad)} unsupported cells exit 2 naming what is allowed" +
      ("".join("\n  " + w for w in wrong)))

# --- supported cells -------------------------------------------------------------------------
results = {}


def cell(s, f, g, a, c, extra=(), name=None):
    case, sets = scene_of(s, f, g)
    sets = sets + [f"pull_in.mode={a}"] + ([f"coupling={{scheme: {c}}}"] if c else []) + list(extra)
    key = name or f"{s}-{f}-{g}-{a}-{c or 'none'}"
    summary, p, wall = run(key, case, sets)
    check(summary is not None, f"{key} runs ({wall:.1f} s)" +
          ("" if summary else f": exit {p.returncode}: {p.stderr.strip()[:300]}"))
    results[(s, f, g, a, c)] = summary["pull_in"] if summary else None
    return results[(s, f, g, a, c)]


def curve_point(qs_h5, k):
    """Point k of the quasi-static curve: (voltage, control deflection)."""
    import h5py
    with h5py.File(qs_h5) as h:
        x = h["pull_in/curve/control_displacement"][()]
        v = h["pull_in/curve/values"][()]
    return float(v[k, 0]), float(x[k])


def static_on_curve(name, s, f, g, qs_h5):
    """The static solve at the curve's third point's voltage lands on that point (the same
    coupled equilibrium, voltage- against displacement-controlled)."""
    v, x_curve = curve_point(qs_h5, 2)
    st = cell(s, f, g, "static", None, [f"pull_in.static={{voltage: {v!r} V}}"])
    if st:
        x = st["static"]["control"]
        check(abs(x / x_curve - 1) < 1e-4,
              f"{name}: the static deflection at {v:.3f} V is the curve's ({x:.6e} / {x_curve:.6e})")


FAST = {  # a short bisection: the bracket around V_dyn, no histories, no check
    "plate": ["pull_in.dynamic={end_time: 30 us, bracket: [150 V, 190 V], tolerance: 2 V, "
              "voltages: [], small_signal: 0, time_check: 0}"],
    "plane": ["pull_in.dynamic={end_time: 20 us, bracket: [450 V, 560 V], tolerance: 6 V, "
              "voltages: [], small_signal: 0, time_check: 0}"],
    "immersed": ["pull_in.dynamic={end_time: 6 us, bracket: [118 V, 127 V], tolerance: 2.5 V, "
                 "voltages: [], small_signal: 0, time_check: 0}"],
}

# The plate: quasi-static with and without the film, dynamic, transients of every scheme.
for g in ("none", "reynolds"):
    cell("plate", "parallel_plate", g, "quasi_static", None)
    for c in TABLE[("plate", "parallel_plate", g)]["dynamic"]:
        cell("plate", "parallel_plate", g, "dynamic", c, FAST["plate"])
TR_PLATE = ["pull_in.transient={voltage: 180 V, end_time: 3 us}"]
for c in TABLE[("plate", "parallel_plate", "reynolds")]["transient"]:
    cell("plate", "parallel_plate", "reynolds", "transient", c, TR_PLATE)
cell("plate", "parallel_plate", "none", "transient", "monolithic", TR_PLATE[:1])
r = results
q0 = r[("plate", "parallel_plate", "none", "quasi_static", None)]
q1 = r[("plate", "parallel_plate", "reynolds", "quasi_static", None)]
if q0 and q1:
    check(q0["quasi_static"]["pull_in_voltage"] == q1["quasi_static"]["pull_in_voltage"],
          "plate: the film does not move the quasi-static fold")
d0 = r[("plate", "parallel_plate", "none", "dynamic", "monolithic")]
d1 = r[("plate", "parallel_plate", "reynolds", "dynamic", "monolithic")]
if d0 and d1:
    ratio = d0["dynamic"]["ratio_to_quasi_static"]
    check(0.85 < ratio < 0.95, f"plate in vacuum: V_dyn / V_qs = {ratio:.3f}")
    check(d1["dynamic"]["pull_in_voltage"] > d0["dynamic"]["pull_in_voltage"],
          "plate: the film raises V_dyn ({:.1f} V against {:.1f} V)".format(
              d1["dynamic"]["pull_in_voltage"], d0["dynamic"]["pull_in_voltage"]))
dyn = [r[("plate", "parallel_plate", "reynolds", "dynamic", c)] for c in
       ("monolithic", "staggered", "strongly_coupled")]
if all(dyn):
    intervals = [(d["dynamic"]["not_pulling_in"], d["dynamic"]["pull_in_voltage"]) for d in dyn]
    check(len(set(intervals)) == 1,
          f"plate + film: the same bisection interval by every scheme ({intervals})")
tr = {c: r[("plate", "parallel_plate", "reynolds", "transient", c)] for c in
      ("monolithic", "staggered", "strongly_coupled")}
if all(tr.values()):
    w = {c: t["transient"]["final_control"] for c, t in tr.items()}
    e = {c: abs(w[c] / w["monolithic"] - 1) for c in w}
    check(e["strongly_coupled"] < 1e-4 and e["staggered"] < 2e-3,
          f"plate + film at 3 us: strongly coupled {e['strongly_coupled']:.1e}, staggered "
          f"{e['staggered']:.1e} from monolithic")
    vac = r[("plate", "parallel_plate", "none", "transient", "monolithic")]
    if vac:
        check(vac["transient"]["extreme_control"] < tr["monolithic"]["transient"]["extreme_control"],
              "plate: the film slows the 180 V step")



def harmonic_on_curve(name, s, f, g, qs_h5):
    """The harmonic analysis at the curve's third point's voltage linearises about that point
    (its static equilibrium, voltage-controlled, against the displacement-controlled curve, whose
    points hold to the quasi-static Newton tolerance: 6e-6 here)."""
    v, x_curve = curve_point(qs_h5, 2)
    h = cell(s, f, g, "harmonic", None, [f"pull_in.harmonic={{bias: {v!r} V, frequencies: [1 Hz]}}"])
    if h:
        x = h["harmonic"]["static_control"]
        check(abs(x / x_curve - 1) < 1e-4 and h["harmonic"]["control"]["amplitude"][0] > 0,
              f"{name}: the harmonic analysis at {v:.3f} V is about the curve's point "
              f"({x:.6e} / {x_curve:.6e})")


for g in ("none", "reynolds"):
    harmonic_on_curve(f"plate, gas {g}", "plate", "parallel_plate", g,
                      f"{work}/plate-parallel_plate-{g}-quasi_static-none.h5")

# The plane beam: parallel-plate and Laplace fields.
for f in ("parallel_plate", "laplace"):
    qs = cell("plane", f, "none", "quasi_static", None)
    schemes = TABLE[("plane", f, "none")]["dynamic"]
    for c in schemes:
        cell("plane", f, "none", "dynamic", c, FAST["plane"])
    if not qs:
        continue
    v_qs = qs["quasi_static"]["pull_in_voltage"]
    qs_h5 = f"{work}/plane-{f}-none-quasi_static-none.h5"
    if f == "parallel_plate":
        harmonic_on_curve("plane", "plane", f, "none", qs_h5)
    # A step at the curve's first point (a small deflection), recorded over ~2 periods (the
    # coarse beam's ~385 kHz): its peak against that point's static deflection.
    v, x_curve = curve_point(qs_h5, 0)
    for c in schemes:
        cell("plane", f, "none", "transient", c,
             [f"pull_in.transient={{voltage: {v!r} V, end_time: 5 us, output_interval: 5 ns}}"])
    if f == "laplace":
        static_on_curve(f"plane/{f}", "plane", f, "none", qs_h5)
    dyn = [r[("plane", f, "none", "dynamic", c)] for c in schemes]
    if all(dyn):
        ratios = [d["dynamic"]["ratio_to_quasi_static"] for d in dyn]
        same = len({(d["dynamic"]["pull_in_voltage"], d["dynamic"]["not_pulling_in"]) for d in dyn}) == 1
        check(all(0.85 < x < 0.95 for x in ratios) and same,
              f"plane/{f}: V_dyn / V_qs {ratios}, the same interval by every scheme")
    trs = [r[("plane", f, "none", "transient", c)] for c in schemes]
    if all(trs):
        peaks = [t["transient"]["extreme_control"] for t in trs]
        overshoot = peaks[0] / x_curve
        check(2.0 < overshoot < 2.3, f"plane/{f}: the step peaks at {overshoot:.3f} x its static "
              "deflection")
        check(max(abs(p / peaks[0] - 1) for p in peaks) < 1e-3,
              f"plane/{f}: the schemes' peaks agree ({peaks})")
pp = r[("plane", "parallel_plate", "none", "quasi_static", None)]
lp = r[("plane", "laplace", "none", "quasi_static", None)]
if pp and lp:
    a, b = pp["quasi_static"]["pull_in_voltage"], lp["quasi_static"]["pull_in_voltage"]
    check(abs(b / a - 1) < 0.03, f"plane: the Laplace fold {b:.1f} V within 3 % of the parallel-plate "
          f"law's {a:.1f} V (the thesis's 181 against 177 V)")

# The immersed field: every gas, every analysis, every scheme.
for g in ("none", "reynolds"):
    qs = cell("plane", "immersed", g, "quasi_static", None)
    if qs:
        static_on_curve(f"immersed/{g}", "plane", "immersed", g,
                        f"{work}/plane-immersed-{g}-quasi_static-none.h5")
    for c in TABLE[("plane", "immersed", g)]["dynamic"]:
        cell("plane", "immersed", g, "dynamic", c, FAST["immersed"])
        cell("plane", "immersed", g, "transient", c,
             ["pull_in.transient={voltage: 80 V, end_time: 0.8 us}"])
for g in ("none", "reynolds"):
    dyn = [r[("plane", "immersed", g, "dynamic", c)] for c in LAGGED["dynamic"]]
    if all(dyn):
        same = len({(d["dynamic"]["pull_in_voltage"], d["dynamic"]["not_pulling_in"]) for d in dyn}) == 1
        ratio = dyn[0]["dynamic"]["ratio_to_quasi_static"]
        check(same and 0.85 < ratio < 0.95,
              f"immersed/{g}: every scheme finds the same interval, V_dyn / V_qs {ratio:.3f}")
    trs = [r[("plane", "immersed", g, "transient", c)] for c in LAGGED["transient"]]
    if all(trs):
        peaks = [t["transient"]["extreme_control"] for t in trs]
        check(max(abs(p / peaks[1] - 1) for p in peaks) < 2e-3,
              f"immersed/{g}: the schemes' 80 V peaks agree with the implicit one ({peaks})")
t0 = r[("plane", "immersed", "none", "transient", "implicit")]
t1 = r[("plane", "immersed", "reynolds", "transient", "implicit")]
if t0 and t1:
    a, b = t0["transient"]["extreme_control"], t1["transient"]["extreme_control"]
    check(b > a and abs(b / a - 1) > 5e-3, f"immersed: the film lowers the 80 V peak ({b:.4e} against {a:.4e})")

# The kinetic gas: equilibria (the gas at rest does not load the beam) and 20 ns transients.
g = "esbgk"
qs = cell("plane", "immersed", g, "quasi_static", None)
if qs:
    static_on_curve("immersed/esbgk", "plane", "immersed", g,
                    f"{work}/plane-immersed-{g}-quasi_static-none.h5")
peaks = []
for c in LAGGED["transient"]:
    t = cell("plane", "immersed", g, "transient", c,
             ["pull_in.transient={voltage: 80 V, end_time: 0.02 us, output_interval: 1 ns}"])
    if t:
        peaks.append(t["transient"]["extreme_control"])
if len(peaks) == 3:
    check(max(abs(p / peaks[1] - 1) for p in peaks) < 2e-3,
          f"immersed/esbgk: the schemes' 20 ns deflections agree ({peaks})")
if KINETIC_DYNAMIC:
    for c in LAGGED["dynamic"]:
        cell("plane", "immersed", g, "dynamic", c, FAST["immersed"])

sys.exit(1 if failures else 0)
