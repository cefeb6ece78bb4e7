#!/usr/bin/env python3
"""studies/validation/compare.py on a made-up study folder: the means, sample standard deviations
and verdicts it prints equal a hand computation, and the rule uses the larger of the resolution
and the sum of the spreads (docs/study.md, Findings); a case on the reference's own packings is
also compared seed by seed (paired).

    python3 tests/validation/compare_test.py STUDIES_VALIDATION_DIR
"""
import csv
import io
import json
import os
import subprocess
import sys
import tempfile

HEADER = ("case,label,seed,trapdoor_width_m,band_angle_deg,band_angle_left_deg,band_angle_right_deg,"
          "zone_surface_m,zone_mid_height_m,min_load_ratio,min_load_at_over_B,final_load_ratio")


def write_run(root, case, seed, phi, overlap, stress, base_left, complete=True):
    run = os.path.join(root, "cases", case, f"seed-{seed}")
    os.makedirs(os.path.join(run, "analysis"))
    deposit = {"stage": "lowering", "bulk_solid_fraction": phi, "bulk_coordination": 5.0,
               "mean_overlap_of_diameter": overlap, "max_overlap_of_diameter": 10 * overlap, "surface_height_m": 0.05}
    json.dump({"deposits": [dict(deposit, stage="settling"), deposit]}, open(os.path.join(run, "deposit.json"), "w"))
    with open(os.path.join(run, "trapdoor.csv"), "w") as f:
        f.write("time_s,trapdoor_displacement_m,trapdoor_stress_Pa\n0.5,0,%r\n" % stress)
    json.dump({"complete": complete, "particle_steps": 2e9}, open(os.path.join(run, "run.json"), "w"))
    json.dump({"shear_bands": {"left": {"base_angle_deg": base_left}, "right": {"base_angle_deg": -base_left}}},
              open(os.path.join(run, "analysis", "metrics.json"), "w"))


