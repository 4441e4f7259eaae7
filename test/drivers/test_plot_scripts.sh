#!/usr/bin/env bash
# The plot scripts in python/ given a result file that does not exist: each exits 2 with one
# line on stderr, "<script>: ..." naming the file (bad input, as the drivers), not a traceback.
#
# Usage: bash test_plot_scripts.sh <directory of the drivers> <source directory>
set -uo pipefail

SRC="$2"
source "$SRC/test/drivers/common.sh"

MISSING="$WORK/no_such_result.h5"
for script in "$SRC"/python/plot_*.py; do
  name=$(basename "$script")
  # -o: the scripts that need an output name get one (in WORK); the others take it as a prefix.
  $PY "$script" "$MISSING" -o "$WORK/plot" >/dev/null 2>"$WORK/$name.err"
  code=$?
  if [ "$code" -eq 2 ] && [ "$(wc -l <"$WORK/$name.err")" -eq 1 ] &&
     grep -q "^$name: .*$MISSING" "$WORK/$name.err"; then
    pass "$name: missing file -> exit 2: $(cat "$WORK/$name.err")"
  else
    fail "$name: missing file: exit $code, stderr: $(head -c 400 "$WORK/$name.err")"
  fi
done

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
