#!/usr/bin/env bash
# rfmems-pullin's coupling section (coupling/coupling_settings.hpp) with pull_in.mode: transient
# on a coarse switch_plate (plate 20 x 2, parallel-plate, Reynolds film at 1 atm), a 180 V
# step from rest to 5 us (before touch-down near 6 us), solver.rtol 1e-5 (the sub-integrators'
# rtol of docs/coupling.md, "Coupling schemes on the same scene"). The centre deflection at 5 us from each scheme
# against the monolithic system at rtol 1e-6, with the accuracy measured there (40 x 4):
#   monolithic rtol 1e-5 and strongly coupled (H = 0.1 us): within 1e-4 (measured: 2.1e-5 at
#     rtol 1e-4, 4.1e-5 strongly coupled at H = 0.1 us, the sub-integrators' rtol floor);
#   staggered: first order in H (the lagged interface), error at H = 0.1 us in [2e-4, 2e-3]
#     (measured: 5.2e-4; below 2e-4 it would not be lagging, i.e. not partitioned) and the
#     observed order from H = 0.2 us in [0.7, 1.6] (measured: 1.24);
# the counters (one pass per macro step staggered, more strongly coupled), the history in the
# result file, and the bad-input contract of every coupling and pull_in.transient key.
#
# Usage: bash test_coupling_scheme.sh <directory of rfmems-pullin> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-pullin"
SRC="$2"
PLATE="$SRC/cases/switch_plate/case.yaml"
PLANE="$SRC/cases/switch_plane_laplace/case.yaml"

source "$SRC/test/drivers/common.sh"

COARSE=(--set "mesh.cells=[20, 2]" --set pull_in.mode=transient
        --set "pull_in.transient={voltage: 180 V, end_time: 5 us, output_interval: 0.1 us}")
run_scheme() {  # NAME RTOL SCHEME MACRO_STEP
  if "$DRIVER" "$PLATE" "${COARSE[@]}" --set "solver.rtol=$2" --set "coupling.scheme=$3" \
      --set "coupling.macro_step=$4" -o "$WORK/$1.h5" --json --quiet >"$WORK/$1.json" 2>"$WORK/err"; then
    pass "$1 ($3, rtol $2, H $4) exits 0"
  else
    fail "$1: $(cat "$WORK/err")"
  fi
}
run_scheme reference 1e-6 monolithic "0.1 us"
run_scheme monolithic 1e-5 monolithic "0.1 us"
run_scheme strong 1e-5 strongly_coupled "0.1 us"
run_scheme staggered 1e-5 staggered "0.1 us"
run_scheme staggered2 1e-5 staggered "0.2 us"

if $PY - "$WORK" <<'PY'
import json, math, sys
import h5py
work = sys.argv[1]
runs = {n: json.load(open(f"{work}/{n}.json")) for n in
        ("reference", "monolithic", "strong", "staggered", "staggered2")}
for n, d in runs.items():
    t = d["pull_in"]["transient"]
    assert not t["pulled_in"] and abs(t["final_time"] / 5e-6 - 1) < 1e-9, (n, t)
    assert t["residual_evals"] > 0 and t["steps"] > 0 and t["wall_time_s"] > 0, (n, t)
    # the history written is the one reported
    with h5py.File(f"{work}/{n}.h5") as f:
        time, values = f["dynamic/transient/time"][()], f["dynamic/transient/values"][()]
    assert abs(time[-1] - t["final_time"]) < 1e-15 and values[-1, 0] == t["final_control"], n
scheme = {n: d["pull_in"]["coupling"]["scheme"] for n, d in runs.items()}
assert scheme == {"reference": "monolithic", "monolithic": "monolithic", "strong": "strongly_coupled",
                  "staggered": "staggered", "staggered2": "staggered"}, scheme
w = {n: d["pull_in"]["transient"]["final_control"] for n, d in runs.items()}
# the deflection is physical: the 180 V step at 5 us has closed 55-70 % of the 3.75 um gap
assert -0.7 * 3.75e-6 < w["reference"] < -0.55 * 3.75e-6, w
err = {n: abs(w[n] / w["reference"] - 1) for n in w}
assert err["monolithic"] < 1e-4 and err["strong"] < 1e-4, err
assert 2e-4 < err["staggered"] < 2e-3, err
order = math.log(err["staggered2"] / err["staggered"]) / math.log(2)
assert 0.7 < order < 1.6, (order, err)
assert err["staggered"] > 10 * err["strong"], err
c = {n: {**runs[n]["pull_in"]["coupling"], **runs[n]["pull_in"]["counters"]}
     for n in ("strong", "staggered", "staggered2")}
assert c["staggered"]["macro_steps"] == 50 and c["staggered"]["coupling_iterations"] == 50, c
assert c["staggered2"]["macro_steps"] == 25 and c["staggered2"]["coupling_iterations"] == 25, c
s = c["strong"]
assert s["macro_steps"] == 50 and 50 < s["coupling_iterations"] <= 50 * s["max_iterations"], s
print(f"w(5 us) = {1e6 * w['reference']:.6f} um; errors: monolithic rtol 1e-5 {err['monolithic']:.1e}, "
      f"strongly coupled {err['strong']:.1e} ({s['coupling_iterations']} passes), staggered "
      f"{err['staggered']:.1e} (H 0.1 us) / {err['staggered2']:.1e} (0.2 us), order {order:.2f}; "
      "residual evals " + ", ".join(f"{n} {runs[n]['pull_in']['transient']['residual_evals']}" for n in runs))
