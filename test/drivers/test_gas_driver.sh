#!/usr/bin/env bash
# rfmems-gas end to end on reduced versions of the gas cases: Couette flow (20 cells) against
# the first-order slip solution and with balanced wall forces; heat transfer (8 x 8, Kn = 1)
# with balanced wall heat flows and a temperature uniform along x; the cavity (8 x 8, Kn = 1)
# with balanced x forces and a clockwise vortex; COMET against the sequential solver (heat
# transfer 10 x 10, Kn = 0.01); the squeeze film (coarse: odd, linear, mass balanced); the
# plots; and the bad-input contract.
#
# Usage: bash test_gas_driver.sh <directory of the drivers> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-gas"
SRC="$2"
COUETTE="$SRC/cases/gas_couette/case.yaml"
HEAT="$SRC/cases/gas_heat_transfer/case.yaml"
CAVITY="$SRC/cases/gas_cavity/case.yaml"

source "$SRC/test/drivers/common.sh"

# ---- Couette, Kn = 0.1, 20 cells: slip solution within 2 % RMS, forces balance --------------
if "$DRIVER" "$COUETTE" --set "mesh.cells=[1, 20]" -o "$WORK/couette.h5" --json --quiet \
     >"$WORK/couette.json" 2>"$WORK/err" &&
   $PY - "$WORK/couette.json" "$WORK/couette.h5" <<'PY'
import json, sys
import h5py, numpy as np
d = json.load(open(sys.argv[1]))
s = d["solver"]
assert s["converged"] and s["residual_ratio"] <= 1e-6 and s["type"] == "sequential", s
assert abs(d["initial"]["knudsen"] / 0.1 - 1) < 1e-12, d["initial"]
fb, ft = d["walls"]["bottom"]["force"], d["walls"]["top"]["force"]
assert abs(fb[2] + ft[2]) < 1e-3 * fb[2] and fb[2] > 0, (fb, ft)
with h5py.File(sys.argv[2]) as f:
    y = f["mesh/cell_centroids"][:, 1]
    uz = f["fields/000000/velocity"][()].reshape(-1, 3)[:, 2]
    its = f["solver/residual/iteration"][()]
    assert len(its) == s["iterations"], (len(its), s["iterations"])
kn, U = 0.1, 10.0
rms = np.sqrt(np.mean(((uz - U * (y + kn) / (1 + 2 * kn)) / U) ** 2))
assert rms < 0.02, rms
print(f"RMS error vs slip {100 * rms:.3f} %, {s['iterations']} iterations, wall force {fb[2]:.4e} N/m")
PY
then
  pass "Couette: converged, velocity within 2 % RMS of the slip solution, wall forces balance"
else
  fail "Couette: $(cat "$WORK/err")"
fi
if $PY "$SRC/python/plot_gas.py" "$WORK/couette.h5" >/dev/null && [ -s "$WORK/couette_fields.png" ] &&
   [ -s "$WORK/couette_profile.png" ] && [ -s "$WORK/couette_residual.png" ]; then
  pass "plot_gas.py draws fields, profile and residual history"
else
  fail "plot_gas.py"
fi

# ---- heat transfer, 8 x 8, Kn = 1: heat flows balance, T uniform along x --------------------
if "$DRIVER" "$HEAT" --set "mesh.cells=[8, 8]" --set initial.knudsen=1 \
     --set "velocity_grid.points=[8, 8, 8]" -o "$WORK/heat.h5" --json --quiet \
     >"$WORK/heat.json" 2>"$WORK/err" &&
   $PY - "$WORK/heat.json" "$WORK/heat.h5" <<'PY'
import json, sys
import h5py, numpy as np
d = json.load(open(sys.argv[1]))
qb, qt = d["walls"]["bottom"]["heat_flow"], d["walls"]["top"]["heat_flow"]
assert d["solver"]["converged"] and qb > 0 and abs(qb + qt) < 1e-3 * qb, (qb, qt)
with h5py.File(sys.argv[2]) as f:
    T = f["fields/000000/temperature"][()].reshape(8, 8)  # rows: y
assert np.all(T.max(axis=1) - T.min(axis=1) < 1e-6 * T.mean()), T
assert 273.15 < T.min() and T.max() < 327.78, (T.min(), T.max())
print(f"heat flow {qb:.4e} W/m, T from {T.min():.2f} to {T.max():.2f} K")
PY
then
  pass "heat transfer: converged, wall heat flows balance, temperature uniform along x"
else
  fail "heat transfer: $(cat "$WORK/err")"
fi

# ---- cavity, 8 x 8, Kn = 1: x forces balance, clockwise vortex -------------------------------
if "$DRIVER" "$CAVITY" --set "mesh.cells=[8, 8]" --set initial.knudsen=1 \
     --set "velocity_grid.points=[8, 8, 8]" -o "$WORK/cavity.h5" --json --quiet \
     >"$WORK/cavity.json" 2>"$WORK/err" &&
   $PY - "$WORK/cavity.json" "$WORK/cavity.h5" <<'PY'
