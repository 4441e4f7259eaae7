#!/usr/bin/env bash
# rfmems-creep end to end:
#   - checkpoint/restart contract: the fixed-fixed creep case runs uninterrupted
#     (writing wall-clock checkpoints, which must not change its arithmetic);
#     then again with a checkpoint at every output, killed with SIGKILL after a random delay
#     once a checkpoint exists, and restarted from it: the final states of the two result
#     files agree to a relative 1e-8 (by construction bit for bit), and the restarted file is
#     complete (every output time, the whole history);
#   - the held switch restarted from its last checkpoint before the collapse: same life and
#     state bit for bit;
#   - the held switch's creep life: reached by the collapse root, the same (0.1 %) with the
#     explicit integrator at dt = 0.5 h; a gap threshold crossed by the IDA root and by
#     interpolation between explicit steps (first order in dt);
#   - the Table 4.1 plate's elastic centre deflection between the plane-stress and
#     plane-strain beam values, and creep adding to the sag monotonically;
#   - the von Karman plate's creep (model.geometric_nonlinearity) a little stiffer than the
#     linear plate's, with its membrane force in the result;
#   - plot_creep.py, and the bad-input contract (one line, exit 2, no result file).
#
# Usage: bash test_creep_driver.sh <directory of rfmems-creep> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-creep"
SRC="$2"
FIXED="$SRC/cases/creep_fixed_fixed/case.yaml"
HOLD="$SRC/cases/creep_switch_hold/case.yaml"

source "$SRC/test/drivers/common.sh"

# --- checkpoint / restart under SIGKILL ---------------------------------------------------
RUN=(--set creep.outputs=40)
# The uninterrupted run writes checkpoints by the wall clock: writing them changes nothing.
if "$DRIVER" "$FIXED" "${RUN[@]}" -o "$WORK/full.h5" --checkpoint-every-seconds 0.2 --json --quiet \
    >"$WORK/full.json" 2>"$WORK/err"; then
  pass "creep_fixed_fixed uninterrupted exits 0"
else
  fail "creep_fixed_fixed: $(cat "$WORK/err")"
fi
killed=no
for attempt in 1 2 3; do
  rm -f "$WORK/killed.h5" "$WORK/killed.checkpoint.h5"
  "$DRIVER" "$FIXED" "${RUN[@]}" -o "$WORK/killed.h5" --checkpoint-every-steps 1 --quiet \
    >/dev/null 2>"$WORK/err" &
  pid=$!
  for _ in $(seq 1 400); do [ -e "$WORK/killed.checkpoint.h5" ] && break; sleep 0.01; done
  sleep "0.$((RANDOM % 8))$((RANDOM % 10))"
  if kill -0 "$pid" 2>/dev/null && kill -KILL "$pid" 2>/dev/null; then
    wait "$pid" 2>/dev/null
    status=$?
    [ "$status" -eq 137 ] && [ ! -e "$WORK/killed.h5" ] && killed=yes && break
  else
    wait "$pid" 2>/dev/null  # finished before the kill: try again
  fi
done
if [ "$killed" = yes ] && [ -e "$WORK/killed.checkpoint.h5" ]; then
  pass "run killed by SIGKILL (attempt $attempt), checkpoint left, no result file"
else
  fail "could not kill the run mid-way with a checkpoint present"
fi
if "$DRIVER" "$FIXED" "${RUN[@]}" -o "$WORK/killed.h5" --restart "$WORK/killed.checkpoint.h5" \
    --json --quiet >"$WORK/restart.json" 2>"$WORK/err" &&
   $PY - "$WORK/full.h5" "$WORK/killed.h5" "$WORK/restart.json" "$WORK/full.json" <<'PY'
import json, sys
import h5py, numpy as np
full, restarted = (h5py.File(p, "r") for p in sys.argv[1:3])
summary = json.load(open(sys.argv[3]))
assert json.load(open(sys.argv[4]))["checkpoints_written"] >= 1
assert summary["restarted"] and 0 < summary["restart_time_s"] < summary["end_time_s"], summary
a = full["creep/final_state/values"][0]
b = restarted["creep/final_state/values"][0]
rel = np.max(np.abs(a - b)) / np.max(np.abs(a))
assert a.shape == b.shape and rel <= 1e-8, rel
# Complete and readable: every output time (t = 0 and 40 outputs), fields at each, history.
times = restarted["fields/times"][()]
assert len(times) == 41 and np.array_equal(times, full["fields/times"][()]), times
for k in range(41):
    g = restarted[f"fields/{k:06d}"]
    assert {"deflection", "plastic_moment", "von_mises_top", "creep_strain"} <= set(g), list(g)
    assert g["deflection"].shape == full[f"fields/{k:06d}/deflection"].shape
