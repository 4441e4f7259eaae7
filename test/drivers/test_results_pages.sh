#!/usr/bin/env bash
# The results pages (docs/*.md): every table between <!-- table: NAME --> and <!-- end table -->
# is what python/results_pages.py generates from the raw data under docs/data/ and
# docs/figures/, so that a page cannot drift from its data; a changed data file makes --check
# fail naming the page and the table; and every page the docs link to exists.
#
# Usage: bash test_results_pages.sh <directory of the drivers (unused)> <source directory>
set -uo pipefail

SRC="$2"
source "$SRC/test/drivers/common.sh"

if $PY "$SRC/python/results_pages.py" --check >"$WORK/check.out" 2>"$WORK/check.err"; then
  pass "results_pages.py --check: $(cat "$WORK/check.out")"
else
  fail "results_pages.py --check: $(cat "$WORK/check.err")"
fi

# A copy with one number changed in a data file: --check exits 1 naming the page and table.
mkdir -p "$WORK/copy/python"
cp -r "$SRC/docs" "$WORK/copy/docs"
cp "$SRC/python/results_pages.py" "$WORK/copy/python/"
sed -i 's/^10,16\.76 %/10,16.77 %/' "$WORK/copy/docs/data/creep_plate_vs_continuum.csv"
$PY "$WORK/copy/python/results_pages.py" --check >/dev/null 2>"$WORK/drift.err"
code=$?
if [ "$code" -eq 1 ] && grep -q "creep.md: table 'creep-plate-vs-continuum' differs" "$WORK/drift.err"; then
  pass "a changed data file -> exit 1: $(cat "$WORK/drift.err")"
else
  fail "a changed data file: exit $code, stderr: $(cat "$WORK/drift.err")"
fi
# Regenerating restores the match.
$PY "$WORK/copy/python/results_pages.py" && $PY "$WORK/copy/python/results_pages.py" --check >/dev/null 2>&1 &&
  grep -q "16.77 %" "$WORK/copy/docs/creep.md" && pass "regenerated page carries the new number" ||
  fail "regenerating did not bring the page to its data"

# A marker naming no table is an error.
printf '<!-- table: no-such-table -->\n<!-- end table -->\n' >>"$WORK/copy/docs/mpi.md"
$PY "$WORK/copy/python/results_pages.py" --check >/dev/null 2>"$WORK/unknown.err"
code=$?
if [ "$code" -eq 1 ] && grep -q "mpi.md: table 'no-such-table'" "$WORK/unknown.err"; then
  pass "unknown table -> exit 1"
else
  fail "unknown table: exit $code, stderr: $(cat "$WORK/unknown.err")"
fi

# Every docs page linked from README.md and docs/*.md exists.
missing=$(cd "$SRC" && grep -ohE '\]\((docs/)?[A-Za-z_-]+\.md' README.md docs/*.md |
  sed -E 's/^\]\(//' | sort -u | while read -r link; do
    case "$link" in docs/*) f="$link" ;; README.md) f="README.md" ;; *) f="docs/$link" ;; esac
    [ -e "$f" ] || echo "$link"
  done)
if [ -z "$missing" ]; then
  pass "every linked page exists"
else
  fail "linked pages missing: $missing"
fi

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
