#!/usr/bin/env bash
# Plate runs through rfmems-solid (model.structure: plate), end to end: the clamped square
# plate case against Timoshenko's centre deflection and moment (thesis Tables 3.2, 3.3), the
# plate vibration case's frequency from its probe (python/probe_frequency.py) against the
# thesis's 6.497e4 Hz, the plate plots, and the bad-input contract for plate keys.
#
# Usage: bash test_plate_driver.sh <directory of rfmems-solid> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-solid"
SRC="$2"
CLAMPED="$SRC/cases/clamped_plate/case.yaml"
VIBRATION="$SRC/cases/plate_vibration/case.yaml"

source "$SRC/test/drivers/common.sh"

# ---- clamped square plate, a/h = 100: w = 1.269e-3 q a^4 / D, M_xx = 0.0229 q a^2 ----------
if "$DRIVER" "$CLAMPED" -o "$WORK/clamped.h5" --json --quiet >"$WORK/clamped.json" 2>"$WORK/err"; then
  pass "clamped plate run exits 0"
else
  fail "clamped plate run: $(cat "$WORK/err")"
fi
if $PY - "$WORK/clamped.json" "$WORK/clamped.h5" <<'PY'
import json, sys
import h5py, numpy as np
d = json.load(open(sys.argv[1]))
E, nu, h, a, q = 200e9, 0.3, 4e-6, 400e-6, -1e3
D = E * h**3 / (12 * (1 - nu**2))
w = d["probes"]["centre"]["w"]
w_ref = 1.269e-3 * q * a**4 / D
assert abs(w / w_ref - 1) < 0.01, (w, w_ref)
assert d["model"] == "plate" and d["solver"]["newton_iterations"] == 1, d
with h5py.File(sys.argv[2]) as f:
    c = f["mesh/cell_centroids"][()]
    m = f["fields/000000/moment"][()].reshape(-1, 3)
    near = np.linalg.norm(c[:, :2] - [a / 2, a / 2], axis=1) < a / 40
    mxx = m[near, 0].mean() / (q * a**2)
    assert near.sum() == 4 and 0.0229 * 0.98 < mxx < 0.0235 * 1.02, (near.sum(), mxx)
    for name in ("deflection", "rotation", "moment", "shear_force"):
        assert name in f["fields/000000"], name
print(f"w/w_ref = {w / w_ref:.5f}, M_xx/(q a^2) = {mxx:.5f}")
PY
then
  pass "clamped plate: centre deflection within 1 % of 1.269e-3 q a^4/D, M_xx within 2 % of 0.0229-0.0235"
else
  fail "clamped plate figures"
fi
if $PY "$SRC/python/plot_plate.py" "$WORK/clamped.h5" >/dev/null && [ -s "$WORK/clamped_moments.png" ]; then
  pass "plot_plate.py draws deflection and moment maps"
else
  fail "plot_plate.py"
fi

# ---- fixed-fixed strip vibration: f = 1.03 (h/L^2) sqrt(E/rho) = 6.497e4 Hz (within 0.5 %) --
if "$DRIVER" "$VIBRATION" -o "$WORK/vib.h5" --quiet 2>"$WORK/err" &&
   $PY "$SRC/python/probe_frequency.py" "$WORK/vib.h5" --probe centre --component w --json \
     >"$WORK/freq.json" &&
   $PY - "$WORK/freq.json" <<'PY'
import json, math, sys
r = json.load(open(sys.argv[1]))
f_ref = 1.03 * 2e-6 / 400e-6**2 * math.sqrt(200e9 / 7854)
assert r["periods"] >= 4 and abs(r["frequency_hz"] / f_ref - 1) < 0.005, (r, f_ref)
print(f"f = {r['frequency_hz']:.6g} Hz ({100 * (r['frequency_hz'] / f_ref - 1):+.3f} % vs 6.497e4)")
PY
then
  pass "plate vibration frequency within 0.5 % of the thesis's 6.497e4 Hz"
else
  fail "plate vibration: $(cat "$WORK/err")"
fi

# ---- bad plate input: exit 2, one line naming file and key, no result file (common.sh) ------
expect_input_error zero_thickness "model.thickness" "$CLAMPED" --set model.thickness=0
expect_input_error bad_plate_bc "boundaries.left.type" "$CLAMPED" --set boundaries.left.type=fixed
expect_input_error displacement_without_w "boundaries.left.w" "$CLAMPED" \
  --set boundaries.left.type=displacement
expect_input_error point_load_outside "point_loads" "$CLAMPED" \
  --set "point_loads=[{at: [1 m, 0 m], force: 1 uN}]"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
