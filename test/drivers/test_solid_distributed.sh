#!/usr/bin/env bash
# rfmems-solid with solver.distributed: true: the cantilever distributed over 1, 2
# and 3 ranks (METIS parts, KINSOL + GMRES with additive Schwarz KLU blocks on the parallel N_Vector)
# writes one result file on rank 0 whose displacement field equals the serial KLU run's to
# 2e-7 of its largest value (the round-off floor of this L/h = 50 beam is ~4e-8,
# test/mpi/test_distributed_structure.cpp), in one Newton step; a short transient equals the
# serial IDA run's to 10 x its rtol in at most 1.5 x its steps, with no GMRES solve missing
# its tolerance; the clamped plate's static deflection and rotations on 2 ranks equal the
# serial ones to 1e-8 (a stocky plate: well conditioned); a plate transient (serial only)
# stops with exit 2 naming the key.
# solver.linear multigrid (GMRES with BoomerAMG): the 3D box matrix-free on one rank and
# distributed on 2 ranks equals the serial KLU run to 1e-8 at a 1e-10 Newton tolerance, in one
# Newton step; at a tolerance beneath the round-off floor multigrid stops there in one Newton
# step too; auto picks multigrid for the case's 3D box (15,360 unknowns) and KLU for the
# plane cantilever; a modal analysis with multigrid is bad input.
#
# Usage: bash test_solid_distributed.sh <directory of the drivers> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-solid"
SRC="$2"
source "$SRC/test/drivers/common.sh"
MPIRUN=(mpirun --allow-run-as-root --oversubscribe)
DIST=(--set 'solver={distributed: true}')

compare() {  # compare SERIAL.h5 OTHER.h5 FIELD TOLERANCE: max |a - b| / max |a| over all outputs
  $PY - "$@" <<'PY'
import sys, h5py, numpy as np
a, b, field, tol = h5py.File(sys.argv[1]), h5py.File(sys.argv[2]), sys.argv[3], float(sys.argv[4])
steps = sorted(k for k in a["fields"] if k.isdigit())
assert steps == sorted(k for k in b["fields"] if k.isdigit()), "different outputs"
scale = max(np.abs(a["fields"][s][field][()]).max() for s in steps)
diff = max(np.abs(a["fields"][s][field][()] - b["fields"][s][field][()]).max() for s in steps)
print(f"{len(steps)} outputs: max |{field} - serial| / max |{field}| = {diff / scale:.2e}")
sys.exit(0 if diff <= tol * scale else 1)
PY
}

STATIC=("$SRC/cases/cantilever_static/case.yaml" --set "mesh.cells=[80, 8]" --json --quiet)
"$DRIVER" "${STATIC[@]}" -o "$WORK/serial.h5" >"$WORK/serial.json" 2>"$WORK/err" ||
  fail "serial static: $(cat "$WORK/err")"
for n in 1 2 3; do
  if "${MPIRUN[@]}" -np $n "$DRIVER" "${STATIC[@]}" "${DIST[@]}" -o "$WORK/d$n.h5" \
      >"$WORK/d$n.json" 2>"$WORK/err" &&
     $PY -c "import json,sys; s=json.load(open(sys.argv[1]))['solver']; assert s['distributed_ranks'] == $n and s['newton_iterations'] == 1, s; print('GMRES iterations', s['krylov_iterations'])" "$WORK/d$n.json" &&
     compare "$WORK/serial.h5" "$WORK/d$n.h5" displacement 2e-7; then
    pass "static cantilever distributed on $n ranks = serial KLU"
  else
    fail "static cantilever on $n ranks: $(head -3 "$WORK/err")"
  fi
done

TRANSIENT=("$SRC/cases/cantilever_vibration/case.yaml" --set "mesh.cells=[40, 4]"
           --set "analysis.end_time=20 ms" --set "analysis.output_interval=5 ms" --quiet)
"$DRIVER" "${TRANSIENT[@]}" --json -o "$WORK/tserial.h5" >"$WORK/tserial.json" 2>"$WORK/err" ||
  fail "serial transient: $(cat "$WORK/err")"
