#!/usr/bin/env bash
# rfmems-pullin's coupling section (coupling/coupling_settings.hpp) with pull_in.mode: transient
# on a coarse switch_plate (plate 20 x 2, parallel-plate, Reynolds film at 1 atm), a 180 V
# step from rest to 5 us (before touch-down near 6 us), solver.rtol 1e-5. The partitioned
# schemes split the film from the plate in the field-coupled structure's loop. The centre
# deflection at 5 us from each scheme against the monolithic system at rtol 1e-6:
#   monolithic rtol 1e-5 and strongly coupled: within 1e-5 (measured 9.0e-7 and 1.4e-7);
#   staggered: the film's force lagged by one accepted step, error in [1e-5, 5e-4] (measured
#     5.2e-5; its first order in a fixed step is test/study/test_coupling_schemes.cpp's), and
#     larger when the film is advanced every 2nd and every 4th step (7.7e-5, 1.3e-4);
# the counters (one film step per plate step staggered, per iterate strongly coupled), the
# history in the result file, and the bad-input contract of every coupling and
# pull_in.transient key.
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
run_scheme() {  # NAME RTOL SCHEME [GAS_EVERY]
  if "$DRIVER" "$PLATE" "${COARSE[@]}" --set "solver.rtol=$2" --set "coupling.scheme=$3" \
      ${4:+--set "coupling.gas_every=$4"} -o "$WORK/$1.h5" --json --quiet >"$WORK/$1.json" \
      2>"$WORK/err"; then
    pass "$1 ($3, rtol $2${4:+, gas_every $4}) exits 0"
  else
    fail "$1: $(cat "$WORK/err")"
  fi
}
run_scheme reference 1e-6 monolithic
run_scheme monolithic 1e-5 monolithic
run_scheme strong 1e-5 strongly_coupled
run_scheme staggered 1e-5 staggered
run_scheme staggered2 1e-5 staggered 2
run_scheme staggered4 1e-5 staggered 4

if $PY - "$WORK" <<'PY'
import json, math, sys
import h5py
work = sys.argv[1]
runs = {n: json.load(open(f"{work}/{n}.json")) for n in
        ("reference", "monolithic", "strong", "staggered", "staggered2", "staggered4")}
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
                  "staggered": "staggered", "staggered2": "staggered", "staggered4": "staggered"}, scheme
w = {n: d["pull_in"]["transient"]["final_control"] for n, d in runs.items()}
# the deflection is physical: the 180 V step at 5 us has closed 55-70 % of the 3.75 um gap
assert -0.7 * 3.75e-6 < w["reference"] < -0.55 * 3.75e-6, w
err = {n: abs(w[n] / w["reference"] - 1) for n in w}
assert err["monolithic"] < 1e-5 and err["strong"] < 1e-5, err
assert 1e-5 < err["staggered"] < 5e-4, err
assert err["staggered"] < err["staggered2"] < err["staggered4"], err
assert err["staggered"] > 10 * err["strong"], err
c = {n: {**runs[n]["pull_in"]["coupling"], **runs[n]["pull_in"]["counters"]}
     for n in ("strong", "staggered", "staggered2", "staggered4")}
for n, k in (("staggered", 1), ("staggered2", 2), ("staggered4", 4)):
    steps = c[n]["structure_steps"]
    assert c[n]["gas_every"] == k and c[n]["gas_steps"] == (steps + k - 1) // k, c[n]
    assert c[n]["coupling_iterations"] == 0, c[n]
s = c["strong"]
assert s["structure_steps"] < s["coupling_iterations"] <= s["structure_steps"] * s["max_iterations"], s
assert s["gas_steps"] == s["coupling_iterations"], s  # the film redone in every iterate
assert s["unconverged_coupling_steps"] == 0 and s["max_coupling_residual"] <= s["tolerance"], s
print(f"w(5 us) = {1e6 * w['reference']:.6f} um; errors: monolithic rtol 1e-5 {err['monolithic']:.1e}, "
      f"strongly coupled {err['strong']:.1e} ({s['coupling_iterations']} iterations over "
      f"{s['structure_steps']} steps), staggered {err['staggered']:.1e} (gas_every 2: "
      f"{err['staggered2']:.1e}, 4: {err['staggered4']:.1e}); residual evals "
      + ", ".join(f"{n} {runs[n]['pull_in']['transient']['residual_evals']}" for n in runs))
