#!/usr/bin/env python3
"""The table of run.sh's trapdoor runs from their published files: for each run folder, the settlement
zone's width at mid-height and at the surface (analysis/metrics.json, zone_of_influence, 5 % of the
travel), the least trapdoor load ratio and the travel / B where it occurred, the final load ratio
(trapdoor.csv), and the two shear bands' angles to the vertical with the height each was traced to
(shear_bands; negative leans inward). Usage: python3 summary.py [FOLDER]"""
import csv
import json
import pathlib
import sys

folder = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent)
print("| run | zone at mid-height | zone at the surface | least load (delta/B) | final load | bands (left / right, height traced) |")
print("| --- | --- | --- | --- | --- | --- |")
for run in sorted(p.parent.parent for p in folder.glob("*/analysis/metrics.json")):
    metrics = json.loads((run / "analysis" / "metrics.json").read_text())
    zone, bands, door = metrics["zone_of_influence"], metrics["shear_bands"], metrics["trapdoor"]
    width = door["width_m"]
    rows = list(csv.DictReader(open(run / "trapdoor.csv")))
    least = min(rows, key=lambda r: float(r["trapdoor_stress_ratio"]))
    surface = zone["surface_width_over_B"]

    def band(side):
        b = bands[side]
        return f"{b['angle_deg']:.1f}°" if b.get("angle_deg") is not None else "none"

    print(f"| {run.name} | {zone['mid_height_width_m'] / width:.2f} B | {f'{surface:.2f} B' if surface > 0 else 'none'} | "
          f"{float(least['trapdoor_stress_ratio']):.3f} ({float(least['trapdoor_displacement_m']) / width:.2f}) | "
          f"{float(rows[-1]['trapdoor_stress_ratio']):.3f} | {band('left')} / {band('right')} "
          f"({bands['left']['height_reached_over_B']:.2f} / {bands['right']['height_reached_over_B']:.2f} B) |")