import json, sys
import h5py, numpy as np
d = json.load(open(sys.argv[1]))
w = d["walls"]
fx = [w[p]["force"][0] for p in ("top", "bottom", "left", "right")]
assert d["solver"]["converged"] and fx[0] < 0 and abs(sum(fx)) < 1e-3 * abs(fx[0]), fx
with h5py.File(sys.argv[2]) as f:
    u = f["fields/000000/velocity"][()].reshape(8, 8, 3)
assert u[-1, :, 0].mean() > 0 and u[0, :, 0].mean() < 0, u[:, :, 0]
print(f"lid drag {fx[0]:.4e} N/m, u_x under the lid {u[-1, :, 0].mean():.3f} m/s")
PY
then
  pass "cavity: converged, x forces on the walls balance, clockwise vortex"
else
  fail "cavity: $(cat "$WORK/err")"
fi

# ---- COMET against the sequential solver, heat transfer 10 x 10 at Kn = 0.01 ----------------
# The same converged state (both to 1e-6 of the initial residual) from both solvers, and COMET
# in far fewer iterations (multigrid cycles against sweeps) in the near-continuum regime it is for.
COMET_ARGS=("$HEAT" --set "mesh.cells=[10, 10]" --set initial.knudsen=0.01
            --set "velocity_grid.points=[8, 8, 8]" --json --quiet)
if "$DRIVER" "${COMET_ARGS[@]}" -o "$WORK/seq.h5" >"$WORK/seq.json" 2>"$WORK/err" &&
   "$DRIVER" "${COMET_ARGS[@]}" --set solver.type=comet -o "$WORK/comet.h5" \
     >"$WORK/comet.json" 2>"$WORK/err" &&
   $PY - "$WORK/seq.json" "$WORK/comet.json" "$WORK/seq.h5" "$WORK/comet.h5" <<'PY'
import json, sys
import h5py, numpy as np
seq, com = (json.load(open(p)) for p in sys.argv[1:3])
assert seq["solver"]["converged"] and com["solver"]["converged"], (seq["solver"], com["solver"])
assert com["solver"]["type"] == "comet", com["solver"]
qs, qc = seq["walls"]["bottom"]["heat_flow"], com["walls"]["bottom"]["heat_flow"]
assert abs(qc / qs - 1) < 1e-3, (qs, qc)
with h5py.File(sys.argv[3]) as a, h5py.File(sys.argv[4]) as b:
    Ts, Tc = a["fields/000000/temperature"][()], b["fields/000000/temperature"][()]
dT = np.abs(Tc - Ts).max() / (327.78 - 273.15)
assert dT < 1e-3, dT
its, itc = seq["solver"]["iterations"], com["solver"]["iterations"]
assert 5 * itc < its, (its, itc)
print(f"heat flow {qs:.6e} / {qc:.6e} W/m, max dT/DT {dT:.1e}, iterations {its} / {itc}")
PY
then
  pass "COMET: same heat flow and temperatures as the sequential solver, >5x fewer iterations"
else
  fail "COMET vs sequential: $(cat "$WORK/err")"
fi

# ---- COMET's cycle from the case (solver.cycle): the default against an explicit V ---------
# docs/kinetic.md, "COMET cycle by regime": below a domain Kn of 0.02 the default (auto) runs F-cycles
# with one-pass coarse sweeps, which need fewer cycles than the V-cycle near continuum; the
# same steady state (both stop at 1e-6 of the initial residual).
if "$DRIVER" "${COMET_ARGS[@]}" --set solver.type=comet --set solver.cycle=V \
     -o "$WORK/comet_v.h5" >"$WORK/comet_v.json" 2>"$WORK/err" &&
   $PY - "$WORK/comet_v.json" "$WORK/comet.json" <<'PY'
import json, sys
v, a = (json.load(open(p)) for p in sys.argv[1:3])
assert v["solver"]["converged"], v["solver"]
qv, qa = v["walls"]["bottom"]["heat_flow"], a["walls"]["bottom"]["heat_flow"]
assert abs(qa / qv - 1) < 1e-4, (qv, qa)
assert a["solver"]["iterations"] < v["solver"]["iterations"], (v["solver"], a["solver"])
print(f"V / default (F) cycles {v['solver']['iterations']} / {a['solver']['iterations']}, "
      f"heat flow {qv:.6e} / {qa:.6e} W/m")
PY
then
  pass "COMET default cycle (F near continuum): same heat flow as the V-cycle, fewer cycles"
else
  fail "COMET default cycle against V: $(cat "$WORK/err")"
fi