ha, hb = full["creep/history/values"][()], restarted["creep/history/values"][()]
assert ha.shape == hb.shape == (41, 3), hb.shape
assert np.max(np.abs(ha - hb) / np.maximum(np.abs(ha), 1e-300)) <= 1e-8
print(f"restart at {summary['restart_time_s'] / 3600:.1f} h: final state max rel. diff {rel:.1e} "
      f"({'bit for bit' if np.array_equal(a, b) else 'not bitwise'}), {len(times)} output times")
PY
then
  pass "restart after SIGKILL: same final state, complete output file"
else
  fail "restart after SIGKILL: $(cat "$WORK/err")"
fi
# The checkpoint belongs to its settings: another case (a changed key) is refused.
expect_input_error restart_other_settings "checkpoint was written for other settings" \
  "$FIXED" "${RUN[@]}" --set "pressure.value=-70 kPa" --restart "$WORK/killed.checkpoint.h5"

# --- the Table 4.1 plate: elastic deflection, creep sag ----------------------------------
if $PY - "$WORK/full.h5" <<'PY'
import json, sys
import h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
h = f["creep/history/values"][()]
w = h[:, 0]
# Beam bounds, clamped-clamped, uniform q: w = q L^4 / (32 E' h^3) per unit width, E' = E
# (plane stress, narrow) or E / (1 - nu^2) (plane strain, wide); shear adds ~(h/L)^2.
q, L, hh, E, nu = 60e3, 240e-6, 4e-6, 200e9, 0.3
w_stress = q * L**4 / (32 * E * hh**3)
w_strain = w_stress * (1 - nu**2)
assert w_strain < -w[0] < w_stress * 1.01, (w[0], w_strain, w_stress)
sag = w - w[0]
assert np.all(np.diff(w) < 0) and sag[-1] < 0, sag    # creep only adds to the sag
assert 1e-4 < sag[-1] / w[0] < 1e-2, sag[-1] / w[0]   # small: hardened within seconds
print(f"w_el = {w[0]:.4e} m (beam {-w_strain:.3e} .. {-w_stress:.3e}), w_p(500 h) = {sag[-1]:.4e} m")
PY
then
  pass "fixed-fixed plate: elastic deflection within beam bounds, creep sag monotone and small"
else
  fail "fixed-fixed plate figures"
fi

# --- the held switch's life ----------------------------------------------------------------
"$DRIVER" "$HOLD" --set creep.outputs=20 -o "$WORK/hold.h5" --checkpoint-every-steps 1 --json --quiet \
  >"$WORK/hold.json" 2>"$WORK/err" || fail "hold: $(cat "$WORK/err")"
# Restarted from its last checkpoint (the output before the collapse), the held switch (Newton
# equilibrium, hold-voltage tangent, collapse root) ends at the same life and state, bit for bit.
if "$DRIVER" "$HOLD" --set creep.outputs=20 -o "$WORK/hold_r.h5" --restart "$WORK/hold.checkpoint.h5" \
    --json --quiet >"$WORK/hold_r.json" 2>"$WORK/err" &&
   $PY - "$WORK/hold.h5" "$WORK/hold_r.h5" "$WORK/hold.json" "$WORK/hold_r.json" <<'PY'
import json, sys
import h5py, numpy as np
a, b = (h5py.File(p, "r")["creep/final_state/values"][0] for p in sys.argv[1:3])
s, r = (json.load(open(p)) for p in sys.argv[3:5])
assert r["restarted"] and r["restart_time_s"] < r["lifetime_s"], r
assert r["end"] == s["end"] == "collapse" and r["lifetime_s"] == s["lifetime_s"], (s, r)
assert np.array_equal(a, b), np.max(np.abs(a - b))
print(f"hold restart at {r['restart_time_s'] / 3600:.0f} h: life {r['lifetime_h']:.3f} h, state bit for bit")
PY
then
  pass "held switch restarted before its collapse: same life, same state"
else
  fail "held switch restart: $(cat "$WORK/err")"
