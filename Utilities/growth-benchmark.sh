#!/usr/bin/env bash
# The growth benchmark: how SliceMesh's time grows with the size of shapes whose slabs are long and
# thin or crowded (a row of specks, a one-voxel bar, a comb, nested rings; a ball as the baseline),
# each at four sizes doubling (inputs made by MakeGrowthVolumes), on one thread, against the size of
# what it makes. Per row: SliceMesh's whole run and its slowest stage, the growth of its time and of
# its triangles from the size before, peak memory, and 3D Slicer's pipeline (SlicerPeer) on the same
# input. Time growing as fast as the triangles is linear. Prints the table.
#   Utilities/growth-benchmark.sh [build folder] [families, e.g. "speck-row comb"]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(cd "${1:-$here/build}" && pwd)"
families="${2:-speck-row bar comb rings sphere}"
cmake --build "$build" -j2 --target SliceMesh MakeGrowthVolumes SlicerPeer >/dev/null
work="$build/growth"
mkdir -p "$work"
[ -f "$work/inputs/sphere-128.nrrd" ] || "$build/Testing/Benchmark/MakeGrowthVolumes" "$work/inputs"

results="$work/results.tsv"
: >"$results"
for family in $families; do
  for input in $(ls "$work/inputs/$family"-[0-9]*.nrrd | sed 's/.*-\([0-9]*\)\.nrrd$/\1 &/' | sort -n | cut -d' ' -f2); do
    name="$(basename "$input" .nrrd)"
    echo "growth benchmark: $name" >&2
    /usr/bin/time -f "%e %M" -o "$work/$name.time" \
      "$build/CLI/SliceMesh" --threads 1 --report "$work/$name.json" "$input" "$work/$name.vtp" >/dev/null 2>&1
    "$build/Testing/Benchmark/SlicerPeer" "$input" "$work/$name.peer.vtp" >"$work/$name.peer.out"
    printf '%s\t%s\t%s\t%s\t%s\n' "$family" "${name##*-}" "$(cat "$work/$name.time")" "$(cat "$work/$name.peer.out")" \
      "$work/$name.json" >>"$results"
  done
done

python3 - "$results" <<'PYTHON'
import json, sys
print("| shape | size | SliceMesh, 1 thread (s) | slowest stage (s) | time growth | triangle growth | peak memory (MB) | triangles | Slicer's meshing (s) |")
print("|---|---:|---:|---|---:|---:|---:|---:|---:|")
previous = {}
for line in open(sys.argv[1]):
    family, size, ours, peer, report = line.rstrip("\n").split("\t")
    wall, kb = map(float, ours.split())
    r = json.load(open(report))
    stage, seconds = max(((k, v) for k, v in r["seconds"].items() if k != "total"), key=lambda kv: kv[1])
    triangles = int(r["mesh"]["triangles"])
    growth = "" if family not in previous else f"{wall / previous[family][0]:.1f}"
    made = "" if family not in previous else f"{triangles / previous[family][1]:.1f}"
    previous[family] = (wall, triangles)
    print(f"| {family} | {size} | {wall:.2f} | {stage} {seconds:.2f} | {growth} | {made} | {kb / 1024:.0f} | {triangles} | {float(peer.split()[3]):.2f} |")
PYTHON
