#!/usr/bin/env python3
"""Two builds of a driver on one case, side by side in one run: the CPU of each (user + system of
the child process, from getrusage) and what each found, alternating A and B so that both see the
same load. One JSON line per run, then one line with the medians and the ratio B / A.

  python3 bench/bench_driver_ab.py --a OLD/rfmems-pullin --a-case OLD/cases/switch_plate/case.yaml \\
      --b build/drivers/rfmems-pullin --b-case cases/switch_plate/case.yaml --repeat 5

The figures read from each summary are the pull-in study's (--json's pull_in: quasi-static and
dynamic pull-in voltages, the pull-in time, the runs and steps of the bisection).
"""
import argparse
import json
import os
import resource
import statistics
import subprocess
import tempfile
import time


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_driver(driver, case, sets, out):
    """One run of rfmems-pullin: its --json summary's pull_in, the child's CPU and wall seconds,
    and the command."""
    cmd = [driver, case, "-o", out, "--json", "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    cpu0, wall0 = child_cpu(), time.time()
    p = subprocess.run(cmd, capture_output=True, text=True, check=True)
    return json.loads(p.stdout)["pull_in"], child_cpu() - cpu0, time.time() - wall0, cmd


def run(driver, case, sets, out):
    j, cpu, wall, _ = run_driver(driver, case, sets, out)
    q, d = j.get("quasi_static", {}), j.get("dynamic", {})
    return {"cpu_s": cpu, "wall_s": wall, "v_qs": q.get("pull_in_voltage"),
            "v_dyn": d.get("pull_in_voltage"), "t_pi": d.get("pull_in_time"),
            "runs": d.get("runs"), "steps": d.get("steps")}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--a", required=True, help="driver A (the baseline)")
    ap.add_argument("--a-case", required=True)
    ap.add_argument("--b", required=True, help="driver B")
    ap.add_argument("--b-case", required=True)
    ap.add_argument("--set", action="append", default=[], help="override for both (repeatable)")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--label-a", default="a")
    ap.add_argument("--label-b", default="b")
    a = ap.parse_args()
    cpu = {"a": [], "b": []}
    with tempfile.TemporaryDirectory() as work:
        for k in range(a.repeat):
            for side, driver, case in (("a", a.a, a.a_case), ("b", a.b, a.b_case)):
                r = run(driver, case, a.set, os.path.join(work, f"{side}.h5"))
                cpu[side].append(r["cpu_s"])
                load = os.getloadavg()[0]
                print(json.dumps({"bench": "driver_ab", "side": side,
                                  "label": a.label_a if side == "a" else a.label_b, "repeat": k,
                                  "case": case, "sets": a.set, "load_average_1min": load, **r}),
                      flush=True)
    ma, mb = statistics.median(cpu["a"]), statistics.median(cpu["b"])
    print(json.dumps({"bench": "driver_ab_summary", "label_a": a.label_a, "label_b": a.label_b,
                      "date": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
                      "repeat": a.repeat, "median_cpu_a_s": ma, "median_cpu_b_s": mb,
                      "ratio_b_over_a": mb / ma}), flush=True)


if __name__ == "__main__":
    main()