# The JSON reports GMRES solves that missed IDA's Krylov tolerance (krylov_conv_fails): with the
# Schur preconditioner and its eps_lin (docs/mpi.md, "Krylov tolerance") this beam has none.
if "${MPIRUN[@]}" -np 2 "$DRIVER" "${TRANSIENT[@]}" --set solver.distributed=true --json \
    -o "$WORK/t2.h5" >"$WORK/t2.json" 2>"$WORK/err" &&
   compare "$WORK/tserial.h5" "$WORK/t2.h5" displacement 1e-3 &&
   $PY -c "import json,sys; s=json.load(open(sys.argv[1]))['solver']; assert s['krylov_iterations'] > s['steps'] > 0 and s['krylov_conv_fails'] == 0, s" "$WORK/t2.json" &&
   $PY -c "import json,sys; a, b = (json.load(open(p))['solver']['steps'] for p in sys.argv[1:]); assert b <= 1.5 * a, (a, b); print('IDA steps serial', a, '2 ranks', b)" "$WORK/tserial.json" "$WORK/t2.json"; then
  pass "transient cantilever distributed on 2 ranks = serial IDA to 10 rtol in 1.5x its steps, no Krylov failures"
else
  fail "transient on 2 ranks: $(head -3 "$WORK/err")"
fi

PLATE=("$SRC/cases/clamped_plate/case.yaml" --set "mesh.cells=[20, 20]" --quiet)
"$DRIVER" "${PLATE[@]}" -o "$WORK/pserial.h5" 2>"$WORK/err" || fail "serial plate: $(cat "$WORK/err")"
if "${MPIRUN[@]}" -np 2 "$DRIVER" "${PLATE[@]}" "${DIST[@]}" -o "$WORK/p2.h5" 2>"$WORK/err" &&
   compare "$WORK/pserial.h5" "$WORK/p2.h5" deflection 1e-8 &&
   compare "$WORK/pserial.h5" "$WORK/p2.h5" rotation 1e-8; then
  pass "static clamped plate distributed on 2 ranks = serial KLU"
else
  fail "plate on 2 ranks: $(head -3 "$WORK/err")"
fi
expect_input_error plate_transient_distributed "solver.distributed" \
  "$SRC/cases/plate_vibration/case.yaml" --set solver.distributed=true

BOX=("$SRC/cases/cantilever_box_3d/case.yaml" --set "mesh.cells=[40, 4, 4]" --json --quiet)
linear_solver() {  # linear_solver FILE.json: the solver's name, its Newton and GMRES iterations
  $PY -c "import json,sys; s=json.load(open(sys.argv[1]))['solver']; print(s['linear_solver'], s['newton_iterations'], s.get('krylov_iterations'))" "$1"
}
"$DRIVER" "${BOX[@]}" --set "solver={linear: direct, tolerance: 1e-10}" -o "$WORK/bklu.h5" \
  >"$WORK/bklu.json" 2>"$WORK/err" || fail "box with KLU: $(cat "$WORK/err")"
if "$DRIVER" "${BOX[@]}" --set "solver={linear: multigrid, tolerance: 1e-10}" -o "$WORK/bamg.h5" \
    >"$WORK/bamg.json" 2>"$WORK/err" && [ "$(linear_solver "$WORK/bamg.json" | cut -d' ' -f1-2)" = "multigrid 1" ] &&
   compare "$WORK/bklu.h5" "$WORK/bamg.h5" displacement 1e-8; then
  pass "3D box, multigrid (matrix-free) on one rank = KLU: $(linear_solver "$WORK/bamg.json")"
else
  fail "3D box multigrid: $(head -3 "$WORK/err") $(linear_solver "$WORK/bamg.json")"
fi
if "${MPIRUN[@]}" -np 2 "$DRIVER" "${BOX[@]}" \
    --set "solver={distributed: true, linear: multigrid, tolerance: 1e-10}" -o "$WORK/bamg2.h5" \
    >"$WORK/bamg2.json" 2>"$WORK/err" && [ "$(linear_solver "$WORK/bamg2.json" | cut -d' ' -f1-2)" = "multigrid 1" ] &&
   compare "$WORK/bklu.h5" "$WORK/bamg2.h5" displacement 1e-8; then
  pass "3D box, multigrid distributed on 2 ranks = KLU: $(linear_solver "$WORK/bamg2.json")"
else
  fail "3D box multigrid on 2 ranks: $(head -3 "$WORK/err")"
