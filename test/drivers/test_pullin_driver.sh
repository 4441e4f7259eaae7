#!/usr/bin/env bash
# rfmems-pullin end to end: the default switch case (plate, parallel-plate law, Reynolds gas)
# at 1 atm and 1 kPa: quasi-static V_PI near the thesis's 187 V, dynamic V_PI below it, higher
# with more gas (damping), pull-in slower at 1 atm at the same voltage, the pull-in time's
# error estimate against a converged run; the Laplace plane case near the thesis's 181 V; the
# plots; the modes under DC bias along the quasi-static curve; and the bad-input contract for
# actuation and gas keys.
#
# Usage: bash test_pullin_driver.sh <directory of rfmems-pullin> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-pullin"
SRC="$2"
PLATE="$SRC/cases/switch_plate/case.yaml"
PLANE="$SRC/cases/switch_plane_laplace/case.yaml"

source "$SRC/test/drivers/common.sh"

for p in atm kPa; do
  pressure=$([ $p = atm ] && echo "1 atm" || echo "1 kPa")
  expect_json_run "$p" "switch_plate at $pressure" "$PLATE" --set "gas.pressure=$pressure" \
    --set "pull_in.dynamic.voltages=[178 V]"
done
if $PY - "$WORK/atm.json" "$WORK/kPa.json" <<'PY'
import json, sys
atm, kpa = (json.load(open(f))["pull_in"] for f in sys.argv[1:3])
for d in (atm, kpa):
    assert abs(d["quasi_static"]["pull_in_voltage"] / 187 - 1) < 0.04, d["quasi_static"]
    assert 0.85 < d["dynamic"]["ratio_to_quasi_static"] < 1.0, d["dynamic"]
    assert d["dynamic"]["pull_in_voltage"] - d["dynamic"]["not_pulling_in"] <= 0.5
# 1 kPa: the film hardly damps (Kn ~ 2), the ratio is the vacuum one (thesis 171/187).
assert abs(kpa["dynamic"]["ratio_to_quasi_static"] - 0.91) < 0.02, kpa["dynamic"]
# More gas, more damping: the dynamic pull-in voltage rises and pull-in at 178 V is slower.
assert atm["dynamic"]["pull_in_voltage"] > kpa["dynamic"]["pull_in_voltage"]
t_atm, t_kpa = (d["dynamic"]["histories"][0] for d in (atm, kpa))
assert t_atm["pulled_in"] and t_kpa["pulled_in"] and t_atm["pull_in_time"] > t_kpa["pull_in_time"], (t_atm, t_kpa)
# The pull-in time's check (the upper end again at 0.1 x the tolerances) estimates the reported
# time's error: at 1 atm the bisection ends at 173.9056 V, where t_PI converges to 11.82760 us
# (pull_in.mode=transient at that voltage, rtol 1e-6 and 1e-7 agree to 5e-8; docs/pull-in.md,
# "The pull-in time and its check") and the default rtol 1e-3 is 0.8 % off; the estimate must
# say so within a factor 2, and the
# check be closer to the converged time than a quarter of the estimate.
c = atm["dynamic"]["pull_in_time_check"]
assert c["pulled_in"] and c["tolerance_factor"] == 0.1, c
assert abs(atm["dynamic"]["pull_in_voltage"] - 173.9056) < 1e-3, atm["dynamic"]
t_ref = 11.82760e-6
error = abs(atm["dynamic"]["pull_in_time"] - t_ref) / t_ref
assert 0.5 < error / c["relative_error_estimate"] < 2, (error, c)
assert abs(c["pull_in_time"] - t_ref) / t_ref < 0.25 * c["relative_error_estimate"], (error, c)
assert kpa["dynamic"]["pull_in_time_check"]["relative_error_estimate"] < 0.01, kpa["dynamic"]
# Small-signal damping ratio: a 40 um wide strip in air at 1 atm, zeta = mu_eff b^2 /
# (2 rho h g^3 omega) = 0.0101 (incompressible film, Veijola mu_eff at Kn = 0.018), measured
# ~0.012 on 4 cells across (the open-edge half-cell error 2 (dy/b)^2 = 12.5 %, and the gap
# closed a little by the 0.3 V_PI step); at 1 kPa Kn = 1.8 and mu_eff drops 19-fold.
z_atm, z_kpa = (d["dynamic"]["small_signal"]["damping_ratio"] for d in (atm, kpa))
assert 0.009 < z_atm < 0.015 and z_atm > 8 * z_kpa, (z_atm, z_kpa)
print(f"V_dyn 1 atm {atm['dynamic']['pull_in_voltage']:.2f} V, 1 kPa {kpa['dynamic']['pull_in_voltage']:.2f} V; "
      f"t_PI(178 V) {1e6 * t_atm['pull_in_time']:.3f} / {1e6 * t_kpa['pull_in_time']:.3f} us; "
      f"zeta {z_atm:.4f} / {z_kpa:.5f}; t_PI(V_dyn, 1 atm) error {error:.2e}, "
      f"estimated {c['relative_error_estimate']:.2e}")
