#!/usr/bin/env bash
# The case-key reference: each driver's --help-case lists the keys its readers accept;
# docs/case-reference.md is what python/case_reference.py generates from those lists, and every
# key of every case under cases/ is one its driver declares; every case passes --check (read,
# model built, no solve, no result file) under its driver with the reads compared to the
# declarations (RFMEMS_CHECK_CASE_SCHEMA, set for every driver test).
#
# Usage: bash test_case_reference.sh <directory of the drivers> <source directory>
set -uo pipefail

BIN="$1"
SRC="$2"
source "$SRC/test/drivers/common.sh"
export RFMEMS_CHECK_CASE_SCHEMA=1

for driver in rfmems-solid rfmems-pullin rfmems-gas rfmems-creep rfmems-flow-factor; do
  if "$BIN/$driver" --help-case >"$WORK/$driver.keys" 2>"$WORK/$driver.err" &&
     head -1 "$WORK/$driver.keys" | grep -q "^# Case keys of $driver$" &&
     [ "$(grep -c '^| `' "$WORK/$driver.keys")" -ge 20 ]; then
    pass "$driver --help-case: $(grep -c '^| `' "$WORK/$driver.keys") keys in $(grep -c '^## ' "$WORK/$driver.keys") groups"
  else
    fail "$driver --help-case: $(cat "$WORK/$driver.err")"
  fi
done

if $PY "$SRC/python/case_reference.py" --bin "$BIN" --check >"$WORK/ref.out" 2>"$WORK/ref.err"; then
  pass "case_reference.py --check: $(cat "$WORK/ref.out")"
else
  fail "case_reference.py --check: $(cat "$WORK/ref.err")"
fi

# The check can fail: a page edited by hand, and a case key no driver declares.
mkdir -p "$WORK/copy/python" "$WORK/copy/docs"
cp -r "$SRC/cases" "$SRC/README.md" "$SRC/lib" "$SRC/drivers" "$WORK/copy/"
cp "$SRC/python/case_reference.py" "$WORK/copy/python/"
sed 's/| `mesh.type` | choice |/| `mesh.type` | text |/' "$SRC/docs/case-reference.md" \
  >"$WORK/copy/docs/case-reference.md"
printf 'solver:\n  rtoll: 1e-3\n' >>"$WORK/copy/cases/cantilever_static/case.yaml"
$PY "$WORK/copy/python/case_reference.py" --bin "$BIN" --check >/dev/null 2>"$WORK/drift.err"
code=$?
if [ "$code" -eq 1 ] && grep -q "docs/case-reference.md differs" "$WORK/drift.err" &&
   grep -q "cantilever_static/case.yaml: key 'solver.rtoll' is not in rfmems-solid" "$WORK/drift.err"; then
  pass "an edited page and an undeclared case key -> exit 1"
else
  fail "drift: exit $code, $(cat "$WORK/drift.err")"
fi

# Every case under its README driver: --check exits 0 and writes nothing.
while read -r name driver; do
  "$BIN/rfmems-$driver" "$SRC/cases/$name/case.yaml" --check --quiet -o "$WORK/$name.h5" \
    >/dev/null 2>"$WORK/$name.err"
  code=$?
  if [ "$code" -eq 0 ] && [ ! -e "$WORK/$name.h5" ]; then
    pass "rfmems-$driver cases/$name --check"
  else
    fail "rfmems-$driver cases/$name --check: exit $code, $(cat "$WORK/$name.err")"
  fi
done < <(sed -nE 's/^\| `(\w+)` \(([a-z-]+).*/\1 \2/p' "$SRC/README.md")

# --check still refuses a typo (exit 2, one line).
DRIVER="$BIN/rfmems-solid"
expect_input_error check_typo "unknown key 'solver.rtoll'" \
  "$SRC/cases/cantilever_static/case.yaml" --check --set "solver={rtoll: 1e-3}"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
