#!/usr/bin/env python3
"""Checks the cohort workflow's results for make_cohort.py's four inputs: the table's rows and
values, the failed row, the per-input files and the summary page.
Usage: check_cohort.py RESULTS EXPECTED_JSON [--snapshots]; exits 1 with the failed checks."""
import csv
import html
import json
import os
import sys

results, expected_path = sys.argv[1], sys.argv[2]
snapshots = "--snapshots" in sys.argv[3:]
problems = []


def check(condition, message):
    if not condition:
        problems.append(message)


with open(expected_path) as f:
    expected = json.load(f)  # "sub-01/1": voxel volume in mL
with open(os.path.join(results, "cohort.tsv")) as f:
    rows = list(csv.DictReader(f, delimiter="\t"))

keys = sorted(f"{r['subject']}/{r['label']}" for r in rows if r["status"] == "ok")
check(keys == sorted(expected), f"meshed rows {keys}, expected {sorted(expected)}")
for row in rows:
    key = f"{row['subject']}/{row['label']}"
    if key not in expected:
        continue
    check(row["exit_code"] == "0" and row["error"] == "", f"{key}: exit code {row['exit_code']} {row['error']}")
    check(int(row["triangles"]) > 100, f"{key}: {row['triangles']} triangles")
    check(row["closed"] == "true", f"{key}: not closed")
    volume, voxels = float(row["volume_ml"]), expected[key]
    check(abs(volume - voxels) <= 0.15 * voxels, f"{key}: volume {volume} mL, its voxels {voxels} mL")
    check(0.0 < float(row["min_angle_deg"]) <= 60.0, f"{key}: smallest angle {row['min_angle_deg']}")
    check(0.0 <= float(row["percent_under_30_deg"]) <= 100.0, f"{key}: {row['percent_under_30_deg']}% under 30")
    check(float(row["seconds"]) > 0.0, f"{key}: {row['seconds']} s")
check([r["session"] for r in rows if r["subject"] == "sub-02"] == ["ses-1"], "sub-02's session is not ses-1")

failed = [r for r in rows if r["status"] != "ok"]
check(len(failed) == 1 and failed[0]["subject"] == "sub-04", f"rows not ok: {failed}")
if failed:
    row = failed[0]
    check(row["exit_code"] == "3", f"sub-04: exit code {row['exit_code']}, SliceMesh's for unreadable input is 3")
    check("sub-04_dseg.nii.gz" in row["error"] and "\n" not in row["error"], f"sub-04: error '{row['error']}'")
    check(row["triangles"] == "", "sub-04: a failed row has triangles")
with open(os.path.join(results, "failed.txt")) as f:
    check(f.read().split() == [os.path.join(results, "sub-04/sub-04_dseg_status.json")], "failed.txt")

files = ["sub-01/sub-01_dseg.vtp", "sub-01/sub-01_dseg_report.json", "sub-01/sub-01_dseg_labels/001_Label_1.vtp",
         "sub-01/sub-01_dseg_labels/002_Label_2.vtp", "sub-02/ses-1/sub-02_ses-1_dseg_labels/005_Label_5.vtp",
         "sub-03/sub-03_T1w.vtp", "sub-04/sub-04_dseg.log"]
if snapshots:
    files += ["sub-01/sub-01_dseg_snapshot.png", "sub-02/ses-1/sub-02_ses-1_dseg_snapshot.png",
              "sub-03/sub-03_T1w_snapshot.png"]
for name in files:
    check(os.path.isfile(os.path.join(results, name)), f"missing {name}")
for name in [n for n in files if n.endswith(".png")]:
    with open(os.path.join(results, name), "rb") as f:
        check(f.read(8) == b"\x89PNG\r\n\x1a\n", f"{name} is not a PNG")
check(not os.path.exists(os.path.join(results, "sub-03/sub-03_T1w_labels")), "the override did not apply")

with open(os.path.join(results, "cohort.html")) as f:
    page = f.read()
check(page.count("<img ") == (3 if snapshots else 0), f"{page.count('<img ')} thumbnails in cohort.html")
if failed:
    check(html.escape(failed[0]["error"]) in page and 'class="failed"' in page, "cohort.html: no sub-04 error")

for problem in problems:
    print("check_cohort:", problem)
sys.exit(1 if problems else 0)