PY
then
  pass "pull-in voltages, times and damping ratios at 1 atm and 1 kPa"
else
  fail "pull-in figures"
fi
if $PY "$SRC/python/plot_pullin.py" "$WORK/atm.h5" >/dev/null && [ -s "$WORK/atm_curve.png" ] &&
   [ -s "$WORK/atm_dynamic.png" ] && [ -s "$WORK/atm_forces.png" ]; then
  pass "plot_pullin.py draws the curve, the histories and the forces"
else
  fail "plot_pullin.py"
fi

if "$DRIVER" "$PLANE" -o "$WORK/plane.h5" --json --quiet >"$WORK/plane.json" 2>"$WORK/err" &&
   $PY -c '
import json, sys
d = json.load(open(sys.argv[1]))["pull_in"]
v = d["quasi_static"]["pull_in_voltage"]
assert d["electrostatics"] == "laplace" and abs(v / 181 - 1) < 0.04, d
' "$WORK/plane.json"; then
  pass "plane beam + Laplace: quasi-static V_PI within 4 % of 181 V"
else
  fail "plane + Laplace: $(cat "$WORK/err") $(cat "$WORK/plane.json")"
fi

# A slow ramp (60 us, ~8 periods) pulls in at nearly the quasi-static voltage: the dynamic
# overshoot of a step is what lowers the dynamic pull-in voltage.
if "$DRIVER" "$PLATE" --set gas.model=none --set "pull_in.dynamic.waveform={type: ramp, rise_time: 60 us}" \
    --set "pull_in.dynamic.end_time=80 us" --set "pull_in.dynamic.bracket=[170 V, 200 V]" \
    --set pull_in.dynamic.small_signal=0 --set "pull_in.dynamic.voltages=[185 V]" \
    -o "$WORK/ramp.h5" --json --quiet >"$WORK/ramp.json" 2>"$WORK/err" &&
   $PY -c '
import json, sys
d = json.load(open(sys.argv[1]))["pull_in"]["dynamic"]
assert d["waveform"] == "ramp" and 0.98 < d["ratio_to_quasi_static"] < 1.0, d
' "$WORK/ramp.json"; then
  pass "a slow voltage ramp pulls in within 2 % below the quasi-static voltage"
else
  fail "ramp: $(cat "$WORK/err") $(cat "$WORK/ramp.json")"
fi

# A slender plate (L/h = 1000, V_qs 5.87 V on 20 x 2 cells): the bisection's default tolerance is
# 0.3 % of V_qs (a fixed 0.5 V, 8.5 % of it, let V_dyn come out at 1.02 V_qs), a tolerance above
# 1 % of V_qs is warned of, and every run of the study prints a progress line on stderr.
THIN=(--set "mesh.cells=[20, 2]" --set "model.thickness=0.4 um" --set gas.model=none
      --set "pull_in.dynamic={end_time: 400 us, voltages: [], small_signal: 0, time_check: 0}")
if "$DRIVER" "$PLATE" "${THIN[@]}" -o "$WORK/thin.h5" --json >"$WORK/thin.json" 2>"$WORK/thin.err" &&
   "$DRIVER" "$PLATE" "${THIN[@]}" --set "pull_in.dynamic.tolerance=0.5 V" -o "$WORK/thin05.h5" \
     --json >"$WORK/thin05.json" 2>"$WORK/thin05.err" &&
   $PY - "$WORK/thin.json" "$WORK/thin05.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
qs, d = p["pull_in"]["quasi_static"]["pull_in_voltage"], p["pull_in"]["dynamic"]
assert abs(d["tolerance"] / (3e-3 * qs) - 1) < 1e-12, d
assert d["pull_in_voltage"] - d["not_pulling_in"] <= d["tolerance"], d
assert 0.88 < d["ratio_to_quasi_static"] < 0.95, d
assert not p["validity"]["warnings"], p["validity"]
w = json.load(open(sys.argv[2]))["validity"]["warnings"]
assert any(x.startswith("pull_in.dynamic.tolerance 0.5 V is 8.5 %") for x in w), w
PY
then
  if [ "$(grep -c '^rfmems-pullin: dynamic: bisection run at ' "$WORK/thin.err")" -ge 5 ] &&
     grep -q "^rfmems-pullin: quasi-static: fold at " "$WORK/thin.err" &&
     grep -q "^rfmems-pullin: warning: pull_in.dynamic.tolerance 0.5 V" "$WORK/thin05.err"; then
    pass "slender plate: relative bisection tolerance, the coarse one warned of, progress lines"
  else
    fail "slender plate's progress lines: $(head -3 "$WORK/thin.err")"
  fi
else
  fail "slender plate: $(cat "$WORK/thin.err" "$WORK/thin05.err" | tail -3)"
fi