def main():
    script = os.path.join(sys.argv[1], "compare.py")
    with tempfile.TemporaryDirectory(prefix="trapdem-validation-compare-") as root:
        os.makedirs(os.path.join(root, "report"))
        rows = [HEADER,
                # reference: left angles 2, 4 (mean 3, sd 1.414); final loads 0.60, 0.61 (sd 0.00707)
                "reference,paper,1,0.05,1,2,0,0.10,0.07,0.50,0.02,0.60",
                "reference,paper,2,0.05,3,4,2,0.11,0.07,0.52,0.02,0.61",
                # shortcut: left angles 8, 10 (mean 9: 6 apart > 1.414 + 1.414 -> beyond); final loads
                # 0.618, 0.628 (mean 0.623: 0.018 apart, beyond the spreads' 0.0141 but within the
                # load's resolution 0.02 -> within)
                "fast,shortcut,1,0.05,5,8,2,0.10,0.07,0.50,0.02,0.618",
                "fast,shortcut,2,0.05,6,10,2,0.11,0.07,0.52,0.02,0.628",
                # an unfinished run: the report lists it with empty metrics; its folder's partial
                # deposit and cost must not count
                "fast,shortcut,3,,,,,,,,,",
                # paired: the reference's own packings (its deposits below are the reference's):
                # left angles 2.5, 4.5 (effect +0.5 +- 0 against the reference's sd 1.414: within);
                # least loads 0.45, 0.47 (effect -0.05 against max(0.02, 0.0141): beyond)
                "lowering,door 0.1 m/s,1,0.05,1,2.5,0,0.10,0.07,0.45,0.02,0.60",
                "lowering,door 0.1 m/s,2,0.05,3,4.5,2,0.11,0.07,0.47,0.02,0.61",
                # a case none of whose runs has finished (no folder yet): shown as "-", no error
                "unrun,not yet run,1,,,,,,,,,"]
        open(os.path.join(root, "report", "metrics.csv"), "w").write("\n".join(rows) + "\n")
        write_run(root, "reference", 1, 0.600, 1e-5, 27000.0, -10.0)
        write_run(root, "reference", 2, 0.602, 1e-5, 27200.0, -12.0)
        write_run(root, "fast", 1, 0.6005, 4e-4, 27100.0, -10.5)
        write_run(root, "fast", 2, 0.6025, 4e-4, 27300.0, -11.5)
        write_run(root, "fast", 3, 0.7, 1e-2, 1.0, 40.0, complete=False)
        write_run(root, "lowering", 1, 0.600, 1e-5, 27000.0, -10.0)
        write_run(root, "lowering", 2, 0.602, 1e-5, 27200.0, -13.0)
        out = subprocess.run([sys.executable, script, root, "--format", "csv"], check=True,
                             capture_output=True, text=True).stdout
        table = {(r["metric"], r["case"]): r for r in csv.DictReader(io.StringIO(out))}
        markdown = subprocess.run([sys.executable, script, root], check=True, capture_output=True, text=True).stdout
    failures = []

    def expect(metric, case, mean, sd, verdict):
        r = table[(metric, case)]
        if abs(float(r["mean"]) - mean) > 1e-9 or abs(float(r["sd"]) - sd) > 1e-9 or r["verdict"] != verdict:
            failures.append(f"{metric} {case}: got mean {r['mean']} sd {r['sd']} verdict '{r['verdict']}', "
                            f"expected {mean} {sd} '{verdict}'")

    s2 = 2 ** 0.5
    expect("band_left", "reference", 3.0, s2, "")
    expect("band_left", "fast", 9.0, s2, "beyond")
    # 0.623 - 0.605 = 0.018 <= max(0.02, 2 * 0.005 * sqrt(2) = 0.0141): within by the resolution alone
    expect("final_load_ratio", "fast", 0.623, 0.005 * s2, "within")
    # the base angle: means -11 and -11 -> within; the zone at the surface /B: 2.1 and 2.1 -> within
    expect("band_base_left", "fast", -11.0, 0.5 * s2, "within")
    expect("zone_surface_B", "fast", 2.1, 0.01 / 0.05 * s2 / 2, "within")
    # the deposit has no resolution: 0.0005 above the reference's 0.601 with spreads 0.0014 + 0.0014: within;
    # the overlap 4e-2 % against 1e-3 % of d with no spread: beyond
    expect("phi_50g", "fast", 0.6015, 0.001 * s2, "within")
    expect("mean_overlap_pct_d", "fast", 0.04, 0.0, "beyond")
    expect("trapdoor_stress_kPa_at_0", "fast", 27.2, 0.1 * s2, "within")
    if table[("phi_50g", "fast")]["n"] != "2" or table[("particle_steps_1e9", "fast")]["n"] != "2":
        failures.append("the unfinished run was counted: n = " + table[("phi_50g", "fast")]["n"])
    if table[("band_left", "unrun")]["n"] != "0" or "| - |" not in markdown:
        failures.append("a case without a finished run is not shown as '-' (n = %s)" % table[("band_left", "unrun")]["n"])
    if "**beyond**" not in markdown or "| band angle left, deg |" not in markdown:
        failures.append("the markdown table does not mark the left band angle beyond:\n" + markdown)
    def expect_paired(metric, case, effect, sd, verdict):
        r = table[(metric, case)]
        if (r["paired_n"] != "2" or abs(float(r["paired_effect_mean"]) - effect) > 1e-9 or
                abs(float(r["paired_effect_sd"]) - sd) > 1e-9 or r["paired_verdict"] != verdict):
            failures.append(f"{metric} {case} paired: got n {r['paired_n']} effect {r['paired_effect_mean']} sd "
                            f"{r['paired_effect_sd']} '{r['paired_verdict']}', expected {effect} {sd} '{verdict}'")

    expect_paired("band_left", "lowering", 0.5, 0.0, "within")
    expect_paired("min_load_ratio", "lowering", -0.05, 0.0, "beyond")
    # base angles -10, -13 against -10, -12: effects 0 and -1 (mean -0.5, sd 0.707) within max(1, 1.414)
    expect_paired("band_base_left", "lowering", -0.5, 0.5 ** 0.5, "within")
    if table[("band_left", "fast")]["paired_n"] != "":
        failures.append("'fast' (another deposit per seed) was taken as paired with the reference")
    if table[("phi_50g", "lowering")]["paired_n"] != "":
        failures.append("the deposit, equal by construction in a paired case, was given a paired effect")
    if "| band angle left, deg | 1.4 (2) | +0.5 ± 0 (2); within |" not in markdown:
        failures.append("the markdown's paired table lacks the left band's effect:\n" + markdown)
    if failures:
        print("\n".join(failures))
        sys.exit(1)
    print("compare.py: 8 metrics, 3 paired effects and the markdown tables as computed by hand")


if __name__ == "__main__":
    main()
