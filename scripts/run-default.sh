#!/usr/bin/env bash
# The default run: installs the dependencies, builds rfmems-solid (Release, in build/), runs
# the cantilever vibration case (cases/cantilever_vibration: thesis sec. 2.7.4), plots it and
# prints the tip response with the first natural frequency measured from it.
#
# Outputs (in out/):
#   cantilever_vibration.h5 / .xdmf      fields at every output time (open the .xdmf in ParaView)
#   cantilever_vibration.json            the run's --json summary
#   cantilever_vibration_probes.png      tip displacement vs time
#   cantilever_vibration_deformed.png    deformed shape at the last time, von Mises stress
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build build -j"$(nproc)" --target rfmems-solid

mkdir -p out
build/drivers/rfmems-solid cases/cantilever_vibration/case.yaml -o out/cantilever_vibration.h5 \
  --json >out/cantilever_vibration.json
/usr/bin/python3 python/plot_solid.py out/cantilever_vibration.h5
# The load ramps up over the first 0.02 s; the free vibration is what follows.
frequency=$(/usr/bin/python3 python/probe_frequency.py out/cantilever_vibration.h5 --probe tip \
  --skip 0.02 --json)

/usr/bin/python3 - out/cantilever_vibration.json "$frequency" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
f = json.loads(sys.argv[2])
tip, s = d["probes"]["tip"], d["solver"]
# Euler-Bernoulli first frequency of the case's beam (see its header).
E, rho, L, h = 200e9, 7854.0, 2.0, 0.04
f_eb = 3.516 / (2 * math.pi * L**2) * math.sqrt(E * h**3 / 12 / (rho * h))
print()
print(f"cantilever_vibration: {d['mesh']['cells']} cells, t = 0 .. {d['final_time']:g} s, "
      f"{s['steps']} IDA steps, wall time {d['wall_time_s']:.1f} s")
print(f"  tip u_y at t = {d['final_time']:g} s: {tip['uy']:.4e} m;  max |u_y|: {tip['max_abs_uy']:.4e} m "
      f"(static deflection P L^3/(3EI) = 1.0e-4 m)")
if "frequency_hz" in f:
    print(f"  first frequency from the tip's {f['periods']} periods: {f['frequency_hz']:.4f} Hz "
          f"(Euler-Bernoulli {f_eb:.4f} Hz, {100 * (f['frequency_hz'] / f_eb - 1):+.2f} %)")
PY
echo "  files: out/cantilever_vibration.{h5,xdmf,json}, out/cantilever_vibration_{probes,deformed}.png"
