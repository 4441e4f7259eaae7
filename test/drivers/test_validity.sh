#!/usr/bin/env bash
# The scene validity report end to end (physics/validity/scene_validity.hpp) through rfmems-pullin:
# the default switch_plate run states its film Knudsen range (lambda/g from the rest gap,
# 67.15 nm / 3.75 um = 0.0179, to the contact gap, 67.15 nm / 75 nm = 0.895) and L/h = 100 in
# the JSON summary's `validity`, with no warning; a film at 10 Pa (Kn 184 at rest, beyond
# Veijola's 880 at the deepest computed gap) and a 45 um thick plate (L/h = 8.9 < 10) print one
# "rfmems-pullin: warning: ..." line each on stderr, listed in the JSON too; --quiet silences
# the stderr lines but not the JSON. rfmems-creep: the plate creep criterion L/h >= 20;
# rfmems-gas: the kinetic Kn range, the velocity grid's cover of the walls and the cell size
# against the mean free path.
#
# Usage: bash test_validity.sh <directory of the drivers> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-pullin"
SRC="$2"
PLATE="$SRC/cases/switch_plate/case.yaml"

source "$SRC/test/drivers/common.sh"

# run NAME ARGS...: the driver with --json; stdout to NAME.json, stderr to NAME.err.
run() {
  local name="$1"
  shift
  if "$DRIVER" "$PLATE" "$@" -o "$WORK/$name.h5" --json >"$WORK/$name.json" 2>"$WORK/$name.err"; then
    pass "$name exits 0"
  else
    fail "$name: $(cat "$WORK/$name.err")"
  fi
}

# check NAME WARNINGS TEXT PYTHON-CONDITION: NAME.err has exactly WARNINGS warning lines (each
# containing TEXT), the JSON lists the same number, and the condition on v (the validity object)
# holds.
check() {
  local name="$1" count="$2" text="$3" condition="$4"
  local lines
  lines=$(grep -c "^rfmems-pullin: warning: .*$text" "$WORK/$name.err")
  local all
  all=$(grep -c "warning" "$WORK/$name.err")
  if [ "$lines" -eq "$count" ] && [ "$all" -eq "$count" ] &&
     $PY -c "import json,sys; v=json.load(open(sys.argv[1]))['validity']; r=v['ranges']
sys.exit(0 if len(v['warnings']) == $count and ($condition) else 1)" "$WORK/$name.json"; then
    pass "$name: $count warning(s) $(head -c 300 "$WORK/$name.err")"
  else
    fail "$name: $lines/$all warning lines (want $count), stderr: $(cat "$WORK/$name.err"), validity: $($PY -c "import json,sys; print(json.load(open(sys.argv[1])).get('validity'))" "$WORK/$name.json" 2>&1)"
  fi
}

run default
# The film's Kn = lambda / g with air's lambda = mu / p0 sqrt(pi R T0 / 2) = 67.15 nm at 1 atm and
# 300 K (mu 1.85e-5 Pa s): over the 3.75 um gap and down to the 75 nm contact gap.
LAMBDA_NM="(1.85e-5 / 101325 * (3.141592653589793 * 287 * 300 / 2) ** 0.5 * 1e9)"
check default 0 "" "abs(r['film_knudsen'][0] - $LAMBDA_NM/3750) < 1e-9 and abs(r['film_knudsen'][1] - $LAMBDA_NM/75) < 1e-3 and r['length_over_thickness'] == [100, 100]"

run low_pressure --set pull_in.mode=quasi_static --set gas.pressure=10Pa
check low_pressure 1 "Veijola's fit range Kn <= 880" "r['film_knudsen'][0] > 180 and r['film_knudsen'][1] > 880"

run thick_plate --set pull_in.mode=quasi_static --set model.thickness=45um
check thick_plate 1 "plate: L/h = 8.89 below 10" "abs(r['length_over_thickness'][0] - 400/45) < 1e-9"

if "$DRIVER" "$PLATE" --set pull_in.mode=quasi_static --set gas.pressure=10Pa -o "$WORK/q.h5" \
    --quiet 2>"$WORK/q.err" >/dev/null && [ ! -s "$WORK/q.err" ]; then
  pass "--quiet prints no warning"
else
  fail "--quiet: $(cat "$WORK/q.err")"
fi

# rfmems-creep: the fixed-fixed creep strip (L = 240 um) at h = 4 um (L/h = 60) has no warning;
# at h = 16 um (L/h = 15 < 20, where the plate's neglected shear creep is 2.5-15 %) one.
CREEP="$1/rfmems-creep"
for h in 4 16; do
  if "$CREEP" "$SRC/cases/creep_fixed_fixed/case.yaml" --set creep.end_time=10h --set creep.outputs=2 \
      --set "model.thickness=${h}um" -o "$WORK/creep$h.h5" --json >"$WORK/creep$h.json" 2>"$WORK/creep$h.err"; then
    want=$([ "$h" = 4 ] && echo 0 || echo 1)
    if [ "$(grep -c "^rfmems-creep: warning: plate creep: L/h = .* below 20" "$WORK/creep$h.err")" -eq "$want" ] &&
       $PY -c "import json,sys; v=json.load(open(sys.argv[1]))['validity']
