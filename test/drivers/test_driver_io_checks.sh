#!/usr/bin/env bash
# The checks every driver makes before it allocates or solves anything, each a bad input (exit
# 2, one line "<program>: ..." on stderr, no result file):
#   - a structured mesh whose memory estimate exceeds the machine's (or --max-memory);
#   - a result path (-o) that is empty, is the case file, the mesh file or the checkpoint to
#     resume from, or where no file can be created;
#   - a case name that is not a plain file name; a gmsh parameter the .geo does not declare;
#   - NaN, negative or out-of-range numeric options; an unknown time unit (the message lists
#     every accepted one); a gas state the velocity grid cannot represent;
# and, at run time: memory running out is one clear line (exit 1); a driver killed while gmsh
# meshes leaves neither gmsh running nor its scratch directory; a --quiet creep run of the held
# switch prints nothing on stderr (no SUNDIALS messages).
#
# Usage: bash test_driver_io_checks.sh <directory of the drivers> <source directory>
set -uo pipefail

BIN=$(cd "$1" && pwd)
SRC="$2"
STATIC="$SRC/cases/cantilever_static/case.yaml"
KIRSCH="$SRC/cases/kirsch_hole/case.yaml"
FIXED="$SRC/cases/creep_fixed_fixed/case.yaml"
HOLD="$SRC/cases/creep_switch_hold/case.yaml"
SWITCH="$SRC/cases/cantilever_switch/case.yaml"
COUETTE="$SRC/cases/gas_couette/case.yaml"

source "$SRC/test/drivers/common.sh"

# bad NAME "needle1|needle2" DRIVER ARGS...: exit 2, one stderr line "<driver>: " holding every
# needle, and nothing left in a fresh output directory (the arguments give -o, or it goes there).
bad() {
  local name="$1" needles="$2" driver="$3"
  shift 3
  local out="$WORK/bad_$name"
  mkdir -p "$out"
  (cd "$out" && timeout 120 "$BIN/$driver" "$@" --quiet >/dev/null 2>"$WORK/$name.err")
  local code=$? ok=1 message
  message=$(cat "$WORK/$name.err")
  [ "$code" -eq 2 ] || { echo "  exit code $code, wanted 2"; ok=0; }
  [ "$(wc -l <"$WORK/$name.err")" -eq 1 ] || { echo "  not one line on stderr"; ok=0; }
  [[ "$message" == "$driver: "* ]] || { echo "  message does not start with '$driver: '"; ok=0; }
  local IFS='|'
  for needle in $needles; do
    [[ "$message" == *"$needle"* ]] || { echo "  message lacks '$needle'"; ok=0; }
  done
  [ -z "$(ls -A "$out")" ] || { echo "  left files: $(ls -A "$out")"; ok=0; }
  if [ "$ok" -eq 1 ]; then pass "$name -> exit 2: $message"; else fail "$name: $message"; fi
}

# ---- the memory estimate of a structured mesh --------------------------------------------
HUGE=(--set "mesh.cells=[1000000, 1000000]")
bad huge_mesh_solid "'mesh.cells'|estimated|MemAvailable" rfmems-solid "$STATIC" "${HUGE[@]}"
bad huge_mesh_pullin "'mesh.cells'|estimated|MemAvailable" rfmems-pullin "$SWITCH" "${HUGE[@]}"
bad huge_mesh_creep "'mesh.cells'|estimated|MemAvailable" rfmems-creep "$FIXED" "${HUGE[@]}"
bad huge_mesh_gas "'mesh.cells'|estimated|MemAvailable" rfmems-gas "$COUETTE" "${HUGE[@]}"
bad max_memory "'mesh.cells'|estimated|more than the 1 MiB|--max-memory" rfmems-solid "$STATIC" \
  --set "mesh.cells=[200, 20]" --max-memory "1 MiB"
bad max_memory_not_a_size "--max-memory" rfmems-solid "$STATIC" --max-memory "lots"
bad max_memory_zero "--max-memory" rfmems-gas "$COUETTE" --max-memory 0
if "$BIN/rfmems-solid" "$STATIC" --set "mesh.cells=[20, 4]" --max-memory "4 GiB" \
    -o "$WORK/fits.h5" --quiet 2>"$WORK/fits.err"; then
  pass "--max-memory '4 GiB' lets a small case run"
