#!/usr/bin/env bash
# Compares the meshes two builds of SliceMesh write for the same inputs, byte for byte: the sample
# label map (one mesh, and one mesh per label), and the quality benchmark's phantoms on its two grids
# (default finish and the tiling alone). Use it to show that a change that should not change the
# output does not:
#   git worktree add ../before <commit> && cmake -S ../before -B ../before/build && cmake --build ../before/build -j2
#   cmake --build build --target SliceMesh WritePhantomMasks
#   Utilities/compare-builds.sh ../before/build build
# Exit 0 when every pair is identical, 1 otherwise (the differing outputs are listed).
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 <build folder A> <build folder B>" >&2
  exit 2
fi
a="$(cd "$1" && pwd)/CLI/SliceMesh"
b="$(cd "$2" && pwd)/CLI/SliceMesh"
writer="$(cd "$2" && pwd)/Testing/Phantoms/WritePhantomMasks"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$writer" "$work/inputs"
cp "$here/Data/sample-labelmap.nii.gz" "$work/inputs/"

run() { # run <executable> <output folder>
  mkdir -p "$2/labels"
  for input in "$work"/inputs/*; do
    name="$(basename "$input")"
    name="${name%%.*}"
    "$1" "$input" "$2/$name.vtp" >/dev/null 2>&1 || echo "exit $? for $name" >>"$2/exits.txt"
    "$1" --surfaceFinish Tiled "$input" "$2/$name-tiled.vtp" >/dev/null 2>&1 || echo "exit $? for $name tiled" >>"$2/exits.txt"
  done
  "$1" --splitLabels --outputDirectory "$2/labels" "$work/inputs/sample-labelmap.nii.gz" "$2/sample-all.vtp" \
    >/dev/null 2>&1 || echo "exit $? for the multi-label run" >>"$2/exits.txt"
}
run "$a" "$work/a"
run "$b" "$work/b"

differ=0
while IFS= read -r file; do
  if ! cmp -s "$work/a/$file" "$work/b/$file"; then
    echo "differs: $file"
    differ=1
  fi
done < <(cd "$work/a" && find . -type f | sort)
if [ "$(cd "$work/a" && find . -type f | sort)" != "$(cd "$work/b" && find . -type f | sort)" ]; then
  echo "the two builds wrote different sets of files"
  differ=1
fi
count="$(cd "$work/a" && find . -name '*.vtp' | wc -l)"
if [ $differ -eq 0 ]; then
  echo "compare-builds: all $count meshes identical"
fi
exit $differ