PY
then
  pass "the three schemes agree at 5 us within the measured accuracy for their step"
else
  fail "coupling-scheme figures"
fi

# To touch-down (contact at 2 % of the gap, near 6 us): on this coarse plate the partitioned
# schemes reach it (on the case's 40 x 4 plate they do not finish, docs/coupling.md,
# "Coupling schemes on the same scene"). Their lag shifts the pull-in time by O(H): measured 3.5e-4 (strongly coupled,
# the tolerance floor near contact) and 1.5e-3 (staggered, H = 0.1 us = 1.7 % of t_PI);
# bounds 1e-3 and 5e-3, the monolithic rtol 1e-5 one 1e-4 (measured 4.4e-6).
for n in "reference 1e-6 monolithic" "monolithic 1e-5 monolithic" "strong 1e-5 strongly_coupled" \
         "staggered 1e-5 staggered"; do
  set -- $n
  "$DRIVER" "$PLATE" "${COARSE[@]}" --set "pull_in.transient.end_time=8 us" --set "solver.rtol=$2" \
    --set "coupling.scheme=$3" -o "$WORK/touch_$1.h5" --json --quiet >"$WORK/touch_$1.json" 2>"$WORK/err" ||
    fail "touch-down $1: $(cat "$WORK/err")"
done
if $PY - "$WORK" <<'PY'
import json, sys
work = sys.argv[1]
t = {}
for n in ("reference", "monolithic", "strong", "staggered"):
    r = json.load(open(f"{work}/touch_{n}.json"))["pull_in"]["transient"]
    assert r["pulled_in"] and 5e-6 < r["pull_in_time"] < 7e-6, (n, r)
    t[n] = r["pull_in_time"]
e = {n: abs(t[n] / t["reference"] - 1) for n in t}
assert e["monolithic"] < 1e-4 and e["strong"] < 1e-3 and e["staggered"] < 5e-3, e
print(f"t_PI = {1e6 * t['reference']:.4f} us; errors: monolithic rtol 1e-5 {e['monolithic']:.1e}, "
      f"strongly coupled {e['strong']:.1e}, staggered {e['staggered']:.1e}")
PY
then
  pass "the three schemes touch down at the same time within O(H)"
else
  fail "touch-down times"
fi

# Plain-text output names the scheme.
if "$DRIVER" "$PLATE" "${COARSE[@]}" --set coupling.scheme=staggered -o "$WORK/text.h5" \
    2>"$WORK/err" | grep -q "step (staggered).*coupling passes over 50 macro steps"; then
  pass "text output names the scheme and its passes"
else
  fail "text output: $(cat "$WORK/err")"
fi

# Bad input: exit 2, one line naming the file, the key and the value.
T=("${COARSE[@]}")
expect_input_error scheme_unknown "coupling.scheme' = 'implicit'" "$PLATE" "${T[@]}" --set coupling.scheme=implicit
expect_input_error key_unknown "unknown key 'coupling.relax'" "$PLATE" "${T[@]}" --set coupling.relax=0.5
expect_input_error iterations_type "coupling.max_iterations' = 'many'" "$PLATE" "${T[@]}" --set coupling.max_iterations=many
expect_input_error iterations_zero "coupling.max_iterations' = 0" "$PLATE" "${T[@]}" --set coupling.max_iterations=0
expect_input_error step_unit "coupling.macro_step' = '0.1 V'" "$PLATE" "${T[@]}" --set "coupling.macro_step=0.1 V"
expect_input_error step_zero "coupling.macro_step' = '0 us'" "$PLATE" "${T[@]}" --set "coupling.macro_step=0 us"
expect_input_error step_negative "coupling.macro_step' = '-1 us'" "$PLATE" "${T[@]}" --set "coupling.macro_step=-1 us"
expect_input_error tolerance_zero "coupling.tolerance' = 0" "$PLATE" "${T[@]}" --set coupling.tolerance=0
expect_input_error tolerance_above_one "coupling.tolerance' = 2" "$PLATE" "${T[@]}" --set coupling.tolerance=2
expect_input_error step_missing "coupling.macro_step': a partitioned scheme needs" "$PLATE" "${T[@]}" --set "coupling={scheme: strongly_coupled}"
expect_input_error no_gas "coupling.scheme' = 'staggered': not with .*gas.model: none, pull_in.mode: transient; allowed: monolithic" "$PLATE" "${T[@]}" --set coupling.scheme=staggered --set gas.model=none
expect_input_error laplace "coupling.macro_step' = '0.1 us': only for the parallel_plate field's partitioned schemes" "$PLANE" --set "coupling={scheme: staggered, macro_step: 0.1 us}"
expect_input_error partitioned_dynamic "coupling.scheme' = 'strongly_coupled': not with .*pull_in.mode: dynamic; allowed: monolithic" "$PLATE" --set coupling.scheme=strongly_coupled
expect_input_error transient_voltage "pull_in.transient.voltage' = '0 V'" "$PLATE" "${T[@]}" --set "pull_in.transient.voltage=0 V"
expect_input_error transient_end "pull_in.transient.end_time' = '-1 us'" "$PLATE" "${T[@]}" --set "pull_in.transient.end_time=-1 us"
expect_input_error transient_missing "pull_in.transient" "$PLATE" --set mesh.cells=[20,2] --set pull_in.mode=transient --set "pull_in.transient={end_time: 5 us}"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
