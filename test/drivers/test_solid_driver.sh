#!/usr/bin/env bash
# Tests of the rfmems-solid command line: a small static run (files, --json, default output
# path), the bad-input contract (exit code 2, exactly one stderr line naming the case file and
# the key or value, no result or temporary file left), a gmsh-meshed case, and a short
# transient that writes several output times. Small meshes and end times keep it under a
# minute.
#
# Usage: bash test_solid_driver.sh <directory of rfmems-solid> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-solid"
SRC="$2"
STATIC="$SRC/cases/cantilever_static/case.yaml"
VIBRATION="$SRC/cases/cantilever_vibration/case.yaml"
SMALL=(--set "mesh.cells=[20,4]")

source "$SRC/test/drivers/common.sh"

# ---- (a) a static run ------------------------------------------------------------------
OUT="$WORK/static"
mkdir -p "$OUT"
if "$DRIVER" "$STATIC" "${SMALL[@]}" -o "$OUT/r.h5" --json --quiet >"$OUT/summary.json" \
    2>"$OUT/stderr"; then
  pass "static run exits 0"
else
  fail "static run exits $? (stderr: $(cat "$OUT/stderr"))"
fi
[ -f "$OUT/r.h5" ] && pass "static run writes r.h5" || fail "no r.h5"
[ -f "$OUT/r.xdmf" ] && pass "static run writes r.xdmf" || fail "no r.xdmf"
if $PY -c '
import json, sys
d = json.load(sys.stdin)
assert d["case"] == "cantilever_static", d["case"]
assert d["analysis"] == "static"
tip = d["probes"]["tip"]
# 20 x 4 cells: within 10 % of P L^3 / (3 E I) = 1e-4 m, downwards.
assert -1.1e-4 < tip["uy"] < -0.9e-4, tip
assert d["solver"]["newton_iterations"] >= 1
assert d["wall_time_s"] > 0
' <"$OUT/summary.json"; then
  pass "--json parses and has the tip probe"
else
  fail "--json output: $(cat "$OUT/summary.json")"
fi
[ ! -s "$OUT/stderr" ] && pass "--quiet static run prints nothing on stderr" \
  || fail "stderr not empty: $(cat "$OUT/stderr")"

# Default output path: out/<case name>.h5 below the working directory.
(cd "$OUT" && "$DRIVER" "$STATIC" "${SMALL[@]}" --quiet >/dev/null 2>&1)
[ -f "$OUT/out/cantilever_static.h5" ] && [ -f "$OUT/out/cantilever_static.xdmf" ] \
  && pass "default output out/cantilever_static.h5" || fail "no out/cantilever_static.h5"

# ---- (b) bad inputs --------------------------------------------------------------------
# expect_input_error NAME CASE "needle1|needle2|..." [driver arguments...]
# Exit code 2, exactly one line on stderr starting "rfmems-solid: " and containing every
# needle, and an empty output directory.
expect_input_error() {
  local name="$1" case_file="$2" needles="$3"
  shift 3
  local out="$WORK/bad_$name"
  mkdir -p "$out"
  "$DRIVER" "$case_file" "$@" -o "$out/r.h5" --quiet >"$WORK/stdout_$name" 2>"$WORK/stderr_$name"
  local code=$?
  local lines
  lines=$(wc -l <"$WORK/stderr_$name")
  local message
  message=$(cat "$WORK/stderr_$name")
  local ok=1
  [ "$code" -eq 2 ] || { echo "  exit code $code, wanted 2"; ok=0; }
  [ "$lines" -eq 1 ] || { echo "  $lines lines on stderr, wanted 1"; ok=0; }
  [[ "$message" == "rfmems-solid: "* ]] || { echo "  message does not start with 'rfmems-solid: '"; ok=0; }
  local IFS='|'
  for needle in $needles; do
    [[ "$message" == *"$needle"* ]] || { echo "  message lacks '$needle'"; ok=0; }
  done
  if [ -n "$(ls -A "$out")" ]; then
    echo "  left files: $(ls -A "$out")"
    ok=0
  fi
  if [ "$ok" -eq 1 ]; then pass "$name -> exit 2: $message"; else fail "$name: $message"; fi
}

expect_input_error unknown_key "$STATIC" "$STATIC|unknown key 'material.Ee'" \
  "${SMALL[@]}" --set material.Ee=3
mkdir -p "$WORK/missing"
sed '/^  E: /d' "$STATIC" >"$WORK/missing/case.yaml"
expect_input_error missing_key "$WORK/missing/case.yaml" \
  "$WORK/missing/case.yaml|missing key 'material.E'" "${SMALL[@]}"
expect_input_error wrong_type "$STATIC" "$STATIC|'mesh.cells'|[a, 4]" --set "mesh.cells=[a,4]"
expect_input_error negative_E "$STATIC" "$STATIC|'material.E' = -1|> 0" "${SMALL[@]}" \
  --set material.E=-1
expect_input_error zero_E "$STATIC" "$STATIC|'material.E' = 0|> 0" "${SMALL[@]}" \
  --set material.E=0
expect_input_error nu "$STATIC" "$STATIC|'material.nu' = 0.7|(-1, 0.5)" "${SMALL[@]}" \
  --set material.nu=0.7
