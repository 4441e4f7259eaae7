#!/usr/bin/env bash
# The drivers under mpirun: `mpirun -np 2 rfmems-pullin` gives the serial answer (the plate is
# solved on the root, the other rank waits), writes one result file, and a bad key still
# exits 2 with the driver's one line (mpirun adds its own notice after it).
#
# Usage: bash test_mpi_drivers.sh <directory of the drivers> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-pullin"
SRC="$2"
PY=/usr/bin/python3
CASE="$SRC/cases/switch_plate/case.yaml"
MPIRUN=(mpirun --allow-run-as-root --oversubscribe -np 2)

WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
source "$SRC/test/drivers/common.sh"

"$DRIVER" "$CASE" --set pull_in.mode=quasi_static -o "$WORK/serial.h5" --json --quiet \
  >"$WORK/serial.json" 2>"$WORK/err" || fail "serial run: $(cat "$WORK/err")"
if "${MPIRUN[@]}" "$DRIVER" "$CASE" --set pull_in.mode=quasi_static -o "$WORK/mpi.h5" --json \
    --quiet >"$WORK/mpi.json" 2>"$WORK/err"; then
  pass "mpirun -np 2 rfmems-pullin exits 0"
else
  fail "mpirun -np 2: $(cat "$WORK/err")"
fi
if $PY - "$WORK/serial.json" "$WORK/mpi.json" <<'PY'
import json, sys
serial, mpi = (json.load(open(f))["pull_in"]["quasi_static"] for f in sys.argv[1:3])
assert serial["pull_in_voltage"] == mpi["pull_in_voltage"], (serial, mpi)
assert serial["pull_in_displacement"] == mpi["pull_in_displacement"], (serial, mpi)
print(f"V_PI serial {serial['pull_in_voltage']:.6f} V, mpirun -np 2 {mpi['pull_in_voltage']:.6f} V")
PY
then pass "same pull-in voltage and displacement on 2 ranks"; else fail "2 ranks differ from serial"; fi
[ -s "$WORK/mpi.h5" ] && pass "one result file" || fail "no result file from the MPI run"

"${MPIRUN[@]}" "$DRIVER" "$CASE" --set pull_in.mode=bogus -o "$WORK/bad.h5" --quiet \
  >/dev/null 2>"$WORK/bad.err"
code=$?
if [ "$code" -eq 2 ] && [ "$(grep -c '^rfmems-pullin: ' "$WORK/bad.err")" -eq 1 ] &&
   grep -q "pull_in.mode" "$WORK/bad.err" && [ ! -e "$WORK/bad.h5" ]; then
  pass "bad key under mpirun -> exit 2, one driver line"
else
  fail "bad key under mpirun: exit $code, $(head -2 "$WORK/bad.err")"
fi
exit $((failures > 0))