fi
# From 20,000 unknowns the sparse LU is UMFPACK's (solvers/sparse_direct_solver.hpp): the plane
# cantilever on 320 x 32 (20,480 unknowns), to the residual's round-off floor in one Newton step,
# against multigrid at the default tolerance (measured 2.2e-9 apart).
FINE=("$SRC/cases/cantilever_static/case.yaml" --set "mesh.cells=[320, 32]" --json --quiet)
"$DRIVER" "${FINE[@]}" --set "solver={linear: direct, tolerance: 1e-10}" -o "$WORK/fumf.h5" \
  >"$WORK/fumf.json" 2>"$WORK/err" || fail "plane 320 x 32, direct: $(cat "$WORK/err")"
if "$DRIVER" "${FINE[@]}" --set "solver={linear: multigrid}" -o "$WORK/famg.h5" \
    >"$WORK/famg.json" 2>"$WORK/err" &&
   [ "$(linear_solver "$WORK/fumf.json" | cut -d' ' -f1-2)" = "umfpack 1" ] &&
   compare "$WORK/fumf.h5" "$WORK/famg.h5" displacement 1e-7; then
  pass "plane cantilever 320 x 32: UMFPACK in one Newton step = multigrid"
else
  fail "plane 320 x 32 UMFPACK: $(head -3 "$WORK/err") $(linear_solver "$WORK/fumf.json")"
fi
# A Newton tolerance beneath the residual's round-off floor (this L/h = 50 beam's: ~2e-7 of
# its initial residual): the Krylov path stops there after one Newton step, as the direct one
# does, with the direct answer to that floor (solvers/distributed_static_solve.hpp).
FLOOR=("$SRC/cases/cantilever_static/case.yaml" --set "mesh.cells=[160, 16]" --json --quiet)
"$DRIVER" "${FLOOR[@]}" --set "solver={linear: direct, tolerance: 1e-10}" -o "$WORK/lklu.h5" \
  >"$WORK/lklu.json" 2>"$WORK/err" || fail "plane 160 x 16, direct: $(cat "$WORK/err")"
if "$DRIVER" "${FLOOR[@]}" --set "solver={linear: multigrid, tolerance: 1e-10}" \
    -o "$WORK/lamg.h5" >"$WORK/lamg.json" 2>"$WORK/err" &&
   [ "$(linear_solver "$WORK/lklu.json" | cut -d' ' -f1-2)" = "klu 1" ] &&
   [ "$(linear_solver "$WORK/lamg.json" | cut -d' ' -f1-2)" = "multigrid 1" ] &&
   [ "$(linear_solver "$WORK/lamg.json" | cut -d' ' -f3)" -le 300 ] &&
   compare "$WORK/lklu.h5" "$WORK/lamg.h5" displacement 1e-6; then
  pass "plane cantilever 160 x 16 at tolerance 1e-10: multigrid stops at the round-off floor in one Newton step: $(linear_solver "$WORK/lamg.json")"
else
  fail "multigrid beneath the round-off floor: $(head -3 "$WORK/err") $(linear_solver "$WORK/lamg.json")"
fi
"$DRIVER" "$SRC/cases/cantilever_box_3d/case.yaml" --json --quiet -o "$WORK/auto3d.h5" \
  >"$WORK/auto3d.json" 2>"$WORK/err" || fail "box, auto: $(cat "$WORK/err")"
"$DRIVER" "${STATIC[@]}" -o "$WORK/auto2d.h5" >"$WORK/auto2d.json" 2>"$WORK/err" ||
  fail "cantilever, auto: $(cat "$WORK/err")"
if [ "$(linear_solver "$WORK/auto3d.json" | cut -d' ' -f1)" = multigrid ] &&
   [ "$(linear_solver "$WORK/auto2d.json" | cut -d' ' -f1)" = klu ]; then
  pass "solver.linear auto: multigrid for the 3D box, KLU for the plane cantilever"
else
  fail "solver.linear auto: $(linear_solver "$WORK/auto3d.json") / $(linear_solver "$WORK/auto2d.json")"
fi
expect_input_error modal_multigrid "solver.linear" "$SRC/cases/cantilever_box_3d/case.yaml" \
  --set analysis.type=modal --set "solver={linear: multigrid}"
expect_input_error linear_typo "solver.linear" "$SRC/cases/cantilever_box_3d/case.yaml" \
  --set "solver={linear: amg}"
exit $((failures > 0))
