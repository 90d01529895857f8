"""The table rule: every input's status file and SliceMesh report -> cohort.tsv (one row per mesh:
per label when labels are meshed separately; one row for an input that failed before meshing)
and failed.txt (the status files of inputs SliceMesh did not finish with exit code 0, one a line,
for `xargs -r -d '\n' -a failed.txt snakemake ... --forcerun`)."""
import csv
import json
import os

COLUMNS = ["subject", "session", "input", "label", "name", "status", "triangles", "volume_ml", "closed",
           "min_angle_deg", "percent_under_30_deg", "seconds", "exit_code", "error"]


def number(value, digits):
    return "" if value is None else f"{value:.{digits}f}"


def mesh_columns(block):
    """The measured columns of one report entry holding "mesh" and "quality" blocks."""
    mesh, quality = block["mesh"], block["quality"]
    return {
        "status": "ok" if mesh["valid"] else "invalid",
        "triangles": int(mesh["triangles"]),
        "volume_ml": number(None if mesh["volumeMm3"] is None else mesh["volumeMm3"] / 1000.0, 4),
        "closed": "true" if mesh["closed"] else "false",
        "min_angle_deg": number(quality["minAngleDegrees"], 2),
        "percent_under_30_deg": number(quality["percentTrianglesBelow30Degrees"], 2),
    }


def rows_of(status, report, label_option):
    common = {
        "subject": status["subject"],
        "session": status["session"],
        "input": os.path.basename(status["path"].rstrip("/")),
        "exit_code": status["exit_code"],
    }
    if report is None:  # nothing meshed: the run's error is the row
        return [dict(common, status="failed", seconds=number(status["seconds"], 2), error=status["error"])]
    if "labels" not in report:
        row = dict(common, label=label_option or "all", seconds=number(report["seconds"]["total"], 2),
                   error=status["error"])
        return [dict(row, **mesh_columns(report))]
    rows = []
    for entry in report["labels"]:
        row = dict(common, label=entry["label"], name=entry["name"], seconds=number(entry["seconds"], 2))
        if "mesh" in entry:
            row.update(mesh_columns(entry))
        elif entry.get("dropped"):
            row.update(status="dropped", error=entry.get("droppedBecause") or "every piece below minimumComponentVolume")
        else:
            row.update(status="failed", error=entry.get("error") or status["error"])
        rows.append(row)
    return rows


def main(snakemake):
    rows, failed = [], []
    for path in snakemake.input.statuses:
        with open(path) as f:
            status = json.load(f)
        report_name = status["files"]["report"]
        report = None
        if report_name:
            with open(os.path.join(os.path.dirname(path), report_name)) as f:
                report = json.load(f)
        rows += rows_of(status, report, status["options"].get("label"))
        if status["exit_code"] != 0:
            failed.append(path)

    with open(snakemake.output.tsv, "w", newline="") as out:
        writer = csv.DictWriter(out, COLUMNS, delimiter="\t", lineterminator="\n", restval="")
        writer.writeheader()
        writer.writerows(rows)
    with open(snakemake.output.failed, "w") as out:
        out.writelines(p + "\n" for p in failed)


main(snakemake)  # noqa: F821 (Snakemake's script directive defines it)