sys.exit(0 if len(v['warnings']) == $want and v['ranges']['length_over_thickness'][0] == 240 / $h else 1)" "$WORK/creep$h.json"; then
      pass "creep at h = $h um: $want warning(s)"
    else
      fail "creep at h = $h um: stderr $(cat "$WORK/creep$h.err"), $(cat "$WORK/creep$h.json")"
    fi
  else
    fail "creep at h = $h um: $(cat "$WORK/creep$h.err")"
  fi
done

# rfmems-gas: Couette flow at Kn = 0.1 reports the computed field's Kn range (0.1 within
# 0.1 %: the density and temperature barely move at 10 m/s) and no warning with the case's
# 3.5 thermal speeds; a grid of 2 thermal speeds (< 3 + the wall's 10 m/s) warns once.
GAS="$1/rfmems-gas"
for extent in 3.5 2; do
  if "$GAS" "$SRC/cases/gas_couette/case.yaml" --set "mesh.cells=[1, 20]" \
      --set "velocity_grid.extent=$extent" -o "$WORK/gas$extent.h5" --json >"$WORK/gas$extent.json" \
      2>"$WORK/gas$extent.err"; then
    want=$([ "$extent" = 2 ] && echo 1 || echo 0)
    if [ "$(grep -c "^rfmems-gas: warning: kinetic gas: velocity grid half-extent" "$WORK/gas$extent.err")" -eq "$want" ] &&
       $PY -c "import json,sys; v=json.load(open(sys.argv[1]))['validity']; kn=v['ranges']['kinetic_knudsen']
grid = [w for w in v['warnings'] if 'velocity grid' in w]
sys.exit(0 if len(grid) == $want and abs(kn[0] - 0.1) < 1e-4 and abs(kn[1] - 0.1) < 1e-4 else 1)" "$WORK/gas$extent.json"; then
      pass "gas couette, velocity extent $extent: $want warning(s)"
    else
      fail "gas couette, velocity extent $extent: stderr $(cat "$WORK/gas$extent.err"), $(cat "$WORK/gas$extent.json")"
    fi
  else
    fail "gas couette, velocity extent $extent: $(cat "$WORK/gas$extent.err")"
  fi
done

# rfmems-gas: the cell size against the mean free path (Kn = 0.1 over 1 m: lambda = 0.1 m):
# 20 cells (h / (2 lambda) = 0.25) keep the profile inside, but first-order transport warns
# that the wall shear and heat flux may be 25 % off (second order: no warning); 4 cells
# (1.25 > 1: upwinding's numerical viscosity above the physical one) warn once, naming
# mesh.cells.
for run in "20 first_order" "20 second_order" "4 first_order"; do
  read -r cells transport <<<"$run"
  if "$GAS" "$SRC/cases/gas_couette/case.yaml" --set "mesh.cells=[1, $cells]" \
      --set "solver.transport=$transport" \
      -o "$WORK/gash$cells.h5" --json >"$WORK/gash$cells.json" 2>"$WORK/gash$cells.err"; then
    want_profile=$([ "$cells" = 4 ] && echo 1 || echo 0)
    want_wall=$([ "$cells" = 20 ] && [ "$transport" = first_order ] && echo 1 || echo 0)
    if [ "$(grep -c "^rfmems-gas: warning: kinetic gas: cell size .*refine mesh.cells" "$WORK/gash$cells.err")" -eq "$want_profile" ] &&
       [ "$(grep -c "^rfmems-gas: warning: kinetic gas: first-order transport: the wall shear and heat flux may be off by up to h / (2 lambda) = 25 %.*second_order or refine mesh.cells" "$WORK/gash$cells.err")" -eq "$want_wall" ] &&
       $PY -c "import json,sys; v=json.load(open(sys.argv[1]))['validity']; q=v['ranges']['kinetic_upwind_viscosity_ratio']
sys.exit(0 if len(v['warnings']) == $want_profile + $want_wall and abs(q[1] - 1.0 / $cells / 0.2) < 1e-3 * q[1] else 1)" "$WORK/gash$cells.json"; then
      pass "gas couette, $cells cells, $transport: $want_profile cell-size and $want_wall wall-flux warning(s)"
    else
      fail "gas couette, $cells cells, $transport: stderr $(cat "$WORK/gash$cells.err"), $(cat "$WORK/gash$cells.json")"
    fi
  else
    fail "gas couette, $cells cells, $transport: $(cat "$WORK/gash$cells.err")"
  fi
done

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
