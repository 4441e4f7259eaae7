#!/usr/bin/env bash
# rfmems-pullin on the immersed-boundary cantilever switch (cases/cantilever_switch),
# on a coarse mesh (46 x 4 beam, 101 x 31 background): a static solve at 50 V exits 0, writes
# its file and a tip deflection within 10 % of the 185 x 11 scene's (-46.3 nm); the quasi-static
# pull-in within 8 % of the distributed closed form (132.5 V); a short transient with the
# Reynolds film inside the strong iteration (coupling.strong_gas); a transient that pulls in
# prints its pull-in time; the dynamic bisection with its early ends and the pull-in time's
# check; and the bad-input contract of the immersed keys (one line naming file, key and value;
# exit 2; no result file).
#
# Usage: bash test_immersed_switch_driver.sh <directory of rfmems-pullin> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-pullin"
SRC="$2"
CASE="$SRC/cases/cantilever_switch/case.yaml"
COARSE=(--set "mesh.cells=[46, 4]" --set "actuation.immersed.background.cells=[101, 31]")

source "$SRC/test/drivers/common.sh"

if "$DRIVER" "$CASE" "${COARSE[@]}" --set pull_in.mode=static -o "$WORK/static.h5" --json \
    --quiet >"$WORK/static.json" 2>"$WORK/err" && [ -s "$WORK/static.h5" ]; then
  pass "static 50 V exits 0 and writes its file"
else
  fail "static: $(cat "$WORK/err")"
fi
if "$DRIVER" "$CASE" "${COARSE[@]}" --set pull_in.mode=quasi_static \
    --set pull_in.quasi_static.points=10 -o "$WORK/qs.h5" --json --quiet >"$WORK/qs.json" \
    2>"$WORK/err"; then
  pass "quasi-static exits 0"
else
  fail "quasi-static: $(cat "$WORK/err")"
fi
if $PY - "$WORK/static.json" "$WORK/qs.json" <<'PY'
import json, sys
st = json.load(open(sys.argv[1]))["pull_in"]["static"]
qs = json.load(open(sys.argv[2]))["pull_in"]["quasi_static"]
assert abs(st["control"] / -46.3e-9 - 1) < 0.10, st
assert abs(qs["pull_in_voltage"] / 132.5 - 1) < 0.08, qs
PY
then pass "static deflection and quasi-static V_PI near their references"
else fail "static / quasi-static figures"
fi

# The gas inside the strong iteration (coupling.strong_gas, Reynolds film, 0.2 us at 125 V):
# every step ends with the summed interface residual below the tolerance.
if "$DRIVER" "$CASE" "${COARSE[@]}" --set pull_in.mode=transient \
    --set pull_in.transient.voltage=125V --set pull_in.transient.end_time=0.2us \
    --set gas.model=reynolds --set coupling.scheme=strongly_coupled --set coupling.strong_gas=true \
    -o "$WORK/strong_gas.h5" --json --quiet >"$WORK/strong_gas.json" 2>"$WORK/err" &&
  $PY - "$WORK/strong_gas.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))["pull_in"]
cpu = p["counters"]
assert p["coupling"]["strong_gas"] is True and p["gas"] == "reynolds", p
assert cpu["unconverged_coupling_steps"] == 0, cpu
assert 0 < cpu["max_coupling_residual"] <= 1e-6, cpu
assert cpu["gas_steps"] == cpu["coupling_iterations"] > cpu["structure_steps"], cpu
PY
then
  pass "strong_gas: the gas in every iterate, every step converged"
else
  fail "strong_gas run: $(cat "$WORK/err")"
fi

# The dynamic bisection (no gas, to 2 V) with its early ends armed by the quasi-static curve:
# runs past the unstable equilibrium end early, and V_dyn and the pull-in time are those of the
# code without the rules (122.5 V, docs/immersed_switch.md, "Grid damping"; t_PI 2.157482 us since the contact root watches
# the surface's vertices, docs/immersed_switch.md, "The tip and the contact gap": 2.172058 us at the cells' centroids), with the
# histories and the small-signal response of every scene's dynamic study.
if "$DRIVER" "$CASE" "${COARSE[@]}" --set pull_in.dynamic.tolerance=2V -o "$WORK/dyn.h5" \
    --json --quiet >"$WORK/dyn.json" 2>"$WORK/err" &&
  $PY - "$WORK/dyn.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))["pull_in"]
d = p["dynamic"]
assert d["pull_in_voltage"] == 122.5 and d["not_pulling_in"] == 121.25, d
assert abs(d["pull_in_time"] / 2.157482e-6 - 1) < 1e-4, d
assert d["past_fold_runs"] >= 1, d
assert abs(p["quasi_static"]["pull_in_voltage"] / 132.5 - 1) < 0.08, p
# The pull-in time's check (the upper end at 0.1 x the tolerances): 2.157883 us, 1.9e-4 away.
# One study for every scene: the histories at 0.97 and 1.03 V_dyn fall either side of it, and
# the small-signal step rings at the beam's first bending frequency (Euler-Bernoulli, 566.9 kHz
# here; measured 565.5 kHz at 0.3 V_qs), undamped but for the grid damping (no gas).
h = d["histories"]
assert [x["pulled_in"] for x in h] == [False, True], h
s = d["small_signal"]
assert abs(s["frequency"] * p["immersed"]["first_bending_period"] - 1) < 0.03, s
assert s["damping_ratio"] < 1e-3, s
c = d["pull_in_time_check"]
assert c["pulled_in"] and c["tolerance_factor"] == 0.1 and c["relative_error_estimate"] < 1e-3, c
PY
then
  pass "dynamic bisection: early ends past the unstable equilibrium, V_dyn and t_PI unchanged, t_PI checked"