fi
"$DRIVER" "$HOLD" --set creep.outputs=20 --set creep.integration=explicit --set "creep.dt=0.5 h" -o "$WORK/hold_e.h5" \
  --json --quiet >"$WORK/hold_e.json" 2>"$WORK/err" || fail "hold explicit: $(cat "$WORK/err")"
for dt in implicit "1 h" "4 h"; do
  set_args=(--set creep.outputs=20 --set "creep.lifetime.gap_threshold=2.5 um")
  [ "$dt" != implicit ] && set_args+=(--set creep.integration=explicit --set "creep.dt=$dt")
  "$DRIVER" "$HOLD" "${set_args[@]}" -o "$WORK/thr.h5" --json --quiet \
    >"$WORK/thr_${dt// /}.json" 2>"$WORK/err" || fail "threshold $dt: $(cat "$WORK/err")"
done
if $PY - "$WORK" <<'PY'
import json, sys
d = sys.argv[1]
load = lambda n: json.load(open(f"{d}/{n}.json"))
imp, exp = load("hold"), load("hold_e")
assert imp["end"] == "collapse" and imp["life_reached"], imp
assert exp["life_reached"] and exp["end"] in ("collapse", "equilibrium_lost"), exp
# The collapse happens well below the lumped fold 2/3 g0 of the initial gap, well above 0.
assert 0.5 < imp["final"]["min_gap"] / imp["initial_min_gap"] < 0.9, imp
assert abs(exp["lifetime_h"] / imp["lifetime_h"] - 1) < 1e-3, (exp["lifetime_h"], imp["lifetime_h"])
# Gap threshold 2.5 um: IDA root vs explicit interpolation, error ~ dt (first order).
t_imp, t_1, t_4 = (load(f"thr_{k}")["lifetime_h"] for k in ("implicit", "1h", "4h"))
for k in ("implicit", "1h", "4h"):
    r = load(f"thr_{k}")
    assert r["end"] == "gap_threshold" and abs(r["final"]["min_gap"] - 2.5e-6) < 1e-12, r
e1, e4 = abs(t_1 - t_imp), abs(t_4 - t_imp)
assert e1 < 0.5 and 2 < e4 / e1 < 8, (t_imp, t_1, t_4)
print(f"life at 180 V: {imp['lifetime_h']:.2f} h (IDA, {imp['steps']} steps), "
      f"{exp['lifetime_h']:.2f} h (explicit 0.5 h); gap 2.5 um at {t_imp:.3f} h "
      f"(explicit 1 h: {t_1:.3f}, 4 h: {t_4:.3f})")
PY
then
  pass "held switch: creep life by the collapse root, explicit agrees; threshold root and interpolation"
else
  fail "held switch figures"
fi
if $PY "$SRC/python/plot_creep.py" "$WORK/hold.h5" "$WORK/thr.h5" >/dev/null && [ -s "$WORK/hold_creep.png" ]; then
  pass "plot_creep.py draws deflection and gap vs time"
else
  fail "plot_creep.py"
fi

# --- bad input -------------------------------------------------------------------------------
# creep.shear_creep: the transverse shear creeps too (KLU on the full Jacobian), so the
# fixed-fixed plate (L/h = 60) sags a little more in 500 h (measured +0.9 %: -3.5823e-10 against
# -3.5502e-10 m; the plate-vs-continuum study shows which is right, docs/creep.md).
if "$DRIVER" "$FIXED" --set creep.outputs=1 -o "$WORK/bend.h5" --json --quiet >"$WORK/bend.json" &&
   "$DRIVER" "$FIXED" --set creep.outputs=1 --set creep.shear_creep=true -o "$WORK/shear.h5" \
     --json --quiet >"$WORK/shear.json" &&
   $PY - "$WORK/bend.json" "$WORK/shear.json" <<'PY'
import json, sys
b, s = (json.load(open(f)) for f in sys.argv[1:3])
wb = b["probes"]["centre"]["w_final"] - b["probes"]["centre"]["w_initial"]
ws = s["probes"]["centre"]["w_final"] - s["probes"]["centre"]["w_initial"]
assert abs(s["probes"]["centre"]["w_initial"] / b["probes"]["centre"]["w_initial"] - 1) < 1e-12
assert wb < 0 and 1.002 < ws / wb < 1.03, (wb, ws)
print(f"  creep sag {wb:.5e} m bending only, {ws:.5e} m with shear creep")
PY
then
  pass "creep.shear_creep: the same elastic state, slightly more creep"