else
  fail "--max-memory '4 GiB': $(cat "$WORK/fits.err")"
fi
# A mesh the estimate lets through (limit raised) but the address space cannot hold: the
# allocation fails, and that is one line saying so (exit 1), not a bare std::bad_alloc.
(ulimit -v 400000 && "$BIN/rfmems-solid" "$STATIC" --set "mesh.cells=[4000, 4000]" \
  --max-memory "1 TiB" -o "$WORK/oom.h5" --quiet >/dev/null 2>"$WORK/oom.err")
code=$?
if [ "$code" -eq 1 ] && [ "$(wc -l <"$WORK/oom.err")" -eq 1 ] &&
   grep -q "^rfmems-solid: error: out of memory" "$WORK/oom.err" && [ ! -e "$WORK/oom.h5" ]; then
  pass "out of memory -> exit 1: $(cat "$WORK/oom.err")"
else
  fail "out of memory: exit $code, stderr: $(head -c 400 "$WORK/oom.err")"
fi

# ---- the result path ---------------------------------------------------------------------
mkdir -p "$WORK/inputs"
cp "$STATIC" "$WORK/inputs/static.yaml"
cp "$SRC/cases/kirsch_hole/case.yaml" "$SRC/cases/kirsch_hole/plate_with_hole.geo" "$WORK/inputs/"
cp "$WORK/inputs/static.yaml" "$WORK/inputs/static.orig"
cp "$WORK/inputs/plate_with_hole.geo" "$WORK/inputs/geo.orig"
bad output_is_case "-o|$WORK/inputs/static.yaml|case file" rfmems-solid "$WORK/inputs/static.yaml" \
  -o "$WORK/inputs/static.yaml"
cmp -s "$WORK/inputs/static.yaml" "$WORK/inputs/static.orig" && pass "the case file is intact" \
  || fail "-o case.yaml changed the case file"
bad output_is_case_relative "case file" rfmems-creep "$WORK/inputs/../inputs/static.yaml" \
  -o "$WORK/inputs/static.yaml"
bad output_is_mesh "'mesh.file'|result file" rfmems-solid "$WORK/inputs/case.yaml" \
  -o "$WORK/inputs/plate_with_hole.geo"
cmp -s "$WORK/inputs/plate_with_hole.geo" "$WORK/inputs/geo.orig" && pass "the .geo is intact" \
  || fail "-o mesh.geo changed the mesh file"
bad output_empty "-o|expected a file name" rfmems-solid "$STATIC" -o ""
for driver in rfmems-solid rfmems-pullin rfmems-gas rfmems-creep; do
  case $driver in
    rfmems-solid) c="$STATIC" ;; rfmems-pullin) c="$SWITCH" ;;
    rfmems-gas) c="$COUETTE" ;; rfmems-creep) c="$HOLD" ;;
  esac
  start=$SECONDS
  bad "unwritable_${driver#rfmems-}" "-o|/proc/r.h5|cannot create" "$driver" "$c" -o /proc/r.h5
  [ $((SECONDS - start)) -lt 20 ] && pass "$driver: unwritable -o found before solving" \
    || fail "$driver: unwritable -o took $((SECONDS - start)) s"
done
bad output_is_directory "-o|is a directory" rfmems-gas "$COUETTE" -o "$WORK"
# A checkpoint to resume from that is also the result.
"$BIN/rfmems-creep" "$FIXED" --set creep.outputs=4 --set "creep.end_time=20 h" \
  -o "$WORK/cp.h5" --checkpoint-every-steps 1 --quiet 2>"$WORK/cp.err" \
  || fail "creep run for a checkpoint: $(cat "$WORK/cp.err")"
cp "$WORK/cp.checkpoint.h5" "$WORK/resume.h5"
bad restart_is_output "--restart|$WORK/resume.h5|result file" rfmems-creep "$FIXED" \
  --set creep.outputs=4 --set "creep.end_time=20 h" --restart "$WORK/resume.h5" -o "$WORK/resume.h5"
[ -s "$WORK/resume.h5" ] && pass "the checkpoint is intact" || fail "the checkpoint was removed"

