#!/usr/bin/env bash
# Each label's enclosed volume against its voxels' volume, for SliceMesh (default settings, one mesh
# per label) and 3D Slicer's label map -> closed surface pipeline (SlicerPeer), on the label maps
# given. Prints one table row per label map: the labels, the mean and the largest relative error of
# each side, and on how many labels each side is the closer.
#   Utilities/label-volumes.sh [build folder] <label map>...
# Default label maps: the atlases of Debian's mricron-data. Needs the project built.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$here/build"
if [ $# -gt 0 ] && [ -d "$1" ]; then
  build="$(cd "$1" && pwd)"
  shift
fi
maps=("$@")
if [ ${#maps[@]} -eq 0 ]; then
  maps=(/usr/share/mricron/templates/{aal,brodmann,jhu189,natbrainlab,AICHAmc,HarvardOxford-cort-maxprob-thr0-1mm,JHU-WhiteMatter-labels-2mm}.nii.gz)
fi
cmake --build "$build" -j2 --target SliceMesh SlicerPeer >/dev/null
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "| label map | labels | SliceMesh: mean / largest error | Slicer: mean / largest error | labels where SliceMesh / Slicer is closer |"
echo "|---|---:|---|---|---|"
for map in "${maps[@]}"; do
  name="$(basename "$map")"
  name="${name%%.*}"
  mkdir -p "$work/$name"
  "$build/CLI/SliceMesh" --splitLabels --outputDirectory "$work/$name" --report "$work/$name.json" \
    "$map" "$work/$name.vtp" >/dev/null
  "$build/Testing/Benchmark/SlicerPeer" "$map" "$work/$name.peer.vtp" "$work/$name.peer.tsv" >/dev/null
  python3 - "$name" "$work/$name.json" "$work/$name.peer.tsv" <<'PYTHON'
import json, sys
name, report, peer = sys.argv[1:4]
theirs = {}  # label -> (voxel volume, surface volume)
for line in open(peer):
    label, _, voxels, surface = line.split()
    theirs[int(label)] = (float(voxels), float(surface))
ours, errors = [], []
for entry in json.load(open(report))["labels"]:
    if entry.get("mesh") is None or entry["label"] not in theirs:
        continue  # dropped or failed: no surface to compare
    voxels, surface = theirs[entry["label"]]
    errors.append((entry["mesh"]["volumeMm3"] / voxels - 1.0, surface / voxels - 1.0))
n = len(errors)
def summary(k):
    values = [abs(e[k]) for e in errors]
    largest = max(errors, key=lambda e: abs(e[k]))[k]
    return f"{100 * sum(values) / n:.2f}% / {100 * largest:+.1f}%"
closer = sum(abs(a) < abs(b) for a, b in errors)
farther = sum(abs(a) > abs(b) for a, b in errors)
print(f"| {name} | {n} | {summary(0)} | {summary(1)} | {closer} / {farther} |")
PYTHON
done
