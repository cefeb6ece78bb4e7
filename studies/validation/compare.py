#!/usr/bin/env python3
"""Each shortcut case of a validation study against its reference case, metric by metric.

    python3 studies/validation/compare.py STUDY_DIR [--reference reference] [--format markdown|csv]

STUDY_DIR is a study folder (or its published copy, scripts/publish-study.sh) whose report has been
written (`trapdem study ... --report-only`): report/metrics.csv gives the mechanism metrics of every
run, each run's deposit.json (`trapdem deposit RUN`) the deposit at 50 g before the trapdoor moves,
its trapdoor.csv the geostatic trapdoor stress, its run.json the cost. For each case and metric it
prints mean +- sample sd (n) and, for every case but the reference, the difference of the means and
the verdict of the study report's trend rule (docs/study.md, Findings): "within" when
|mean_case - mean_ref| <= max(r, sd_case + sd_ref), "beyond" otherwise, with r the quantity's
resolution as the report uses it (band angle 1 deg, zone widths 0.1 B, trapdoor load 0.02 of its
initial value; the ground reaction curve's sampling, 0.1 mm = 0.002 B, for where the least load
occurs) and r = 0 for the deposit and the geostatic stress (the rule is then the spread alone). A
case with one run has sd 0.

Paired cases. A shortcut that acts only after the deposit is made (the lowering rate) runs, on one
thread, on the reference's own packing for the same seed: its deposit is the reference's to the
last digit. Such a case is recognised (every seed both ran has equal deposit metrics and geostatic
stress) and compared run by run as well: the effect of the shortcut is the mean +- sd of the
per-seed differences, free of the packing noise, and its verdict is "within" when
|mean effect| <= max(r, sd_ref), the reference's seed-to-seed spread (the shortcut moves a result
by less than another packing would); a markdown table of its own, columns paired_* in the CSV.
"""
import argparse
import csv
import json
import math
import os
import sys


def mean_sd(values):
    values = [v for v in values if v is not None and not math.isnan(v)]
    n = len(values)
    if n == 0:
        return None, None, 0
    m = sum(values) / n
    sd = math.sqrt(sum((v - m) ** 2 for v in values) / (n - 1)) if n > 1 else 0.0
    return m, sd, n


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def deposit_at_lowering_start(run_dir):
    """The last deposit entry (the lowering's first snapshot, trapdoor at 0, at the test's g)."""
    path = os.path.join(run_dir, "deposit.json")
    if not os.path.exists(path):
        return {}
    deposits = json.load(open(path))["deposits"]
    settled = [d for d in deposits if d["stage"] == "settling"]
    last = deposits[-1]
    out = {
        "phi_50g": last["bulk_solid_fraction"],
        "coordination_50g": last["bulk_coordination"],
        "mean_overlap_pct_d": 100 * last["mean_overlap_of_diameter"],
        "max_overlap_pct_d": 100 * last["max_overlap_of_diameter"],
        "surface_mm": 1000 * last["surface_height_m"],
    }
    if settled:
        out["phi_1g"] = settled[-1]["bulk_solid_fraction"]
    return out


def geostatic_stress(run_dir):
    path = os.path.join(run_dir, "trapdoor.csv")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        first = next(csv.DictReader(f))
    return {"trapdoor_stress_kPa_at_0": number(first["trapdoor_stress_Pa"]) / 1000.0}


def band_bases(run_dir):
    """The bands' angles fitted near the trapdoor edge (analysis/metrics.json, base_angle_deg)."""
    path = os.path.join(run_dir, "analysis", "metrics.json")
    if not os.path.exists(path):
        return {}
    bands = json.load(open(path)).get("shear_bands", {})
    return {f"band_base_{side}": bands.get(side, {}).get("base_angle_deg") for side in ("left", "right")}


def finished(run_dir):
    path = os.path.join(run_dir, "run.json")
    return os.path.exists(path) and json.load(open(path)).get("complete") is True


def cost(run_dir):
    path = os.path.join(run_dir, "run.json")
    if not os.path.exists(path):
        return {}
    run = json.load(open(path))
    return {"particle_steps_1e9": run["particle_steps"] / 1e9}


