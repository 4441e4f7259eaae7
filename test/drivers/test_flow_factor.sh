#!/usr/bin/env bash
# rfmems-flow-factor and the Reynolds film's flow-factor table, end to end:
#  1. three cheap points of cases/flow_factor (Kn = 0.316, 1 and 10, the case's grids, ~2 s)
#     run again: the same Q as the committed table docs/data/flow_factor_bgk.csv (to 1e-5; the
#     run is deterministic), within 0.5 % of the linearised BGK reference
#     (docs/data/flow_factor_bgk_reference.csv) and Veijola's fit within his 5 % of it; the table
#     has the command and the date in its header and no temporary file is left;
#  2. the table it wrote is one the film reads: rfmems-pullin --check on the default switch
#     with gas.rarefaction: table;
#  3. bad input, exit 2 with one line naming the file and the key: a missing and an ill-formed
#     table, a table without rarefaction: table, and a point with Kn <= 0.
#
# Usage: bash test_flow_factor.sh <directory of the drivers> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-flow-factor"
PULLIN="$1/rfmems-pullin"
SRC="$2"
CASE="$SRC/cases/flow_factor/case.yaml"
source "$SRC/test/drivers/common.sh"

POINTS='[{knudsen: 0.316227766, cells: 20, velocity_points: [8, 64, 8]},
         {knudsen: 1, cells: 20, velocity_points: [8, 128, 8]},
         {knudsen: 10, cells: 10, velocity_points: [8, 200, 8]}]'
if "$DRIVER" "$CASE" --set "flow_factor.points=$POINTS" -o "$WORK/table.csv" --json --quiet \
     >"$WORK/run.json" 2>"$WORK/err" &&
   $PY - "$WORK/table.csv" "$WORK/run.json" "$SRC/docs/data" <<'PY'
import csv, json, sys
def rows(path):
    with open(path, newline="") as f:
        return {r["knudsen"]: r for r in csv.DictReader(l for l in f if not l.startswith("#"))}
table, run = rows(sys.argv[1]), json.load(open(sys.argv[2]))
committed = rows(sys.argv[3] + "/flow_factor_bgk.csv")
reference = rows(sys.argv[3] + "/flow_factor_bgk_reference.csv")
header = [l for l in open(sys.argv[1]) if l.startswith("#")]
assert any(l.startswith("# command: rfmems-flow-factor ") for l in header), header
assert any(l.startswith("# date: 20") for l in header), header
assert len(table) == 3 and len(run["points"]) == 3, (table, run)
for kn, r in table.items():
    q = float(r["flow_factor"])
    q_committed = float(committed[kn]["flow_factor"])
    q_ref = float(reference[kn]["flow_factor"])
    q_veijola = 1 + 9.638 * float(kn) ** 1.159
    print(f"Kn = {kn}: Q = {q:.6f}, committed {q_committed:.6f}, linearised BGK {q_ref:.6f} "
          f"({100 * (q / q_ref - 1):+.3f} %), Veijola {q_veijola:.5f} ({100 * (q_veijola / q - 1):+.2f} %)")
    assert abs(q / q_committed - 1) < 1e-5, (kn, q, q_committed)
    assert abs(q / q_ref - 1) < 5e-3, (kn, q, q_ref)
    assert abs(q_veijola / q - 1) < 0.05, (kn, q, q_veijola)
    assert abs(6 * float(r["flow_rate"]) / float(r["delta"]) / q - 1) < 1e-6, r
PY
then
  pass "three points again: the committed table's Q, the linearised BGK reference's to 0.5 %, Veijola's to 5 %"
else
  fail "three points: $(cat "$WORK/err")"
fi
if ls "$WORK"/table.csv.tmp* >/dev/null 2>&1; then fail "a temporary table was left"; fi

# The table written is one the Reynolds film reads (an absolute path; relative ones are to the
# case file).
if "$PULLIN" "$SRC/cases/switch_plate/case.yaml" --check --quiet --set gas.rarefaction=table \
     --set "gas.flow_factor_table=$WORK/table.csv" -o "$WORK/check.h5" >/dev/null 2>"$WORK/err"; then
  pass "rfmems-pullin --check reads the written table"
else
  fail "rfmems-pullin with the written table: $(cat "$WORK/err")"
fi

DRIVER="$PULLIN"
expect_input_error missing_table "gas.flow_factor_table.*nothere.csv: cannot read" \
  "$SRC/cases/switch_plate/case.yaml" --set gas.rarefaction=table \
  --set gas.flow_factor_table=nothere.csv
printf '# bad\nknudsen,flow_factor\n0.1,2.5\n1,oops\n' >"$WORK/bad.csv"
expect_input_error bad_table "gas.flow_factor_table.*bad.csv:4: 'oops' is not a number" \
  "$SRC/cases/switch_plate/case.yaml" --set gas.rarefaction=table \
  --set "gas.flow_factor_table=$WORK/bad.csv"
expect_input_error table_without_choice "gas.flow_factor_table.*only with rarefaction: table" \
  "$SRC/cases/switch_plate/case.yaml" --set "gas.flow_factor_table=$WORK/table.csv"
expect_input_error table_required "missing key 'gas.flow_factor_table'" \
  "$SRC/cases/switch_plate/case.yaml" --set gas.rarefaction=table

DRIVER="$1/rfmems-flow-factor"
expect_input_error bad_point "flow_factor.points.*knudsen" "$CASE" \
  --set "flow_factor.points=[{knudsen: -1, cells: 10, velocity_points: [8, 8, 8]}]"
if [ -e "$WORK/bad_point.csv" ]; then fail "bad input left a table"; fi

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