# ---- case keys ---------------------------------------------------------------------------
bad name_with_path "'name' = '../x'|plain" rfmems-solid "$STATIC" --set "name=../x"
bad name_empty "'name'|plain" rfmems-solid "$STATIC" --set "name=''"
bad gmsh_parameter_typo "'mesh.parameters.hh'|declares no parameter 'hh'|h" rfmems-solid \
  "$KIRSCH" --set "mesh.parameters={hh: 0.1}"
bad creep_time_unit "'creep.end_time'|s, ms|min|h|d" rfmems-creep "$FIXED" \
  --set "creep.end_time=5 years"

# A temperature the velocity grid cannot hold: the gas reader's discrete equilibrium fails on
# the input alone.
bad gas_state_off_grid "$COUETTE|velocity_grid" rfmems-gas "$COUETTE" --set initial.T=1e15

# ---- numeric options ---------------------------------------------------------------------
bad every_seconds_nan "--checkpoint-every-seconds|nan" rfmems-creep "$FIXED" \
  --checkpoint-every-seconds nan
bad every_seconds_inf "--checkpoint-every-seconds|inf" rfmems-creep "$FIXED" \
  --checkpoint-every-seconds inf
bad every_steps_negative "--checkpoint-every-steps|-1" rfmems-creep "$FIXED" \
  --checkpoint-every-steps -1
if [ "$(wc -c <"$WORK/every_steps_negative.err")" -lt 200 ]; then
  pass "the checkpoint-step message is short"
else
  fail "the checkpoint-step message: $(cat "$WORK/every_steps_negative.err")"
fi

# ---- a creep life ends quietly -----------------------------------------------------------
if "$BIN/rfmems-creep" "$HOLD" -o "$WORK/hold.h5" --quiet >/dev/null 2>"$WORK/hold.err"; then
  [ ! -s "$WORK/hold.err" ] && pass "creep_switch_hold ends with nothing on stderr" \
    || fail "creep_switch_hold stderr: $(head -c 400 "$WORK/hold.err")"
else
  fail "creep_switch_hold: $(cat "$WORK/hold.err")"
fi

# ---- killed while gmsh meshes ------------------------------------------------------------
if [ -x /usr/bin/gmsh ] || command -v gmsh >/dev/null; then
  for sig in TERM INT HUP; do
    mkdir -p "$WORK/tmp_$sig"
    # Started through exec with SIGINT at its default (a background job's is ignored).
    TMPDIR="$WORK/tmp_$sig" $PY -c 'import os, signal, sys
signal.signal(signal.SIGINT, signal.SIG_DFL)
os.execv(sys.argv[1], sys.argv[1:])' "$BIN/rfmems-solid" "$KIRSCH" --set mesh.parameters.h=0.002 \
      -o "$WORK/killed_$sig.h5" --quiet >/dev/null 2>&1 &
    driver=$!
    gmsh_pid=""
    for _ in $(seq 1 300); do
      # gmsh by name: the driver has other children (MPI's orted).
      gmsh_pid=$(pgrep -P "$driver" -x gmsh || true)
      [ -n "$gmsh_pid" ] && break
      sleep 0.05
    done
    if [ -z "$gmsh_pid" ]; then
      fail "SIG$sig: gmsh never started under the driver"
      kill -KILL "$driver" 2>/dev/null
      continue
    fi
    sleep 0.3  # gmsh is meshing by now
    kill -"$sig" "$driver"
    wait "$driver" 2>/dev/null
    gone=0
    for _ in $(seq 1 50); do
      kill -0 "$gmsh_pid" 2>/dev/null || { gone=1; break; }
      sleep 0.1
    done
    if [ "$gone" -eq 1 ]; then
      pass "SIG$sig while meshing: gmsh ($gmsh_pid) is gone"
    else
      fail "SIG$sig while meshing: gmsh ($gmsh_pid) still runs"
      kill -KILL "$gmsh_pid"
    fi
    # (MPI keeps a session directory of its own there.)
    left=$(find "$WORK/tmp_$sig" -maxdepth 1 -name 'rfmems-mesh-*')
    [ -z "$left" ] && pass "SIG$sig while meshing: no scratch directory left" \
      || fail "SIG$sig while meshing: left $left"
    [ ! -e "$WORK/killed_$sig.h5" ] && pass "SIG$sig: no result file" || fail "SIG$sig: result file"
  done
else
  echo "SKIP: no gmsh"
fi

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
