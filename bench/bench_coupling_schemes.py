#!/usr/bin/env python3
"""The coupling schemes of the plate + film switch, through rfmems-pullin's transient mode, in one
run: one JSON line per run (scheme, rtol, gas_every, what the run found, its counters and the
CPU of the child process), then one line with the date and the commands.

  python3 bench/bench_coupling_schemes.py --driver build/drivers/rfmems-pullin \\
      --case cases/switch_plate/case.yaml > docs/figures/coupling_schemes.jsonl

Two studies of cases/switch_plate (plate, parallel-plate force, Reynolds film at 1 atm), a 180 V
step from rest:
  deflection   on the coarse 20 x 2 plate to 5 us (before touch-down near 6 us): the centre
               deflection there, monolithic at rtol 1e-6 the reference;
  touch-down   on the case's 40 x 4 plate at its default rtol (1e-3), to 10 us: the pull-in time;
  study        the case's default dynamic study (quasi-static curve, bisection, the pull-in time's
               check, histories, small-signal step) with each scheme.
"""
import argparse
import datetime
import json
import os
import sys
import tempfile

from bench_driver_ab import run_driver

DEFLECTION = [("monolithic", "1e-6", 1), ("monolithic", "1e-5", 1), ("strongly_coupled", "1e-5", 1),
              ("staggered", "1e-5", 1), ("staggered", "1e-5", 2), ("staggered", "1e-5", 4),
              ("monolithic", "1e-3", 1), ("strongly_coupled", "1e-3", 1), ("staggered", "1e-3", 1)]
TOUCH_DOWN = [("monolithic", "1e-6", 1), ("monolithic", "1e-3", 1), ("strongly_coupled", "1e-3", 1),
              ("staggered", "1e-3", 1)]
STUDY = [("monolithic", "1e-3", 1), ("strongly_coupled", "1e-3", 1), ("staggered", "1e-3", 1)]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--driver", required=True)
    ap.add_argument("--case", required=True)
    a = ap.parse_args()
    studies = {
        "deflection": (DEFLECTION, ["mesh.cells=[20, 2]", "pull_in.mode=transient",
                                    "pull_in.transient={voltage: 180 V, end_time: 5 us}"]),
        "touch_down": (TOUCH_DOWN, ["pull_in.mode=transient",
                                    "pull_in.transient={voltage: 180 V, end_time: 10 us}"]),
        "study": (STUDY, ["pull_in.mode=dynamic"]),
    }
    commands = {}
    with tempfile.TemporaryDirectory() as work:
        for study, (rows, common) in studies.items():
            for scheme, rtol, every in rows:
                sets = common + [f"solver.rtol={rtol}", f"coupling.scheme={scheme}"]
                if every != 1:
                    sets.append(f"coupling.gas_every={every}")
                p, cpu, _, cmd = run_driver(a.driver, a.case, sets, os.path.join(work, "run.h5"))
                shown = cmd[:2] + cmd[4:4 + 2 * (len(common) + 1)]
                commands[study] = " ".join(f"'{c}'" if " " in c else c for c in shown) + (
                    " --set solver.rtol=RTOL --set coupling.scheme=SCHEME"
                    " [--set coupling.gas_every=K]")
                line = {"bench": "coupling_schemes", "study": study, "scheme": scheme,
                        "rtol": float(rtol), "gas_every": every, "counters": p["counters"],
                        "cpu_s": cpu, "load": os.getloadavg()[0]}
                if study == "study":
                    d = p["dynamic"]
                    line.update({"v_qs": p["quasi_static"]["pull_in_voltage"],
                                 "v_dyn": d["pull_in_voltage"], "not_pulling_in": d["not_pulling_in"],
                                 "pull_in_time": d["pull_in_time"], "runs": d["runs"],
                                 "steps": d["steps"],
                                 "damping_ratio": d["small_signal"]["damping_ratio"],
                                 "frequency": d["small_signal"]["frequency"],
                                 "pull_in_time_check": d["pull_in_time_check"]["pull_in_time"]})
                else:
                    t = p["transient"]
                    line.update({"final_control": t["final_control"], "pulled_in": t["pulled_in"],
                                 "pull_in_time": t.get("pull_in_time"), "steps": t["steps"],
                                 "residual_evals": t["residual_evals"]})
                print(json.dumps(line), flush=True)
    print(json.dumps({"bench": "coupling_schemes_summary",
                      "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
                      "commands": commands}))


if __name__ == "__main__":
    sys.exit(main())