else
  fail "dynamic bisection: $(cat "$WORK/err")"
fi
# A transient that pulls in prints its pull-in time (it has no damping ratio to print), and its
# JSON says so: 125 V on the coarse scene touches down at ~1.37 us, before the 3 us end.
if "$DRIVER" "$CASE" "${COARSE[@]}" --set pull_in.mode=transient \
    --set pull_in.transient.voltage=125V --set pull_in.transient.end_time=3us \
    -o "$WORK/closing.h5" >"$WORK/closing.txt" 2>"$WORK/err" &&
  grep -Eq "125.00 V step \(staggered\), .*, pull-in time 1\.3[0-9]+ us; " "$WORK/closing.txt"; then
  pass "a transient that pulls in prints its pull-in time"
else
  fail "closing transient: $(cat "$WORK/closing.txt" "$WORK/err")"
fi
# The ESBGK gas stepped by IDA (COMET's arrowhead preconditioner) instead of the sweeps: the
# same tip deflection to 1e-3 after 31 coupled steps (measured 1.6e-5), by a different solve
# (not the same bits). Coarse background, 6^3 velocities; ~13 s.
ESBGK=("$CASE" --set pull_in.mode=transient --set "actuation.immersed.background.cells=[50, 18]"
       --set "mesh.cells=[46, 4]" --set pull_in.transient.end_time=0.02us --set gas.model=esbgk
       --set gas.velocities=6 --json --quiet)
if "$DRIVER" "${ESBGK[@]}" -o "$WORK/sweeps.h5" >"$WORK/sweeps.json" 2>"$WORK/err" &&
   "$DRIVER" "${ESBGK[@]}" --set gas.stepper=ida -o "$WORK/ida.h5" >"$WORK/ida.json" 2>"$WORK/err" &&
   $PY - "$WORK/sweeps.json" "$WORK/ida.json" <<'PY'
import json, sys
a, b = (json.load(open(p))["pull_in"]["transient"] for p in sys.argv[1:3])
wa, wb = a["final_control"], b["final_control"]
rel = abs(wb - wa) / abs(wa)
print(f"tip {wa:.6e} (sweeps) / {wb:.6e} m (IDA): {rel:.1e} apart, {a['steps']} / {b['steps']} steps")
assert 0 < rel <= 1e-3 and a["steps"] == b["steps"], (wa, wb)
PY
then
  pass "ESBGK gas by IDA with the arrowhead preconditioner = the sweeps to 1e-3"
else
  fail "ESBGK IDA stepper: $(cat "$WORK/err")"
fi

expect_input_error bad_margin "past_fold_margin" "$CASE" --set pull_in.dynamic.past_fold_margin=2
expect_input_error bad_time_check "time_check" "$CASE" --set pull_in.dynamic.time_check=-0.1

expect_input_error bad_cells "cells" "$CASE" --set "actuation.immersed.background.cells=[2, 50]"
expect_input_error bad_electrode "x" "$CASE" --set "actuation.electrode.x=[50 um, 40 um]"
expect_input_error bad_anchor "anchor_patch" "$CASE" --set actuation.immersed.anchor_patch=wall
expect_input_error bad_gas "model" "$CASE" --set gas.model=dsmc
expect_input_error bad_stepper "gas.stepper" "$CASE" --set gas.stepper=rk4
expect_input_error coarse_velocity_grid "no discrete equilibrium" "$CASE" --set gas.model=esbgk \
  --set gas.velocities=4
# The gas keys mean the same for every model: the pressure is the case's, required with a gas.
expect_input_error gas_without_pressure "gas.pressure" "$CASE" --set "gas={model: reynolds}"
expect_input_error bad_scheme "scheme" "$CASE" --set coupling.scheme=monolithic
expect_input_error bad_bracket "bracket" "$CASE" --set "pull_in.dynamic.bracket=[140 V, 100 V]"
expect_input_error bad_contact "contact_gap" "$CASE" --set pull_in.contact_gap=2um
expect_input_error outside "background" "$CASE" --set "actuation.immersed.background.upper=[40 um, 10 um]"
expect_input_error strong_gas_value "strong_gas" "$CASE" --set coupling.strong_gas=maybe
expect_input_error strong_gas_staggered "strong_gas" "$CASE" --set coupling.strong_gas=true
expect_input_error strong_gas_every "gas_every' = 2: the strongly coupled iteration" "$CASE" \
  --set "gas={model: reynolds, pressure: 1 atm}" --set coupling.scheme=strongly_coupled \
  --set coupling.strong_gas=true --set coupling.gas_every=2
expect_input_error gas_every_without_gas "gas_every' = 2: only with a gas" "$CASE" \
  --set coupling.gas_every=2
expect_input_error bad_fixed_step "fixed_step" "$CASE" --set solver.fixed_step=-1ns
expect_input_error typo "actuation.immersed.electrodes" "$CASE" \
  --set "actuation.immersed.electrodes={x: [0, 1]}"
# The keys this vocabulary renamed name their new place.
expect_input_error old_block "key 'immersed'.*actuation.immersed" "$CASE" \
  --set "immersed={anchor_patch: left}"
expect_input_error old_strong "strongly_coupled" "$CASE" --set coupling.scheme=strong
expect_input_error old_contact_gap "pull_in.contact_gap" "$CASE" \
  --set pull_in.dynamic.contact_gap=0.3um

exit $((failures > 0))
