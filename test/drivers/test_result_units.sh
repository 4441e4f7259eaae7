#!/usr/bin/env bash
# Every result file states its units: each cell field (/fields/<step>/<name>) carries a
# non-empty "units" attribute, each time series its abscissa's and one unit per component of
# its values, for a run of each driver (the plane and the plate structure, the kinetic gas, a
# pull-in transient with its force histories, a creep run with probe columns). The units are
# those of io/quantity_units.cpp; spot checks: displacement m, stress Pa, temperature K, the
# plate's forces N.
#
# Usage: bash test_result_units.sh <directory of the drivers> <source directory>
set -uo pipefail
SRC="$2"
DRIVER="$1/rfmems-solid"
source "$SRC/test/drivers/common.sh"

check_units() {  # check_units FILE EXPECTED...: EXPECTED as dataset=unit (first component)
  $PY - "$@" <<'PY'
import sys
import h5py
path, expected = sys.argv[1], dict(a.split("=", 1) for a in sys.argv[2:])
missing, seen = [], {}
def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)
with h5py.File(path, "r") as f:
    def visit(name, obj):
        if not isinstance(obj, h5py.Dataset) or name.startswith(("mesh", "metadata")):
            return
        if name in ("fields/times", "fields/steps") or name.endswith("final_state/values"):
            return
        u = obj.attrs.get("units")
        if u is None:
            missing.append(name)
            return
        units = [text(x) for x in u] if not isinstance(u, (str, bytes)) else [text(u)]
        if any(x == "" for x in units):
            missing.append(f"{name} {units}")
        seen[name.split("/")[-1] if name.startswith("fields/") else name] = units
    f.visititems(visit)
for key, unit in expected.items():
    if seen.get(key, [None])[0] != unit:
        missing.append(f"{key}: {seen.get(key)} instead of {unit}")
print(f"{path.rsplit('/', 1)[-1]}: {len(seen)} datasets with units" +
      (f"; wrong or missing: {missing}" if missing else ""))
sys.exit(1 if missing else 0)
PY
}

run() {  # run NAME DRIVER ARGS...
  local name="$1" program="$2"
  shift 2
  "$program" "$@" -o "$WORK/$name.h5" --quiet >/dev/null 2>"$WORK/err" ||
    fail "$name: $(cat "$WORK/err")"
}

run solid "$1/rfmems-solid" "$SRC/cases/cantilever_vibration/case.yaml" \
  --set "mesh.cells=[20, 2]" --set analysis.end_time=5ms --set analysis.output_interval=2.5ms
check_units "$WORK/solid.h5" displacement=m velocity=m/s stress=Pa probes/tip/time=s \
  probes/tip/values=m && pass "rfmems-solid: every dataset has units" || fail "rfmems-solid units"

run plate "$1/rfmems-solid" "$SRC/cases/clamped_plate/case.yaml" --set "mesh.cells=[8, 8]"
check_units "$WORK/plate.h5" deflection=m rotation=rad moment=N shear_force=N/m &&
  pass "rfmems-solid plate: every dataset has units" || fail "rfmems-solid plate units"

run gas "$1/rfmems-gas" "$SRC/cases/gas_couette/case.yaml" --set "velocity_grid.points=[6, 6, 6]"
check_units "$WORK/gas.h5" density=kg/m^3 velocity=m/s temperature=K pressure=Pa \
  heat_flux=W/m^2 solver/residual/iteration=1 &&
  pass "rfmems-gas: every dataset has units" || fail "rfmems-gas units"

run pullin "$1/rfmems-pullin" "$SRC/cases/switch_plate/case.yaml" --set pull_in.mode=transient \
  --set "pull_in.transient={voltage: 150 V, end_time: 2 us}" --set "mesh.cells=[20, 6]"
check_units "$WORK/pullin.h5" dynamic/transient/time=s dynamic/transient/values=m &&
  $PY -c "import h5py,sys; u=[x.decode() if isinstance(x, bytes) else x for x in h5py.File(sys.argv[1])['dynamic/transient/values'].attrs['units']]; assert u == ['m', 'm', 'N', 'N', 'N', 'V'], u" "$WORK/pullin.h5" &&
  pass "rfmems-pullin: every dataset has units, the plate's forces in N" || fail "rfmems-pullin units"

run creep "$1/rfmems-creep" "$SRC/cases/creep_switch_hold/case.yaml" --set creep.end_time=1h
check_units "$WORK/creep.h5" creep/history/time=s plastic_moment=N creep_strain=1 &&
  pass "rfmems-creep: every dataset has units" || fail "rfmems-creep units"

exit $((failures > 0))
