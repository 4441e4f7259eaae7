# Shared by the driver tests (sourced, not run): the scratch directory WORK (removed on exit),
# the Python PY, PASS/FAIL counting and the bad-input contract. The sourcing script sets
# DRIVER (the program).
PY=/usr/bin/python3
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
failures=0
pass() { echo "PASS: $1"; }
fail() { echo "FAIL: $1"; failures=$((failures + 1)); }

# expect_input_error NAME TEXT ARGS...: the driver run with ARGS exits 2 with exactly one line
# on stderr, "<program>: ..." containing TEXT, and leaves no result file.
expect_input_error() {
  local name="$1" text="$2"
  shift 2
  "$DRIVER" "$@" -o "$WORK/$name.h5" --quiet >/dev/null 2>"$WORK/$name.err"
  local code=$?
  if [ "$code" -eq 2 ] && [ "$(wc -l <"$WORK/$name.err")" -eq 1 ] &&
     grep -q -- "^$(basename "$DRIVER"): .*$text" "$WORK/$name.err" && [ ! -e "$WORK/$name.h5" ]; then
    pass "$name -> exit 2: $(cat "$WORK/$name.err")"
  else
    fail "$name: exit $code, stderr: $(cat "$WORK/$name.err")"
  fi
}

# expect_mpi_input_error NAME TEXT RANKS ARGS...: the same under mpirun on RANKS ranks: exit 2,
# exactly one "<program>: " line containing TEXT (mpirun adds its own notice after it), no
# result file.
expect_mpi_input_error() {
  local name="$1" text="$2" ranks="$3"
  shift 3
  mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$DRIVER" "$@" -o "$WORK/$name.h5" \
    --quiet >/dev/null 2>"$WORK/$name.err"
  local code=$?
  local program
  program=$(basename "$DRIVER")
  if [ "$code" -eq 2 ] && [ "$(grep -c "^$program: " "$WORK/$name.err")" -eq 1 ] &&
     grep -q -- "^$program: .*$text" "$WORK/$name.err" && [ ! -e "$WORK/$name.h5" ]; then
    pass "$name on $ranks ranks -> exit 2: $(grep "^$program: " "$WORK/$name.err")"
  else
    fail "$name on $ranks ranks: exit $code, $(head -2 "$WORK/$name.err")"
  fi
}

# expect_json_run NAME TEXT ARGS...: the driver run with ARGS writes $WORK/NAME.h5 and its
# --json summary $WORK/NAME.json, and exits 0 ("TEXT exits 0"; else the failure with stderr).
expect_json_run() {
  local name="$1" text="$2"
  shift 2
  if "$DRIVER" "$@" -o "$WORK/$name.h5" --json --quiet >"$WORK/$name.json" 2>"$WORK/err"; then
    pass "$text exits 0"
  else
    fail "$text: $(cat "$WORK/err")"
  fi
}
