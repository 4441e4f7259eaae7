#!/usr/bin/env bash
# rfmems-pullin, dynamic mode on a laplace case (coupling/field_coupled_structure.hpp): the
# coarse 25 x 2 plane beam of cases/switch_plane_laplace under the Laplace field recomputed per
# IDA step exits 0, reports V_dyn with a ratio to the quasi-static V_PI near the thesis's 0.91,
# says in the JSON and the result file's metadata that the dynamic study used the Laplace field
# (staggered), and writes the histories; a single transient at a history's voltage runs the
# same Laplace field (its peak is the history's); what the field cannot do is bad input
# (exit 2).
#
# Usage: bash test_pullin_laplace_dynamic.sh <directory of rfmems-pullin> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-pullin"
SRC="$2"
PLANE="$SRC/cases/switch_plane_laplace/case.yaml"
PLATE="$SRC/cases/switch_plate/case.yaml"

source "$SRC/test/drivers/common.sh"

# Coarse beam (two cells through the thickness: V_PI ~550 V), per-kind error weights at
# rtol 1e-4 with this beam's first frequency (~385 kHz), bisection to 2 V.
COARSE=(--set "mesh.cells=[25,2]" --set actuation.laplace.gap_cells=4 --set pull_in.mode=dynamic
        --set "pull_in.dynamic={end_time: 20 us, tolerance: 2 V, small_signal: 0.2}"
        --set "solver={rtol: 1e-4, error_weights: per_kind, velocity_frequency: 385 kHz}")
if "$DRIVER" "$PLANE" "${COARSE[@]}" -o "$WORK/dyn.h5" --json --quiet >"$WORK/dyn.json" \
    2>"$WORK/err"; then
  pass "switch_plane_laplace 25 x 2, dynamic, exits 0"
else
  fail "switch_plane_laplace dynamic: $(cat "$WORK/err")"
fi
if $PY - "$WORK/dyn.json" "$WORK/dyn.h5" <<'PY'
import json, sys
import h5py
d = json.load(open(sys.argv[1]))["pull_in"]
dyn, qs = d["dynamic"], d["quasi_static"]
assert d["electrostatics"] == "laplace", d
assert d["coupling"]["scheme"] == "staggered", d
assert d["counters"]["field_solves"] > dyn["steps"], d  # one field solve per accepted step at least
assert dyn["pull_in_voltage"] - dyn["not_pulling_in"] <= 2.0, dyn
assert abs(dyn["ratio_to_quasi_static"] - 0.91) < 0.02, dyn
assert dyn["pull_in_time"] > 0
h = dyn["histories"]
assert len(h) == 2 and not h[0]["pulled_in"] and h[1]["pulled_in"], h
assert dyn["small_signal"]["log_decrement"]["swings"] >= 3 and dyn["small_signal"]["damping_ratio"] < 0.01, dyn
with h5py.File(sys.argv[2]) as f:
    meta = f["metadata"].attrs
    text = lambda k: meta[k].decode() if isinstance(meta[k], bytes) else meta[k]
    assert text("electrostatics") == "laplace", dict(meta)
    assert "V0" in f["dynamic"] and "small_signal" in f["dynamic"], list(f["dynamic"])
print(f"V_qs {qs['pull_in_voltage']:.2f} V, V_dyn {dyn['pull_in_voltage']:.2f} V, ratio "
      f"{dyn['ratio_to_quasi_static']:.4f}, {dyn['runs']} runs, {d['counters']['field_solves']} field solves")
PY
then
  pass "V_dyn, ratio, electrostatics in JSON and metadata, histories"
else
  fail "laplace dynamic figures"
fi

# The single transient at the lower history's voltage (0.97 V_dyn) to the same end time: the
# same Laplace field and stepping, so the same peak (a parallel-plate run would miss it by
# percent).
V=$($PY -c "import json,sys; print(repr(json.load(open(sys.argv[1]))['pull_in']['dynamic']['histories'][0]['voltage']))" "$WORK/dyn.json")
if "$DRIVER" "$PLANE" "${COARSE[@]}" --set pull_in.mode=transient \
    --set "pull_in.transient={voltage: $V, end_time: 20 us}" -o "$WORK/tr.h5" --json --quiet \
    >"$WORK/tr.json" 2>"$WORK/err" &&
  $PY - "$WORK/dyn.json" "$WORK/tr.json" <<'PY'
import json, sys
h = json.load(open(sys.argv[1]))["pull_in"]["dynamic"]["histories"][0]
p = json.load(open(sys.argv[2]))["pull_in"]
t = p["transient"]
assert p["electrostatics"] == "laplace" and p["coupling"]["scheme"] == "staggered", p
assert not t["pulled_in"] and abs(t["extreme_control"] / h["extreme_control"] - 1) < 1e-6, (t, h)
print(f"transient peak {t['extreme_control']:.6e} m, history {h['extreme_control']:.6e} m")
PY
then
  pass "the Laplace transient runs the Laplace field: its peak is the dynamic study's history's"
else
  fail "Laplace transient: $(cat "$WORK/err")"
fi

expect_input_error laplace_coupling_old_key "coupling.scheme" "$PLATE" \
  --set pull_in.dynamic.laplace_coupling=implicit
expect_input_error laplace_ramp "the laplace field takes a step voltage only" "$PLANE" \
  "${COARSE[@]}" --set "pull_in.dynamic.waveform={type: ramp, rise_time: 1 us}"
expect_input_error laplace_monolithic "coupling.scheme' = 'monolithic': .*allowed: staggered | implicit" \
  "$PLANE" "${COARSE[@]}" --set "coupling={scheme: monolithic}"

exit $((failures > 0))