# (key, label, resolution r of the trend rule, how it is computed from a metrics.csv row; None: from
# the run folder)
METRICS = [
    ("phi_1g", "solid fraction after settling at 1 g", 0.0, None),
    ("phi_50g", "solid fraction at 50 g", 0.0, None),
    ("coordination_50g", "coordination number at 50 g", 0.0, None),
    ("mean_overlap_pct_d", "mean overlap at 50 g, % of d", 0.0, None),
    ("max_overlap_pct_d", "largest overlap at 50 g, % of d", 0.0, None),
    ("surface_mm", "surface height at 50 g, mm", 0.0, None),
    ("trapdoor_stress_kPa_at_0", "trapdoor stress before lowering, kPa", 0.0, None),
    ("min_load_ratio", "least trapdoor load / initial", 0.02, lambda r: number(r["min_load_ratio"])),
    ("min_load_at_over_B", "where: travel / B", 0.002, lambda r: number(r["min_load_at_over_B"])),
    ("final_load_ratio", "trapdoor load at the end / initial", 0.02, lambda r: number(r["final_load_ratio"])),
    ("band_left", "band angle left, deg", 1.0, lambda r: number(r["band_angle_left_deg"])),
    ("band_right", "band angle right, deg", 1.0, lambda r: number(r["band_angle_right_deg"])),
    ("band_mean", "band angle mean of both, deg", 1.0, lambda r: number(r["band_angle_deg"])),
    ("band_base_left", "band angle near the door edge, left, deg", 1.0, None),
    ("band_base_right", "band angle near the door edge, right, deg", 1.0, None),
    ("zone_surface_B", "zone of influence at the surface / B", 0.1,
     lambda r: number(r["zone_surface_m"]) / number(r["trapdoor_width_m"]) if number(r["zone_surface_m"]) else None),
    ("zone_mid_B", "zone of influence at mid-height / B", 0.1,
     lambda r: number(r["zone_mid_height_m"]) / number(r["trapdoor_width_m"]) if number(r["zone_mid_height_m"]) else None),
    ("particle_steps_1e9", "cost, 1e9 particle-steps", 0.0, None),
]


def verdict(diff, sd_case, sd_ref, resolution):
    return "within" if abs(diff) <= max(resolution, sd_case + sd_ref) else "beyond"


# What a shortcut acting after the deposit leaves exactly equal to the reference's run of the same seed.
DEPOSIT_KEYS = ["phi_1g", "phi_50g", "coordination_50g", "mean_overlap_pct_d", "max_overlap_pct_d", "surface_mm",
                "trapdoor_stress_kPa_at_0"]


def paired_seeds(case_runs, reference_runs):
    """The seeds the case shares with the reference if it ran on the reference's own packings (the
    same deposit for every seed both finished, at least two of them), else []."""
    common = sorted(set(case_runs) & set(reference_runs))
    if len(common) < 2:
        return []
    for seed in common:
        for key in DEPOSIT_KEYS:
            a, b = case_runs[seed].get(key), reference_runs[seed].get(key)
            if a is None or b is None or abs(a - b) > 1e-12 * max(abs(a), abs(b), 1e-300):
                return []
    return common


def paired_effect(key, seeds, case_runs, reference_runs):
    diffs = []
    for seed in seeds:
        a, b = case_runs[seed].get(key), reference_runs[seed].get(key)
        if a is not None and b is not None and not math.isnan(a) and not math.isnan(b):
            diffs.append(a - b)
    return mean_sd(diffs)


