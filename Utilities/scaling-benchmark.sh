#!/usr/bin/env bash
# The scaling benchmark: SliceMesh and 3D Slicer's label map -> closed surface pipeline (SlicerPeer)
# in the same run, on a large isotropic volume, the same shape on thick slices, the AAL atlas (all
# labels), 60 generated labels on 256^3, a generated whole-body CT segmentation (87 labels on
# 512 x 512 x 400), and one sphere at 128^3, 256^3 and 512^3. Per row: whole run
# and meshing time (reading and writing excluded) of both, their ratio, SliceMesh's time per stage,
# peak memory of both, triangles, triangles per second. Writes the table into the "Scaling" section
# of Documentation/Benchmark.md with the machine it ran on (the rest of the file is kept) and prints it.
# Each row runs both sides in turn, `runs` times, and shows the medians: single runs of either side
# moved by 10-40% between tables on the same shared machine.
#   Utilities/scaling-benchmark.sh [build folder] [rows, e.g. "ellipsoid-thick aal"] [runs]
# Defaults: build, every row, 3 runs. Needs the project built (it builds the benchmark's own tools).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(cd "${1:-$here/build}" && pwd)"
rows="${2:-ellipsoid-large ellipsoid-thick aal labels-60 ct-like sphere-128 sphere-256 sphere-512}"
runs="${3:-3}"
case "$runs" in
  '' | *[!0-9]* | 0) echo "scaling benchmark: runs must be a positive whole number, not '$runs'" >&2; exit 2 ;;
esac
cmake --build "$build" -j2 --target SliceMesh MakeScalingVolumes SlicerPeer >/dev/null
work="$build/scaling"
mkdir -p "$work"
[ -f "$work/inputs/ct-like.nrrd" ] || "$build/Testing/Benchmark/MakeScalingVolumes" "$work/inputs"

input_of() {
  case "$1" in
    aal) echo /usr/share/mricron/templates/aal.nii.gz ;;
    *) echo "$work/inputs/$1.nrrd" ;;
  esac
}
options_of() { # one mesh per label where there are several
  case "$1" in
    aal | labels-60 | ct-like) echo "--splitLabels" ;;
    *) echo "" ;;
  esac
}

results="$work/results.tsv"
: >"$results"
for row in $rows; do
  input="$(input_of "$row")"
  for run in $(seq "$runs"); do
    echo "scaling benchmark: $row, run $run of $runs" >&2
    /usr/bin/time -f "%e %M" -o "$work/$row.slicemesh.time" \
      "$build/CLI/SliceMesh" $(options_of "$row") --report "$work/$row.$run.json" "$input" "$work/$row.slicemesh.vtp" >/dev/null
    /usr/bin/time -f "%e %M" -o "$work/$row.slicer.time" \
      "$build/Testing/Benchmark/SlicerPeer" "$input" "$work/$row.slicer.vtp" >"$work/$row.slicer.out"
    printf '%s\t%s\t%s\t%s\t%s\n' "$row" "$(cat "$work/$row.slicemesh.time")" "$(cat "$work/$row.slicer.time")" \
      "$(cat "$work/$row.slicer.out")" "$work/$row.$run.json" >>"$results"
  done
done

python3 - "$results" "$here/Documentation/Benchmark.md" "$(nproc)" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //')" "$runs" <<'PYTHON'
import json, sys, datetime, statistics
results, document, cores, cpu, runs = sys.argv[1:6]
stages = ["Contours", "Correspondence", "Tiling", "Validation", "Finishing"]
lines = [
    "| input | SliceMesh whole run (s) | Slicer whole run (s) | ratio | SliceMesh meshing (s) | Slicer meshing (s) | ratio | "
    "SliceMesh by stage (s): " + ", ".join(stages) + " | peak memory SliceMesh / Slicer (MB) | triangles SliceMesh / Slicer | "
    "SliceMesh triangles per s |",
    "|---|---:|---:|---:|---:|---:|---:|---|---|---|---:|",
]
runs_of = {}  # row -> its runs, in the order the rows ran
for line in open(results):
    row, ours, theirs, peer, report = line.rstrip("\n").split("\t")
    our_wall, our_kb = map(float, ours.split())
    their_wall, their_kb = map(float, theirs.split())
    peer = peer.split()
    r = json.load(open(report))
    seconds = r["seconds"]
    runs_of.setdefault(row, []).append({
        "our_wall": our_wall, "our_kb": our_kb, "their_wall": their_wall, "their_kb": their_kb,
        "their_triangles": int(peer[1]), "their_meshing": float(peer[3]),
        "by_stage": [seconds.get(s, 0.0) for s in stages], "triangles": int(r["mesh"]["triangles"])})
for row, measured in runs_of.items():
    median = lambda key: statistics.median(m[key] for m in measured)
    by_stage = [statistics.median(m["by_stage"][k] for m in measured) for k in range(len(stages))]
    meshing = statistics.median(sum(m["by_stage"]) for m in measured)
    our_wall, their_wall, their_meshing = median("our_wall"), median("their_wall"), median("their_meshing")
    triangles, their_triangles = measured[0]["triangles"], measured[0]["their_triangles"]
    lines.append(
        f"| {row} | {our_wall:.1f} | {their_wall:.1f} | {our_wall / their_wall:.1f} | {meshing:.1f} | {their_meshing:.2f} | "
        f"{meshing / their_meshing:.1f} | " + ", ".join(f"{s:.1f}" for s in by_stage) +
        f" | {median('our_kb') / 1024:.0f} / {median('their_kb') / 1024:.0f} | {triangles} / {their_triangles} | "
        f"{triangles / meshing:.0f} |")
table = "\n".join(lines) + "\n"
section = (
    "<!-- scaling: written by Utilities/scaling-benchmark.sh -->\n"
    "## Scaling: time and memory against 3D Slicer's pipeline\n\n"
    "Regenerate with `Utilities/scaling-benchmark.sh` (inputs made by `MakeScalingVolumes`; the peer is\n"
    "`SlicerPeer`, Slicer's conversion of each label on its own extent, as the quality table describes).\n"
    "Whole run: wall clock of the process, reading and writing included; meshing: the stages between\n"
    "the read volume and the finished surface (SliceMesh's Contours to Finishing; the peer's conversion).\n"
    f"Run on {datetime.date.today()}, {cores} cores, {cpu} (a shared machine: times are indicative);\n"
    f"each figure the median of {runs} runs of each side, run in turn.\n\n"
    + table + "<!-- /scaling -->\n")
try:
    text = open(document).read()
except FileNotFoundError:
    text = "# Benchmark\n\n"
start, end = text.find("<!-- scaling"), text.find("<!-- /scaling -->")
if start >= 0 and end >= 0:
    text = text[:start] + section + text[end + len("<!-- /scaling -->\n"):]
else:
    text = text.rstrip("\n") + "\n\n" + section
open(document, "w").write(text)
print(table)
PYTHON