PY
then
  pass "the three schemes agree at 5 us within the measured accuracy for their step"
else
  fail "coupling-scheme figures"
fi

# To touch-down (contact at 2 % of the gap, near 6 us). The pull-in time against the monolithic
# system at rtol 1e-6: measured 3.8e-6 (monolithic rtol 1e-5), 4.8e-6 (strongly coupled) and
# 9.5e-5 (staggered, the lag); bounds 5e-5, 5e-5 and 1e-3.
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
assert e["monolithic"] < 5e-5 and e["strong"] < 5e-5 and e["staggered"] < 1e-3, e
print(f"t_PI = {1e6 * t['reference']:.4f} us; errors: monolithic rtol 1e-5 {e['monolithic']:.1e}, "
      f"strongly coupled {e['strong']:.1e}, staggered {e['staggered']:.1e}")
PY
then
  pass "the three schemes touch down at the same time"
else
  fail "touch-down times"
fi

# Plain-text output names the scheme.
if "$DRIVER" "$PLATE" "${COARSE[@]}" --set coupling.scheme=staggered -o "$WORK/text.h5" \
    2>"$WORK/err" | grep -q "step (staggered).*residual evaluations, [0-9]* gas steps$"; then
  pass "text output names the scheme and its gas steps"
else
  fail "text output: $(cat "$WORK/err")"
fi

# Bad input: exit 2, one line naming the file, the key and the value.
T=("${COARSE[@]}")
expect_input_error scheme_unknown "coupling.scheme' = 'implicit'" "$PLATE" "${T[@]}" --set coupling.scheme=implicit
expect_input_error key_unknown "unknown key 'coupling.relax'" "$PLATE" "${T[@]}" --set coupling.relax=0.5
expect_input_error iterations_type "coupling.max_iterations' = 'many'" "$PLATE" "${T[@]}" --set coupling.max_iterations=many
expect_input_error iterations_zero "coupling.max_iterations' = 0" "$PLATE" "${T[@]}" --set coupling.max_iterations=0
expect_input_error old_macro_step "coupling.macro_step' = '0.1 us': .*coupling.gas_every" "$PLATE" "${T[@]}" --set "coupling.macro_step=0.1 us"
expect_input_error every_zero "coupling.gas_every' = 0" "$PLATE" "${T[@]}" --set coupling.gas_every=0
expect_input_error every_strong "coupling.gas_every' = 2: the strongly coupled iteration" "$PLATE" "${T[@]}" --set coupling.scheme=strongly_coupled --set coupling.gas_every=2
expect_input_error strong_gas_plate "coupling.strong_gas' = 'true': only with actuation.electrostatics: immersed" "$PLATE" "${T[@]}" --set coupling.strong_gas=true
expect_input_error tolerance_zero "coupling.tolerance' = 0" "$PLATE" "${T[@]}" --set coupling.tolerance=0
expect_input_error tolerance_above_one "coupling.tolerance' = 2" "$PLATE" "${T[@]}" --set coupling.tolerance=2
expect_input_error no_gas "coupling.scheme' = 'staggered': not with .*gas.model: none, pull_in.mode: transient; allowed: monolithic" "$PLATE" "${T[@]}" --set coupling.scheme=staggered --set gas.model=none
expect_input_error laplace "coupling.gas_every' = 2: only with a gas" "$PLANE" --set "coupling={scheme: staggered, gas_every: 2}"
expect_input_error partitioned_ramp "pull_in.dynamic.waveform.type' = 'ramp': a partitioned scheme takes a step voltage only" "$PLATE" --set coupling.scheme=strongly_coupled --set "pull_in.dynamic.waveform={type: ramp, rise_time: 1 us}"
expect_input_error partitioned_release "pull_in.release' = .*: the release runs the monolithic system" "$PLATE" --set coupling.scheme=staggered --set "actuation.contact={gap: 75 nm}" --set "pull_in.release={hold_voltage: 10 V}"
expect_input_error transient_voltage "pull_in.transient.voltage' = '0 V'" "$PLATE" "${T[@]}" --set "pull_in.transient.voltage=0 V"
expect_input_error transient_end "pull_in.transient.end_time' = '-1 us'" "$PLATE" "${T[@]}" --set "pull_in.transient.end_time=-1 us"
expect_input_error transient_missing "pull_in.transient" "$PLATE" --set mesh.cells=[20,2] --set pull_in.mode=transient --set "pull_in.transient={end_time: 5 us}"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
