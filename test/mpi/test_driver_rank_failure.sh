#!/usr/bin/env bash
# A failure on one rank while the others are inside a collective ends the whole mpirun job
# with exit 1 and the failing rank's one line, within seconds (before the fix it hung until
# ctest's timeout). Serially the same program exits 1 with the same line.
#
# Usage: bash test_driver_rank_failure.sh <driver_rank_failure program> <source directory>
set -uo pipefail
PROGRAM="$1"
CASE="$2/cases/switch_plate/case.yaml"
source "$2/test/drivers/common.sh"

for ranks in 1 2 3; do
  start=$(date +%s)
  timeout 60 mpirun --allow-run-as-root --oversubscribe --bind-to none -np "$ranks" \
    "$PROGRAM" "$CASE" >"$WORK/out" 2>"$WORK/err"
  code=$?
  seconds=$(( $(date +%s) - start ))
  last=$((ranks - 1))
  if [ "$code" -eq 1 ] && grep -q "^driver_rank_failure: error: injected failure on rank $last$" "$WORK/err"; then
    pass "$ranks rank(s): exit 1 in ${seconds} s with the failing rank's line"
  else
    fail "$ranks rank(s): exit $code after ${seconds} s (124 = hung), stderr: $(cat "$WORK/err")"
  fi
done
exit "$failures"