else
  fail "creep.shear_creep run"
fi
# model.geometric_nonlinearity: the von Karman plate creeps (KLU on the full Jacobian). The
# fixed-fixed plate sags w/h = 0.12, so stretching stiffens it by ~(w/h)^2 (measured: the
# elastic sag 0.95 % and the creep sag 2 % less than the linear plate's); the result holds the
# in-plane displacements, the stretching part of N (membrane_force) and the whole
# h sigma0 + A:eps - C int eps_p dz (total_membrane_force), tension at the centre.
if "$DRIVER" "$FIXED" --set creep.outputs=1 --set model.geometric_nonlinearity=true \
     -o "$WORK/vk.h5" --json --quiet >"$WORK/vk.json" &&
   $PY - "$WORK/bend.json" "$WORK/vk.json" "$WORK/vk.h5" <<'PY'
import json, sys
import h5py, numpy as np
b, v = (json.load(open(f)) for f in sys.argv[1:3])
pb, pv = b["probes"]["centre"], v["probes"]["centre"]
elastic = pv["w_initial"] / pb["w_initial"]
creep = (pv["w_final"] - pv["w_initial"]) / (pb["w_final"] - pb["w_initial"])
assert 0.98 < elastic < 0.999 and 0.9 < creep < 0.999, (elastic, creep)
f = h5py.File(sys.argv[3])
last = f["fields"][sorted(k for k in f["fields"] if k.isdigit())[-1]]
N = np.asarray(last["total_membrane_force"])
centre = np.argmin(np.linalg.norm(np.asarray(f["mesh/cell_centroids"])[:, :2] - [120e-6, 30e-6], axis=1))
assert N[centre, 0] > 0 and "membrane_force" in last, N[centre]
print(f"  von Karman / linear: elastic sag {elastic:.5f}, creep sag {creep:.5f}; N_xx {N[centre, 0]:.4g} N/m")
PY
then
  pass "model.geometric_nonlinearity: the von Karman plate creeps, a little stiffer"
else
  fail "model.geometric_nonlinearity creep run"
fi
expect_input_error shear_creep_not_bool "creep.shear_creep" "$FIXED" --set creep.shear_creep=maybe
expect_input_error shear_creep_with_von_karman "creep.shear_creep" "$FIXED" \
  --set creep.shear_creep=true --set model.geometric_nonlinearity=true
expect_input_error missing_law_key "creep.law.sigma_y0" "$FIXED" --set "creep.law={A: 1e-6, B: 1, m: 2, n: 2}"
expect_input_error bad_integration "creep.integration" "$FIXED" --set creep.integration=euler
expect_input_error explicit_without_dt "creep.dt" "$FIXED" --set creep.integration=explicit
expect_input_error bad_duration "creep.end_time" "$FIXED" --set "creep.end_time=500 hours"
expect_input_error even_points "creep.thickness_points" "$FIXED" --set creep.thickness_points=20
expect_input_error lifetime_without_gap "creep.lifetime" "$FIXED" --set "creep.lifetime={gap_threshold: 0 um}"
expect_input_error threshold_above_gap "creep.lifetime.gap_threshold" "$HOLD" --set "creep.lifetime.gap_threshold=4 um"
expect_input_error negative_voltage "actuation.voltage" "$HOLD" --set "actuation.voltage=-5 V"
expect_input_error above_pull_in "actuation.voltage.*above the pull-in" "$HOLD" --set "actuation.voltage=195 V"
expect_input_error gas_refused "gas" "$HOLD" --set "actuation.gap=3.75 um" --set "gas={model: reynolds, pressure: 1 atm}"
expect_input_error typo "creep.rtoll" "$FIXED" --set creep.rtoll=1e-6
expect_input_error bad_steps_flag "checkpoint-every-steps" "$FIXED" --checkpoint-every-steps 1.5
expect_input_error restart_missing "checkpoint file not found" "$FIXED" --restart "$WORK/none.h5"
echo "not a checkpoint" >"$WORK/text.h5"
expect_input_error restart_not_checkpoint "not a readable rfmems checkpoint" "$FIXED" --restart "$WORK/text.h5"

[ "$failures" -eq 0 ] && echo "all creep driver tests passed" || echo "$failures creep driver test(s) failed"
exit "$failures"
