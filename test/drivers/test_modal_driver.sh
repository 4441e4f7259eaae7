#!/usr/bin/env bash
# rfmems-solid with analysis.type modal, on the two vibration cases: the JSON's modes (first
# frequencies against their closed forms, ascending, undamped plate, the solver statistics),
# the result file's /modal/modes table and one shape per mode (largest displacement component
# +1), python/plot_modes.py on it, and the bad-input contract for the modal keys (modes < 1,
# more modes than the structure has, a negative or non-frequency shift, modal under
# solver.distributed); and analysis.type harmonic: the resonance of a sweep, the phase on
# either side, the result file, and its bad input.
#
# Usage: bash test_modal_driver.sh <directory of rfmems-solid> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-solid"
SRC="$2"
PLATE="$SRC/cases/plate_vibration/case.yaml"
BEAM="$SRC/cases/cantilever_vibration/case.yaml"
# The transient cases' analysis and solver sections replaced by a modal analysis.
# modal EXTRA: the arguments, in MODAL, for analysis {type: modal<EXTRA>}.
modal() { MODAL=(--set "analysis={type: modal$1}" --set "solver={}"); }

source "$SRC/test/drivers/common.sh"

# ---- the plate strip: 6 modes -----------------------------------------------------------
modal ""
expect_json_run plate "modal plate_vibration" "$PLATE" "${MODAL[@]}"
if $PY - "$WORK/plate.json" <<'PY'; then
import json, math, sys
d = json.load(open(sys.argv[1]))
assert d["analysis"] == "modal", d["analysis"]
modes = d["modes"]
assert len(modes) == 6 and [m["index"] for m in modes] == list(range(1, 7)), modes
f = [m["frequency"] for m in modes]
assert f == sorted(f), f
# Euler-Bernoulli clamped-clamped, b L = 4.7300407: 6.4839e4 Hz; the thesis's 6.497e4 Hz.
f_eb = 4.730040744862704**2 / (2 * math.pi * math.sqrt(12)) * 2e-6 / 400e-6**2 * math.sqrt(200e9 / 7854)
assert abs(f[0] / f_eb - 1) < 1e-3, (f[0], f_eb)
assert abs(f[0] / 6.497e4 - 1) < 5e-3, f[0]
for m in modes:
    assert m["damping_ratio"] == 0 and not m["complex"] and m["eigenvalue_imag"] == 0, m
    assert abs(m["angular_frequency"] - 2 * math.pi * m["frequency"]) < 1e-9 * m["angular_frequency"]
    assert abs(m["eigenvalue_real"] / m["angular_frequency"]**2 - 1) < 1e-12, m
s = d["solver"]
assert s["modes_converged"] == s["modes_requested"] == 6, s
assert s["operator_applications"] >= 6 and s["factor_time_s"] >= 0 and s["eigensolve_time_s"] >= 0, s
assert d["state"]["at_rest"] is False  # the case's pressure: its static state first
assert d["n_outputs"] == 6
print(f"f1 = {f[0]:.6g} Hz ({100 * (f[0] / f_eb - 1):+.4f} % vs Euler-Bernoulli)")
PY
  pass "plate modes: ascending, undamped, first within 0.1 % of Euler-Bernoulli"
else
  fail "plate modes JSON: $(head -c 600 "$WORK/plate.json")"
fi

if $PY - "$WORK/plate.h5" "$WORK/plate.json" <<'PY'; then
import json, sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], "r")
d = json.load(open(sys.argv[2]))
names = [n.decode() if isinstance(n, bytes) else n for n in f["modal/modes/values"].attrs["components"]]
table = f["modal/modes/values"][()]
assert list(f["modal/modes/mode"][()]) == [1, 2, 3, 4, 5, 6]
col = names.index("frequency")
assert np.allclose(table[:, col], [m["frequency"] for m in d["modes"]], rtol=1e-12)
assert list(f["fields/times"][()]) == [1, 2, 3, 4, 5, 6]
for k in range(6):
    w = f[f"fields/{k:06d}/deflection"][()].reshape(-1, 3)[:, 2]
    assert abs(w.max() - 1) < 1e-12, (k, w.max())
    assert abs(w).max() <= 1 + 1e-12
assert f["metadata"].attrs["analysis"] in (b"modal", "modal")
PY
  pass "result file: /modal/modes matches the JSON, one shape per mode with max w = 1"
else
  fail "plate modal result file"
fi
[ -f "$WORK/plate.xdmf" ] && pass "modal run writes the XDMF sidecar" || fail "no plate.xdmf"

if $PY "$SRC/python/plot_modes.py" "$WORK/plate.h5" -o "$WORK/plate" >/dev/null 2>"$WORK/err" &&
   [ -s "$WORK/plate_frequencies.png" ] && [ -s "$WORK/plate_shapes.png" ]; then
  pass "plot_modes.py draws the frequencies and the shapes"
else
  fail "plot_modes.py: $(cat "$WORK/err")"
fi