# ---- squeeze film, coarse (167 cells, 8^3 velocities), beam at -0.1, +0.1, -0.2 m/s -------
# Damping opposes the motion, is linear in the velocity and odd in it at these speeds (the
# film's pressure change is ~1.5 % of p, which bounds the nonlinearity), and the steady state
# passes as much gas out of the domain as the moving beam pushes in (mass balance over all
# patches to the solver's tolerance).
SQUEEZE="$SRC/cases/gas_squeeze_film/case.yaml"
for v in -0.1 0.1 -0.2; do
  "$DRIVER" "$SQUEEZE" --set mesh.parameters.refine=0.25 --set "velocity_grid.points=[8, 8, 8]" \
    --set "boundaries.beam.velocity=[0 m/s, $v m/s]" -o "$WORK/squeeze$v.h5" --json --quiet \
    >"$WORK/squeeze$v.json" 2>"$WORK/err" || fail "squeeze film at $v m/s: $(cat "$WORK/err")"
done
if $PY - "$WORK"/squeeze-0.1.json "$WORK"/squeeze0.1.json "$WORK"/squeeze-0.2.json <<'PY'
import json, sys
runs = [json.load(open(p)) for p in sys.argv[1:4]]
for d in runs:
    assert d["solver"]["converged"], d["solver"]
    flows = [b["mass_flow"] for b in d["boundaries"].values()]
    assert abs(sum(flows)) < 1e-3 * max(abs(q) for q in flows), d["boundaries"]
down, up, down2 = (d["walls"]["beam"]["force"][1] for d in runs)
assert down > 0 > up, (down, up)
assert abs(down + up) < 0.05 * down, (down, up)
assert abs(down2 / down - 2) < 0.04, (down, down2)
print(f"half-beam force {down:.4e} / {up:.4e} / {down2:.4e} N/m at -0.1 / +0.1 / -0.2 m/s: "
      f"odd to {abs(down + up) / down:.1e}, linear to {abs(down2 / down / 2 - 1):.1e}")
PY
then
  pass "squeeze film: damping opposes the motion, odd and linear in the velocity, mass balanced"
else
  fail "squeeze film"
fi

# ---- near the continuum the sequential solver says early that its cap will not do -----------
# Kn = 1e-4: source iteration contracts by ~0.997 per sweep and slows further; with a cap of
# 20000 sweeps the contraction rate forecasts the cap's failure within its first tenth: exit 1,
# one line with the rate and the remedy (COMET), no result file.
start=$SECONDS
"$DRIVER" "$CAVITY" --set "mesh.cells=[20, 20]" --set initial.knudsen=1e-4 \
  --set "velocity_grid.points=[6, 6, 6]" --set solver.max_iterations=20000 \
  -o "$WORK/slow.h5" --quiet >/dev/null 2>"$WORK/err"
rc=$?
if [ $rc -eq 1 ] && grep -q "contraction rate" "$WORK/err" && grep -q "solver.type: comet" "$WORK/err" &&
   [ ! -e "$WORK/slow.h5" ] &&
   $PY -c "import re,sys; n=int(re.search(r'after (\d+) of its 20000', open(sys.argv[1]).read()).group(1)); assert n <= 2000, n; print('stopped after', n, 'sweeps')" "$WORK/err"; then
  pass "Kn 1e-4 sequential: stopped early by the forecast ($((SECONDS - start)) s)"
else
  fail "Kn 1e-4 sequential (exit $rc): $(cat "$WORK/err")"
fi

# ---- bad input: exit 2, one line naming file and key, no result file (common.sh) ------------
expect_input_error bad_collision "gas.collision" "$COUETTE" --set gas.collision=bgk2
expect_input_error missing_boundary "boundaries.left" "$COUETTE" \
  --set "boundaries={top: {type: specular_wall}, bottom: {type: specular_wall}, right: {type: specular_wall}}"
expect_input_error unknown_patch "boundaries.lid" "$COUETTE" --set "boundaries.lid={type: symmetry}"
expect_input_error density_and_knudsen "initial" "$COUETTE" --set "initial.density=1e-5 kg/m^3"
expect_input_error bad_points "velocity_grid.points" "$COUETTE" --set "velocity_grid.points=[10, 10]"
expect_input_error bad_solver "solver.type" "$COUETTE" --set solver.type=multigrid
expect_input_error negative_wall_T "boundaries.top.T" "$COUETTE" --set "boundaries.top.T=-3 K"
expect_input_error bad_accommodation "boundaries.top.accommodation" "$COUETTE" \
  --set boundaries.top.accommodation=1.5
expect_input_error typo "solver.tolerence" "$COUETTE" --set solver.tolerence=1e-8
expect_input_error comet_key_typo "solver.pre_sweep" "$COUETTE" --set solver.type=comet \
  --set solver.pre_sweep=2
expect_input_error comet_bad_coupling "solver.coupling" "$COUETTE" --set solver.type=comet \
  --set solver.coupling=momentum
expect_input_error comet_bad_cycle "solver.cycle" "$COUETTE" --set solver.type=comet \
  --set solver.cycle=X

exit $((failures > 0))
