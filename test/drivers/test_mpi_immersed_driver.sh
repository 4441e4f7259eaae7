#!/usr/bin/env bash
# `mpirun -np 2 / 3 rfmems-pullin` on the immersed cantilever switch with the ESBGK gas (
# "runs under MPI and serially; the same answer"): the gas is distributed over the ranks, the
# rest is computed on every rank from the same data, the root writes the one result file.
# Coarse scene (45 x 3 beam, 76 x 26 background, 6^3 velocities, gas step residual 1e-8), 80 V
# step for 20 ns: the same number of structural steps as the serial run, the tip-deflection
# history (/dynamic/transient in the result file) equal to 1e-6 of its largest value, the gas
# force history to 1e-7 of p0 times the beam's perimeter (the step tolerance is relative to
# the whole distribution); one result file and no scratch file of the other ranks left; a bad
# key under mpirun still exits 2 with one driver line. The ESBGK run's scene report carries
# none of the Reynolds film's warnings.
#
# Usage: bash test_mpi_immersed_driver.sh <directory of the drivers> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-pullin"
SRC="$2"
CASE="$SRC/cases/cantilever_switch/case.yaml"
ARGS=(--set "mesh.cells=[45, 3]" --set "actuation.immersed.background.cells=[76, 26]" --set gas.model=esbgk
      --set gas.velocities=6 --set gas.step_tolerance=1e-8 --set pull_in.mode=transient
      --set pull_in.transient.voltage=80V --set pull_in.transient.end_time=0.02us
      --set pull_in.transient.output_interval=1ns --json --quiet)

source "$SRC/test/drivers/common.sh"

"$DRIVER" "$CASE" "${ARGS[@]}" -o "$WORK/serial.h5" >"$WORK/serial.json" 2>"$WORK/err" ||
  fail "serial run: $(cat "$WORK/err")"
# The scene report names the chosen gas's limits only: no Reynolds-film warning for ESBGK.
if $PY - "$WORK/serial.json" <<'PY'
import json, sys
warnings = json.load(open(sys.argv[1]))["validity"]["warnings"]
assert not any("Reynolds" in w for w in warnings), warnings
PY
then pass "ESBGK run: no Reynolds-film validity warning"; else fail "ESBGK run warns about the film"; fi
for n in 2 3; do
  mkdir -p "$WORK/np$n"
  if mpirun --allow-run-as-root --oversubscribe --bind-to none -np $n "$DRIVER" "$CASE" \
      "${ARGS[@]}" -o "$WORK/np$n/mpi.h5" >"$WORK/np$n.json" 2>"$WORK/err"; then
    pass "mpirun -np $n rfmems-pullin (gas esbgk) exits 0"
  else
    fail "mpirun -np $n: $(cat "$WORK/err")"
    continue
  fi
  files=$(ls "$WORK/np$n")
  [ "$files" = "$(printf 'mpi.h5\nmpi.xdmf')" ] && pass "np $n: one result file (+ xdmf), no rank scratch" ||
    fail "np $n: files left: $files"
  if $PY - "$WORK/serial" "$WORK/np$n/mpi" "$WORK/np$n.json" <<'PY'
import json, sys
import h5py, numpy as np
serial = json.load(open(sys.argv[1] + ".json"))["pull_in"]
mpi = json.load(open(sys.argv[3]))["pull_in"]
assert serial["transient"]["steps"] == mpi["transient"]["steps"], (serial["transient"], mpi["transient"])
with h5py.File(sys.argv[1] + ".h5") as a, h5py.File(sys.argv[2] + ".h5") as b:
    ta, va = a["dynamic/transient/time"][:], a["dynamic/transient/values"][:]
    tb, vb = b["dynamic/transient/time"][:], b["dynamic/transient/values"][:]
assert ta.shape == tb.shape and np.array_equal(ta, tb), (ta.shape, tb.shape)
d_tip = np.max(np.abs(va[:, 0] - vb[:, 0])) / np.max(np.abs(va[:, 0]))
perimeter = 2 * (45e-6 + 1.5e-6)
d_gas = np.max(np.abs(va[:, 3] - vb[:, 3])) / (1.36e4 * perimeter)
print(f"{len(ta)} samples, {mpi['transient']['steps']} steps: tip {va[-1, 0]:.6e} m, "
      f"history to {d_tip:.2e} of its largest value; gas force to {d_gas:.2e} of p0 x perimeter")
assert d_tip <= 1e-6 and d_gas <= 1e-7, (d_tip, d_gas)
PY
  then pass "np $n: same steps, tip deflection and gas force histories as serial"
  else fail "np $n differs from serial"; fi
done

expect_mpi_input_error bad_gas_key "smoother" 2 "$CASE" --set gas.model=esbgk \
  --set gas.smoother=jacobi
# The IDA stepper is serial: asked for on 2 ranks, bad input naming gas.stepper.
expect_mpi_input_error ida_stepper "gas.stepper" 2 "$CASE" --set gas.model=esbgk \
  --set gas.stepper=ida

exit $((failures > 0))