def paired_verdict(effect, sd_ref, resolution):
    return "within" if abs(effect) <= max(resolution, sd_ref) else "beyond"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("study_dir")
    parser.add_argument("--reference", default="reference")
    parser.add_argument("--format", choices=["markdown", "csv"], default="markdown")
    args = parser.parse_args()
    metrics_csv = os.path.join(args.study_dir, "report", "metrics.csv")
    if not os.path.exists(metrics_csv):
        sys.exit(f"compare.py: {metrics_csv} not found: write the report first (trapdem study ... --report-only)")
    rows = list(csv.DictReader(open(metrics_csv)))
    cases, labels, values, by_seed = [], {}, {}, {}
    for row in rows:
        case = row["case"]
        if case not in labels:
            cases.append(case)
            labels[case] = row["label"]
        seed = row["seed"]
        run_dir = os.path.join(args.study_dir, "cases", case, f"seed-{seed}" if seed else "")
        if not finished(run_dir):
            continue  # the report lists unfinished runs too (empty metrics); their files are partial
        v = {}
        v.update(deposit_at_lowering_start(run_dir))
        v.update(geostatic_stress(run_dir))
        v.update(band_bases(run_dir))
        v.update(cost(run_dir))
        for key, _, _, from_row in METRICS:
            if from_row is not None:
                v[key] = from_row(row)
        values.setdefault(case, []).append(v)
        by_seed.setdefault(case, {})[seed] = v
    if args.reference not in values:
        sys.exit(f"compare.py: no finished run of the reference case '{args.reference}' in {metrics_csv}")

    stats = {c: {k: mean_sd([v.get(k) for v in values.get(c, [])]) for k, _, _, _ in METRICS} for c in cases}
    others = [c for c in cases if c != args.reference]
    reference_runs = by_seed[args.reference]
    paired = {c: paired_seeds(by_seed.get(c, {}), reference_runs) for c in others}
    paired = {c: seeds for c, seeds in paired.items() if seeds}
    if args.format == "csv":
        w = csv.writer(sys.stdout)
        w.writerow(["metric", "case", "n", "mean", "sd", "difference_from_reference", "resolution", "verdict",
                    "paired_n", "paired_effect_mean", "paired_effect_sd", "paired_verdict"])
        for key, _, resolution, _ in METRICS:
            mr, sr, _ = stats[args.reference][key]
            for c in cases:
                m, s, n = stats[c][key]
                diff = m - mr if m is not None and mr is not None and c != args.reference else None
                row = [key, c, n, m, s, diff, resolution, "" if diff is None else verdict(diff, s, sr, resolution)]
                if c in paired and key not in DEPOSIT_KEYS:
                    e, se, ne = paired_effect(key, paired[c], by_seed[c], reference_runs)
                    row += [ne, e, se, "" if e is None or sr is None else paired_verdict(e, sr, resolution)]
                else:
                    row += ["", "", "", ""]
                w.writerow(row)
        return

    def cell(m, s, n):
        return "-" if m is None else f"{m:.3g} ± {s:.2g} ({n})"

    header = ["metric", f"{labels[args.reference]}"] + [f"{labels[c]}: value; difference" for c in others]
    print("| " + " | ".join(header) + " |")
    print("|" + " --- |" * len(header))
    for key, label, resolution, _ in METRICS:
        mr, sr, nr = stats[args.reference][key]
        line = [label, cell(mr, sr, nr)]
        for c in others:
            m, s, n = stats[c][key]
            if m is None or mr is None:
                line.append(cell(m, s, n))
                continue
            diff = m - mr
            v = verdict(diff, s, sr, resolution)
            line.append(f"{cell(m, s, n)}; {diff:+.3g} {'**beyond**' if v == 'beyond' else v}")
        print("| " + " | ".join(line) + " |")
    if not paired:
        return
    print()
    print("Paired with the reference's own packings (the same seed, the same deposit): the shortcut's "
          "effect is the mean ± sd of the per-seed differences, compared with the reference's "
          "seed-to-seed sd.")
    print()
    header = ["metric", f"{labels[args.reference]}: sd between seeds"] + \
             [f"{labels[c]}: effect (seeds {', '.join(paired[c])}); verdict" for c in paired]
    print("| " + " | ".join(header) + " |")
    print("|" + " --- |" * len(header))
    for key, label, resolution, _ in METRICS:
        if key in DEPOSIT_KEYS:
            continue
        mr, sr, nr = stats[args.reference][key]
        line = [label, "-" if sr is None else f"{sr:.2g} ({nr})"]
        for c in paired:
            e, se, ne = paired_effect(key, paired[c], by_seed[c], reference_runs)
            if e is None or sr is None:
                line.append("-")
                continue
            v = paired_verdict(e, sr, resolution)
            line.append(f"{e:+.3g} ± {se:.2g} ({ne}); {'**beyond**' if v == 'beyond' else v}")
        print("| " + " | ".join(line) + " |")


if __name__ == "__main__":
    main()
