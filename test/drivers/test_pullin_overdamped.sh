#!/usr/bin/env bash
# rfmems-pullin on an overdamped switch (cases/switch_plate_damped at 10 atm over a 1.5 um gap,
# 20 x 6 cells: small-signal zeta ~1.7; docs/pull-in.md, "Bisection end rules"): the bisection's
# answer no longer depends on end_time. Runs between V_dyn and V_qs creep past the fold for
# hundreds of microseconds; before the past-fold rule (coupling/past_unstable_equilibrium.hpp)
# a 50 us window counted them "no pull-in" and gave (54.73, 54.88] V = 1.134 V_qs, a 1000 us
# window (48.55, 48.69] V. With it both windows give the same bracket, and it holds V_qs: for
# zeta >> 1 (the film damps still harder near the fold) V_dyn tends to V_qs. The runs below
# V_qs settle (settled_at_rest.hpp), those above end past the fold.
#
# Usage: bash test_pullin_overdamped.sh <directory of rfmems-pullin> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-pullin"
SRC="$2"
CASE="$SRC/cases/switch_plate_damped/case.yaml"
SCENE=(--set gas.pressure=10atm --set actuation.gap=1.5um --set "mesh.cells=[20, 6]"
       --set "pull_in.dynamic.bracket=[38 V, 56 V]" --set pull_in.dynamic.tolerance=0.25V
       --set "pull_in.dynamic.voltages=[40 V]")

source "$SRC/test/drivers/common.sh"

for t in 50 1000; do
  expect_json_run "t$t" "overdamped bisection, end_time $t us," "$CASE" "${SCENE[@]}" \
    --set "pull_in.dynamic.end_time=$t us"
done

if $PY - "$WORK/t50.json" "$WORK/t1000.json" <<'PY'
import json, sys
short, long = (json.load(open(f))["pull_in"] for f in sys.argv[1:3])
a, b = short["dynamic"], long["dynamic"]
v_qs = long["quasi_static"]["pull_in_voltage"]
# The same bracket from both windows, holding V_qs.
assert (a["not_pulling_in"], a["pull_in_voltage"]) == (b["not_pulling_in"], b["pull_in_voltage"]), (a, b)
assert b["not_pulling_in"] < v_qs <= b["pull_in_voltage"], (v_qs, b)
ratio = b["pull_in_voltage"] / v_qs
assert 1.0 <= ratio < 1.0 + 0.25 / v_qs, ratio
# The early ends did the deciding: settled below V_qs (with the long window), past the fold above.
assert b["settled_runs"] > 0 and a["past_fold_runs"] > 0 and b["past_fold_runs"] > 0, (a, b)
zeta = b["small_signal"]["damping_ratio"]
assert 1.4 < zeta < 2.0 and b["small_signal"]["fit_residual"] < 0.01, b["small_signal"]
print(f"V_dyn in ({b['not_pulling_in']:.4f}, {b['pull_in_voltage']:.4f}] V with 50 and 1000 us, "
      f"V_qs {v_qs:.4f} V (upper end / V_qs {ratio:.5f}); zeta {zeta:.3f}; runs {a['runs']} / "
      f"{b['runs']}, settled {a['settled_runs']} / {b['settled_runs']}, past the fold "
      f"{a['past_fold_runs']} / {b['past_fold_runs']}")
PY
then
  pass "V_dyn independent of end_time, at V_qs"
else
  fail "overdamped figures"
fi

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