# ---- the plane-stress cantilever: 3 modes, near a shift --------------------------------
modal ", modes: 3"
expect_json_run beam "modal cantilever_vibration" "$BEAM" "${MODAL[@]}"
modal ", modes: 1, shift: 140 Hz"
expect_json_run shifted "modal cantilever_vibration shifted to 140 Hz" "$BEAM" "${MODAL[@]}"
if $PY - "$WORK/beam.json" "$WORK/shifted.json" <<'PY'; then
import json, math, sys
d = json.load(open(sys.argv[1]))
shifted = json.load(open(sys.argv[2]))
f = [m["frequency"] for m in d["modes"]]
# Euler-Bernoulli cantilever: 1.8751^2 / (2 pi L^2) sqrt(E h^2 / (12 rho)) = 8.1517 Hz; the
# second and third modes at (4.6941 / 1.8751)^2 and (7.8548 / 1.8751)^2 of it (shear lowers them).
f1 = 1.875104068711961**2 / (2 * math.pi * 4) * math.sqrt(200e9 * 0.04**2 / (12 * 7854))
assert abs(f[0] / f1 - 1) < 5e-3, (f, f1)
assert abs(f[1] / (f1 * (4.694091132974175 / 1.875104068711961)**2) - 1) < 1e-2, f
assert abs(f[2] / (f1 * (7.854757438237613 / 1.875104068711961)**2) - 1) < 2e-2, f
# The mode nearest 140 Hz is the third.
assert abs(shifted["modes"][0]["frequency"] / f[2] - 1) < 1e-8, (shifted["modes"], f)
# Kelvin-Voigt grid damping C = beta K: zeta = beta omega / 2 grows with the frequency.
z = [m["damping_ratio"] for m in d["modes"]]
w = [m["angular_frequency"] for m in d["modes"]]
assert all(x > 0 for x in z) and abs(z[1] / z[0] - w[1] / w[0]) < 1e-6 * w[1] / w[0], (z, w)
print(f"f = {f} Hz, Euler-Bernoulli f1 = {f1:.6g} Hz")
PY
  pass "cantilever modes against Euler-Bernoulli; the shift picks the mode nearest 140 Hz"
else
  fail "cantilever modes: $(head -c 600 "$WORK/beam.json")"
fi
if $PY - "$WORK/beam.h5" <<'PY'; then
import sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], "r")
for k in range(3):
    u = f[f"fields/{k:06d}/displacement"][()].reshape(-1, 3)
    assert abs(np.abs(u).max() - 1) < 1e-12 and abs(u.max() - 1) < 1e-12, (k, u.max())
PY
  pass "continuum shapes: largest displacement component +1"
else
  fail "continuum modal result file"
fi

# ---- harmonic: the plate strip's response to its load over a sweep ----------------------
# The largest centre deflection is at the sweep's point nearest the first natural frequency,
# and below it the response is in phase with the load (the case's load pushes along -z, so the
# centre's w is negative: phase 180 degrees), above it in antiphase.
expect_json_run harmonic "harmonic plate_vibration" "$PLATE" \
  --set "analysis={type: harmonic, sweep: {from: 10 kHz, to: 200 kHz, points: 60}}" --set "solver={}"
if $PY - "$WORK/harmonic.json" "$WORK/plate.json" "$WORK/harmonic.h5" <<'PY'; then
import json, math, sys
import h5py
d = json.load(open(sys.argv[1]))
f1 = json.load(open(sys.argv[2]))["modes"][0]["frequency"]
assert d["analysis"] == "harmonic", d["analysis"]
f = d["harmonic"]["frequencies"]
assert len(f) == 60 and abs(f[0] - 1e4) < 1e-6 and abs(f[-1] - 2e5) < 1e-4, f
w = d["harmonic"]["probes"]["centre"]["w"]
top = max(range(len(f)), key=lambda k: w["amplitude"][k])
nearest = min(range(len(f)), key=lambda k: abs(math.log(f[k] / f1)))
assert top == nearest, (f[top], f1)
phase = w["phase_deg"]
assert all(abs(abs(phase[k]) - 180) < 1e-6 for k in range(len(f)) if f[k] < 0.9 * f1), phase
assert all(abs(phase[k]) < 1e-6 for k in range(len(f)) if 1.1 * f1 < f[k] < 2.5 * f1), phase
assert d["solver"]["factorizations"] == 1 and d["solver"]["refactorizations"] == 59, d["solver"]
h = h5py.File(sys.argv[3], "r")
values = h["harmonic/centre/values"][()]
assert values.shape == (60, 6), values.shape
assert abs(math.hypot(values[top, 0], values[top, 1]) / w["amplitude"][top] - 1) < 1e-12
PY
  pass "harmonic: resonance at the first mode, in phase below, antiphase above; result file"
else
  fail "harmonic sweep"
fi

# ---- bad input -------------------------------------------------------------------------
modal ", modes: 0"
expect_input_error zero_modes "analysis.modes' = 0: must be in \[1, " "$PLATE" "${MODAL[@]}"
modal ", modes: 100000"
expect_input_error too_many "analysis.modes' = 100000: must be in \[1, 158\]" "$PLATE" \
  "${MODAL[@]}"
modal ", shift: -1 kHz"
expect_input_error negative_shift "analysis.shift' = '-1 kHz': must be >= 0" "$PLATE" \
  "${MODAL[@]}"
modal ", shift: 3 m"
expect_input_error shift_unit "analysis.shift' = '3 m'" "$PLATE" "${MODAL[@]}"
expect_input_error modal_distributed "solver.distributed" "$BEAM" \
  --set "analysis={type: modal}" --set "solver={distributed: true}"
expect_input_error harmonic_none "analysis.frequencies': give the frequencies or a sweep" \
  "$PLATE" --set "analysis={type: harmonic}" --set "solver={}"
expect_input_error harmonic_negative "analysis.frequencies' = .*every frequency must be > 0" \
  "$PLATE" --set "analysis={type: harmonic, frequencies: [1 kHz, -2 kHz]}" --set "solver={}"
expect_input_error harmonic_sweep "analysis.sweep.to' = '1 kHz': must not be below" \
  "$PLATE" --set "analysis={type: harmonic, sweep: {from: 2 kHz, to: 1 kHz}}" --set "solver={}"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
