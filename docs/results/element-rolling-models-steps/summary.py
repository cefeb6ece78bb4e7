#!/usr/bin/env python3
"""The table of run.sh's element tests: for each set (the folder name without -seedS), the mean and the
sample standard deviation over its seeds of phi'_peak and phi'_cs (element.json's angles at 50 kPa),
and the largest lateral-stress servo error of its specimens. Usage: python3 summary.py [FOLDER]"""
import json
import pathlib
import re
import statistics
import sys

folder = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent)
sets = {}
for path in sorted(folder.glob("*/element.json")):
    name = re.sub(r"-seed\d+$", "", path.parent.name)
    run = json.loads(path.read_text())
    angles = run["angles"][0]
    servo = max(s["max_lateral_stress_error"] for s in run["specimens"])
    sets.setdefault(name, []).append((angles["phi_peak_deg"], angles["phi_cs_deg"], servo, run["time_step_s"]))


def mean_sd(values):
    return f"{statistics.mean(values):.1f} ± {statistics.stdev(values):.1f}" if len(values) > 1 else f"{values[0]:.1f}"


print("| set | time step (s) | specimens | phi'_peak (deg) | phi'_cs (deg) | largest servo error |")
print("| --- | --- | --- | --- | --- | --- |")
for name, runs in sets.items():
    peak, cs, servo, step = zip(*runs)
    print(f"| {name} | {step[0]:.3g} | {len(runs)} | {mean_sd(peak)} | {mean_sd(cs)} | {100 * max(servo):.1f} % |")
