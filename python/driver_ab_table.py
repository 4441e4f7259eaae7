#!/usr/bin/env python3
"""The Markdown table of a bench_driver_ab.py run (its JSON lines): per side the median CPU and
the figures it found, and the ratio B / A.

  python3 python/driver_ab_table.py docs/figures/coupling_ab.jsonl
"""
import json
import statistics
import sys


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: driver_ab_table.py RESULTS.jsonl")
    try:
        lines = [json.loads(x) for x in open(sys.argv[1]) if x.strip()]
    except OSError as e:
        sys.exit(f"driver_ab_table.py: {e}")
    runs = [x for x in lines if x.get("bench") == "driver_ab"]
    summary = next(x for x in lines if x.get("bench") == "driver_ab_summary")
    print("| build | runs | median CPU [s] | CPU range [s] | V_qs [V] | V_dyn [V] | t_PI [us] | bisection runs | steps |")
    print("|---|---|---|---|---|---|---|---|---|")
    for side in ("a", "b"):
        r = [x for x in runs if x["side"] == side]
        cpu = [x["cpu_s"] for x in r]
        f = r[0]
        same = all((x["v_qs"], x["v_dyn"], x["t_pi"]) == (f["v_qs"], f["v_dyn"], f["t_pi"]) for x in r)
        print(f"| {f['label']} | {len(r)} | {statistics.median(cpu):.2f} | {min(cpu):.2f}-{max(cpu):.2f} "
              f"| {f['v_qs']:.4f} | {f['v_dyn']:.4f} | {1e6 * f['t_pi']:.4f}{'' if same else ' (varies)'} "
              f"| {f['runs']} | {f['steps']} |")
    print(f"\nCPU ratio {summary['label_b']} / {summary['label_a']}: "
          f"**{summary['ratio_b_over_a']:.3f}** (medians; {summary['date']}).")


if __name__ == "__main__":
    main()
