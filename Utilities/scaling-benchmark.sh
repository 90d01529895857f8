#!/usr/bin/env bash
# The scaling benchmark: SliceMesh and 3D Slicer's label map -> closed surface pipeline (SlicerPeer)
# in the same run, on a large isotropic volume, the same shape on thick slices, the AAL atlas (all
# labels), 60 generated labels on 256^3, a generated whole-body CT segmentation (87 labels on
# 512 x 512 x 400), and one sphere at 128^3, 256^3 and 512^3. Per row: whole run
# and meshing time (reading and writing excluded) of both, their ratio, SliceMesh's time per stage,
# peak memory of both, triangles, triangles per second. Writes the table into the "Scaling" section
# of Documentation/Benchmark.md with the machine it ran on (the rest of the file is kept) and prints it.
#   Utilities/scaling-benchmark.sh [build folder] [rows, e.g. "ellipsoid-thick aal"]
# Defaults: build, every row. Needs the project built (it builds the benchmark's own tools).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(cd "${1:-$here/build}" && pwd)"
rows="${2:-ellipsoid-large ellipsoid-thick aal labels-60 ct-like sphere-128 sphere-256 sphere-512}"
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
  echo "scaling benchmark: $row" >&2
  /usr/bin/time -f "%e %M" -o "$work/$row.slicemesh.time" \
    "$build/CLI/SliceMesh" $(options_of "$row") --report "$work/$row.json" "$input" "$work/$row.slicemesh.vtp" >/dev/null
  /usr/bin/time -f "%e %M" -o "$work/$row.slicer.time" \
    "$build/Testing/Benchmark/SlicerPeer" "$input" "$work/$row.slicer.vtp" >"$work/$row.slicer.out"
  printf '%s\t%s\t%s\t%s\t%s\n' "$row" "$(cat "$work/$row.slicemesh.time")" "$(cat "$work/$row.slicer.time")" \
    "$(cat "$work/$row.slicer.out")" "$work/$row.json" >>"$results"
done

python3 - "$results" "$here/Documentation/Benchmark.md" "$(nproc)" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //')" <<'PYTHON'
import json, sys, datetime
results, document, cores, cpu = sys.argv[1:5]
stages = ["Contours", "Correspondence", "Tiling", "Validation", "Finishing"]
lines = [
    "| input | SliceMesh whole run (s) | Slicer whole run (s) | ratio | SliceMesh meshing (s) | Slicer meshing (s) | ratio | "
    "SliceMesh by stage (s): " + ", ".join(stages) + " | peak memory SliceMesh / Slicer (MB) | triangles SliceMesh / Slicer | "
    "SliceMesh triangles per s |",
    "|---|---:|---:|---:|---:|---:|---:|---|---|---|---:|",
]
for line in open(results):
    row, ours, theirs, peer, report = line.rstrip("\n").split("\t")
    our_wall, our_kb = map(float, ours.split())
    their_wall, their_kb = map(float, theirs.split())
    peer = peer.split()
    their_triangles, their_meshing = int(peer[1]), float(peer[3])
    r = json.load(open(report))
    seconds = r["seconds"]
    by_stage = [seconds.get(s, 0.0) for s in stages]
    meshing = sum(by_stage)
    triangles = int(r["mesh"]["triangles"])
    lines.append(
        f"| {row} | {our_wall:.1f} | {their_wall:.1f} | {our_wall / their_wall:.1f} | {meshing:.1f} | {their_meshing:.2f} | "
        f"{meshing / their_meshing:.1f} | " + ", ".join(f"{s:.1f}" for s in by_stage) +
        f" | {our_kb / 1024:.0f} / {their_kb / 1024:.0f} | {triangles} / {their_triangles} | {triangles / meshing:.0f} |")
table = "\n".join(lines) + "\n"
section = (
    "<!-- scaling: written by Utilities/scaling-benchmark.sh -->\n"
    "## Scaling: time and memory against 3D Slicer's pipeline\n\n"
    "Regenerate with `Utilities/scaling-benchmark.sh` (inputs made by `MakeScalingVolumes`; the peer is\n"
    "`SlicerPeer`, Slicer's conversion of each label on its own extent, as the quality table describes).\n"
    "Whole run: wall clock of the process, reading and writing included; meshing: the stages between\n"
    "the read volume and the finished surface (SliceMesh's Contours to Finishing; the peer's conversion).\n"
    f"Run on {datetime.date.today()}, {cores} cores, {cpu} (a shared machine: times are indicative).\n\n"
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