expect_input_error wrong_unit "$STATIC" "$STATIC|'material.E' = '3 m'|pressure" "${SMALL[@]}" \
  --set "material.E=3 m"
expect_input_error patch_without_bc "$STATIC" "$STATIC|'boundaries.bottom'|mesh patch 'bottom'" \
  "${SMALL[@]}" --set "boundaries={left: {type: fixed}, right: {type: free}, top: {type: free}}"
expect_input_error bc_without_patch "$STATIC" "$STATIC|'boundaries.hole'|no patch 'hole'" \
  "${SMALL[@]}" --set "boundaries.hole={type: free}"
expect_input_error missing_mesh_file "$STATIC" "$STATIC|'mesh.file'|nonexistent.msh|no such file" \
  --set "mesh={type: gmsh, file: nonexistent.msh}"
expect_input_error probe_outside "$STATIC" "$STATIC|'probes[0].at'|probe 'tip'" "${SMALL[@]}" \
  --set "probes[0].at=[3 m, 0 m]"
expect_input_error hypothesis_dim "$STATIC" "$STATIC|'model.hypothesis' = '3d'" "${SMALL[@]}" \
  --set model.hypothesis=3d

# A unit square as two triangles of opposite orientation (the second is inverted relative to
# the first), MSH 4.1 as in test/unit/mesh/test_gmsh_reader.cpp.
mkdir -p "$WORK/inverted"
cat >"$WORK/inverted/mixed.msh" <<'EOF'
$MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
1
2 1 "square"
$EndPhysicalNames
$Entities
0 1 1 0
1 0 0 0 1 1 0 1 7 0
1 0 0 0 1 1 0 1 1 0
$EndEntities
$Nodes
1 4 10 40
2 1 0 4
10
20
30
40
0 0 0
1 0 0
1 1 0
0 1 0
$EndNodes
$Elements
2 6 1 9
1 1 1 4
1 10 20
2 20 30
3 30 40
4 40 10
2 1 2 2
7 10 20 30
9 10 40 30
$EndElements
EOF
expect_input_error inverted_cell "$STATIC" "$STATIC|'mesh.file'|$WORK/inverted/mixed.msh|inverted" \
  --set "mesh={type: gmsh, file: $WORK/inverted/mixed.msh}"

expect_input_error missing_case "$WORK/nonexistent.yaml" "$WORK/nonexistent.yaml"
expect_input_error bad_option "$STATIC" "--bogus" --bogus

# ---- a gmsh-meshed case (the .geo is meshed at run time) -------------------------------
OUT="$WORK/kirsch"
mkdir -p "$OUT"
if "$DRIVER" "$SRC/cases/kirsch_hole/case.yaml" --set mesh.parameters.h=0.4 -o "$OUT/r.h5" \
    --json --quiet >"$OUT/summary.json" 2>"$OUT/stderr" \
  && $PY -c '
import json, sys
d = json.load(sys.stdin)
# The hole widens along the load: u_x > 0 at its side, u_y < 0 at its top.
assert d["probes"]["hole_side"]["ux"] > 0 and d["probes"]["hole_top"]["uy"] < 0, d["probes"]
' <"$OUT/summary.json"; then
  pass "kirsch_hole (gmsh .geo) runs"
else
  fail "kirsch_hole: $(cat "$OUT/stderr") $(cat "$OUT/summary.json")"
fi

# ---- (c) a short transient -------------------------------------------------------------
OUT="$WORK/transient"
mkdir -p "$OUT"
if "$DRIVER" "$VIBRATION" "${SMALL[@]}" --set analysis.end_time=5ms \
    --set analysis.output_interval=1ms -o "$OUT/r.h5" --json >"$OUT/summary.json" \
    2>"$OUT/stderr"; then
  pass "transient run exits 0"
else
  fail "transient run exits $? (stderr: $(cat "$OUT/stderr"))"
fi
if $PY -c '
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    times = f["fields/times"][()]
    assert np.allclose(times, [0, 1e-3, 2e-3, 3e-3, 4e-3, 5e-3]), times
    last = "fields/%06d" % (len(times) - 1)
    for name, n in (("displacement", 3), ("velocity", 3), ("stress", 6)):
        assert f[last][name].shape[1] == n, (name, f[last][name].shape)
    tip = f["probes/tip/values"][()]
    assert tip.shape == (6, 3), tip.shape
    assert tip[-1, 1] < 0, tip  # the ramped load pushes the tip down
    assert "case_text" in f["metadata"].attrs and "git_hash" in f["metadata"].attrs
' "$OUT/r.h5"; then
  pass "transient writes 6 output times with displacement, velocity, stress and the probe"
else
  fail "transient output times"
fi
if $PY -c '
import json, sys
d = json.load(sys.stdin)
tip = d["probes"]["tip"]
assert d["analysis"] == "transient" and tip["samples"] == 6 and tip["max_abs_uy"] > 0, d
assert d["solver"]["steps"] > 0 and d["solver"]["residual_evals"] > 0, d["solver"]
' <"$OUT/summary.json"; then
  pass "transient --json has samples, max |u_y| and solver steps"
else
  fail "transient --json: $(cat "$OUT/summary.json")"
fi

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