# ---- the modes under DC bias along the quasi-static curve ---------------------------------
# The first frequency at rest is the structure's own (130.9 kHz, docs/modal.md); it falls
# monotonically along the stable branch and follows the 1-DOF parallel-plate law
# (f/f0)^2 = 1 - (8/27) v^2/x^3, x^2 (1 - x) = (4/27) v^2, to 2 % up to 0.95 V_PI; the result
# file's /pull_in/modes holds the same numbers.
expect_json_run bias "quasi-static with modes" "$PLATE" --set pull_in.mode=quasi_static \
  --set pull_in.quasi_static.modes=2 --set gas.model=none
if $PY - "$WORK/bias.json" "$WORK/bias.h5" <<'PY'; then
import json, sys
import h5py
q = json.load(open(sys.argv[1]))["pull_in"]["quasi_static"]
modes, v_pi = q["modes"], q["pull_in_voltage"]
assert modes[0]["voltage"] == 0 and modes[0]["control"] == 0, modes[0]
f0 = modes[0]["frequencies"][0]
assert abs(f0 / 130898.9 - 1) < 1e-5, f0
f1 = [m["frequencies"][0] for m in modes]
assert all(b < a for a, b in zip(f1, f1[1:]) if b > 0), f1
def lumped(v):
    lo, hi = 2 / 3, 1.0
    for _ in range(200):
        x = (lo + hi) / 2
        lo, hi = (x, hi) if x * x * (1 - x) > 4 / 27 * v * v else (lo, x)
    return (max(0.0, 1 - 8 / 27 * v * v / x**3)) ** 0.5
checked = [m for m in modes if 0 < m["voltage"] <= 0.95 * v_pi]
assert len(checked) >= 5, len(checked)
for m in checked:
    ratio = m["frequencies"][0] / f0
    assert abs(ratio - lumped(m["voltage"] / v_pi)) < 0.02, (m["voltage"], ratio)
h = h5py.File(sys.argv[2], "r")["pull_in/modes"]
assert h["values"].shape == (len(modes), 3), h["values"].shape
assert abs(h["values"][-1][1] - modes[-1]["frequencies"][0]) <= 1e-9 * f0
PY
  pass "modes under bias: f0 130.9 kHz, falling, the 1-DOF law within 2 % to 0.95 V_PI"
else
  fail "modes under bias"
fi
expect_input_error bias_modes_laplace "pull_in.quasi_static.modes" "$PLANE" \
  --set pull_in.mode=quasi_static --set pull_in.quasi_static.modes=2

expect_input_error negative_gap "actuation.gap" "$PLATE" --set "actuation.gap=-1 um"
expect_input_error laplace_plate "actuation.electrostatics" "$PLATE" --set actuation.electrostatics=laplace
expect_input_error electrode_off "actuation.electrode" "$PLATE" --set "actuation.electrode={x: [500 um, 600 um]}"
expect_input_error gas_plane "gas.model" "$PLANE" --set "gas={model: reynolds, pressure: 1 atm}"
expect_input_error bad_mode "pull_in.mode" "$PLATE" --set pull_in.mode=static
expect_input_error jacobian_refresh_above_one "solver.jacobian_refresh" "$PLATE" --set solver.jacobian_refresh=1.5
expect_input_error time_check_one "pull_in.dynamic.time_check" "$PLATE" --set pull_in.dynamic.time_check=1
expect_input_error ramp_without_rise "rise_time" "$PLATE" --set "pull_in.dynamic.waveform={type: ramp}"
# Contact and release keys (actuation.contact, pull_in.release): validated before any solve.
CONTACT="actuation.contact={gap: 75 nm}"
expect_input_error release_without_contact "pull_in.release" "$PLATE" --set "pull_in.release={hold_voltage: 10 V}"
expect_input_error contact_laplace "actuation.contact" "$PLANE" --set "$CONTACT"
expect_input_error contact_gap_too_large "actuation.contact.gap" "$PLATE" --set "actuation.contact={gap: 4 um}"
expect_input_error penetration_too_large "actuation.contact.penetration" "$PLATE" --set "actuation.contact={gap: 75 nm, penetration: 20 nm}"
expect_input_error contact_gap_twice "pull_in.contact_gap.*actuation.contact.gap" "$PLATE" --set "$CONTACT" --set "pull_in.contact_gap=0.1 um"
expect_input_error release_missing_hold "pull_in.release.hold_voltage" "$PLATE" --set "$CONTACT" --set "pull_in.release={delay: 1 us}"
expect_input_error release_unit "pull_in.release.hold_voltage" "$PLATE" --set "$CONTACT" --set "pull_in.release={hold_voltage: 10 us}"
expect_input_error release_unknown_key "pull_in.release.hold" "$PLATE" --set "$CONTACT" --set "pull_in.release={hold_voltage: 10 V, hold: 3}"
expect_input_error release_delay_and_time "pull_in.release.time" "$PLATE" --set "$CONTACT" --set "pull_in.release={hold_voltage: 10 V, delay: 1 us, time: 20 us}"
expect_input_error release_hold_above "pull_in.release.hold_voltage" "$PLATE" --set "$CONTACT" --set "pull_in.release={hold_voltage: 200 V, voltage: 180 V}"
expect_input_error control_outside "actuation.control" "$PLATE" --set "actuation.control=[1 m, 0 m]"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
