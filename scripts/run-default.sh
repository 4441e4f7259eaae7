#!/usr/bin/env bash
# The default run: installs the dependencies, builds the drivers (Release, in build/), and runs
# the main job on the default case: dynamic pull-in of the fixed-fixed RF MEMS switch
# (cases/switch_plate: Mindlin-Reissner plate, parallel-plate electrostatics, Reynolds squeeze
# film at 1 atm), then plots it and prints the pull-in voltages and time.
#
# Outputs (in out/):
#   switch_plate.h5 / .xdmf       deflection at the quasi-static fold, the voltage-deflection
#                                 curve, and the dynamic histories (open the .xdmf in ParaView)
#   switch_plate.json             the run's --json summary
#   switch_plate_curve.png        deflection vs voltage, stable and unstable branches, the fold
#   switch_plate_dynamic.png      centre deflection vs time around the dynamic pull-in voltage
#   switch_plate_forces.png       electrostatic and gas forces vs time
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build build -j"$(nproc)" --target rfmems-pullin rfmems-solid

mkdir -p out
build/drivers/rfmems-pullin cases/switch_plate/case.yaml -o out/switch_plate.h5 --json \
  >out/switch_plate.json
/usr/bin/python3 python/plot_pullin.py out/switch_plate.h5 >/dev/null

/usr/bin/python3 - out/switch_plate.json <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
q, dyn = d["pull_in"]["quasi_static"], d["pull_in"]["dynamic"]
print()
print(f"switch_plate ({d['model']}, {d['mesh']['cells']} cells, parallel-plate electrostatics, "
      f"Reynolds gas at 1 atm), wall time {d['wall_time_s']:.1f} s")
print(f"  quasi-static pull-in voltage: {q['pull_in_voltage']:.2f} V at a centre deflection of "
      f"{100 * q['pull_in_fraction_of_gap']:.1f} % of the gap (thesis, plate, vacuum: 187 V)")
print(f"  dynamic pull-in voltage (step): {dyn['pull_in_voltage']:.2f} V "
      f"({dyn['ratio_to_quasi_static']:.3f} of quasi-static; thesis, vacuum: 171 V)")
check = dyn.get("pull_in_time_check") or {}
estimate = check.get("relative_error_estimate")
print(f"  pull-in time just above it: {1e6 * dyn['pull_in_time']:.2f} us"
      + (f" (error estimate {100 * estimate:.1f} %: {1e6 * check['pull_in_time']:.2f} us at "
         f"{check['tolerance_factor']:g} x the tolerances)" if estimate is not None else "") + "; "
      + ", ".join(f"{h['voltage']:.1f} V: " + (f"{1e6 * h['pull_in_time']:.2f} us" if h["pulled_in"] else "no pull-in")
                  for h in dyn["histories"]))
s = dyn.get("small_signal")
if s:
    print(f"  small-signal response (step to {s['voltage']:.1f} V): damping ratio {s['damping_ratio']:.4f}, "
          f"damped frequency {s['frequency'] / 1e3:.1f} kHz")
PY
echo "  files: out/switch_plate.{h5,xdmf,json}, out/switch_plate_{curve,dynamic,forces}.png"
