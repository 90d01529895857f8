"""The summary rule: cohort.tsv -> cohort.html, one page: the totals, then one row per input with
its snapshot as a thumbnail (linked to the picture), its rows of the table folded under it."""
import csv
import html
import json
import os
from collections import defaultdict

STYLE = """body{font-family:sans-serif;margin:1.5em}table{border-collapse:collapse}
td,th{border-bottom:1px solid #ddd;padding:4px 8px;text-align:left;vertical-align:top}
td.n{text-align:right}img{width:160px;border:1px solid #ccc}.failed{background:#fde2e2}
.invalid{background:#fff3cd}details table{font-size:90%}"""


def cell(value, numeric=False):
    return f"<td{' class=n' if numeric else ''}>{html.escape(str(value))}</td>"


def duration(seconds):
    if seconds >= 3600:
        return f"{seconds / 3600:.1f} h"
    return f"{seconds / 60:.1f} min" if seconds >= 60 else f"{seconds:.0f} s"


def label_table(rows, columns):
    head = "".join(f"<th>{html.escape(c)}</th>" for c in columns)
    body = "".join("<tr>" + "".join(cell(r[c]) for c in columns) + "</tr>" for r in rows)
    return f"<details><summary>{len(rows)} row(s)</summary><table><tr>{head}</tr>{body}</table></details>"


def input_row(status, rows, here, columns):
    columns = [c for c in columns if c not in ("subject", "session", "input", "exit_code")]
    folder = os.path.relpath(os.path.dirname(status["_path"]), here)
    picture = status["files"]["snapshot"]
    thumbnail = ""
    if picture:
        src = html.escape(os.path.join(folder, picture))
        thumbnail = f'<a href="{src}"><img src="{src}" alt="snapshot" loading="lazy"></a>'
    meshed = [r for r in rows if r["triangles"]]
    worst = "failed" if any(r["status"] == "failed" for r in rows) else (
        "invalid" if any(r["status"] == "invalid" for r in rows) else "")
    angles = [float(r["min_angle_deg"]) for r in meshed]
    cells = [
        f"<td>{thumbnail}</td>",
        cell(status["subject"]), cell(status["session"]), cell(os.path.basename(status["path"].rstrip("/"))),
        cell(status["exit_code"], True),
        cell(f"{len(meshed)}/{len(rows)}", True),
        cell(sum(int(r["triangles"]) for r in meshed), True),
        cell(f"{sum(float(r['volume_ml']) for r in meshed):.2f}", True),
        cell(f"{min(angles):.1f}" if angles else "", True),
        cell(f"{status['seconds']:.1f}", True),
        cell(status["error"]),
        f"<td>{label_table(rows, columns)}</td>",
    ]
    return f'<tr class="{worst}">' + "".join(cells) + "</tr>"


def main(snakemake):
    with open(snakemake.input.tsv) as f:
        reader = csv.DictReader(f, delimiter="\t")
        columns, table = reader.fieldnames, list(reader)
    by_input = defaultdict(list)
    for row in table:
        by_input[(row["subject"], row["session"], row["input"])].append(row)

    statuses = []
    for path in snakemake.input.statuses:
        with open(path) as f:
            statuses.append(dict(json.load(f), _path=path))
    here = os.path.dirname(snakemake.output.html)
    failed = sum(1 for s in statuses if s["exit_code"] != 0)
    busy = duration(sum(s["seconds"] for s in statuses))
    key = lambda s: (s["subject"], s["session"], os.path.basename(s["path"].rstrip("/")))
    body = "".join(input_row(s, by_input[key(s)], here, columns) for s in sorted(statuses, key=key))
    head = "".join(f"<th>{h}</th>" for h in ["snapshot", "subject", "session", "input", "exit code", "meshes",
                                              "triangles", "volume (mL)", "min angle (°)", "seconds", "error",
                                              "rows of cohort.tsv"])
    page = f"""<!DOCTYPE html><html><head><meta charset="utf-8"><title>SliceMesh cohort</title>
<style>{STYLE}</style></head><body><h1>SliceMesh cohort</h1>
<p>{len(statuses)} inputs: {len(statuses) - failed} meshed (exit code 0), {failed} not;
{len(table)} rows in <a href="cohort.tsv">cohort.tsv</a>; the mesh jobs took {busy} together.</p>
<table><tr>{head}</tr>{body}</table></body></html>
"""
    with open(snakemake.output.html, "w") as out:
        out.write(page)


main(snakemake)  # noqa: F821 (Snakemake's script directive defines it)
