#!/usr/bin/env bash
# Compares the meshes two builds of SliceMesh write for the same inputs, byte for byte: the sample
# label map (one mesh, and one mesh per label), and the quality benchmark's phantoms on its two grids
# (default finish and the tiling alone); and their quality reports, but for the seconds and the
# folder they were written to. Use it to show that a change that should not change the output does not:
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
    "$1" --report "$2/$name.json" "$input" "$2/$name.vtp" >/dev/null 2>&1 || echo "exit $? for $name" >>"$2/exits.txt"
    "$1" --surfaceFinish Tiled --report "$2/$name-tiled.json" "$input" "$2/$name-tiled.vtp" >/dev/null 2>&1 ||
      echo "exit $? for $name tiled" >>"$2/exits.txt"
  done
  "$1" --splitLabels --outputDirectory "$2/labels" --report "$2/sample-all.json" "$work/inputs/sample-labelmap.nii.gz" \
    "$2/sample-all.vtp" >/dev/null 2>&1 || echo "exit $? for the multi-label run" >>"$2/exits.txt"
}
# A report without what changes from run to run: the seconds, and the folder of the run.
timeless() { # timeless <report> <run folder>
  sed -e '/"seconds": {/,/}/d' -e '/"seconds": [0-9]/d' -e "s#$2#RUN#g" "$1"
}
run "$a" "$work/a"
run "$b" "$work/b"

differ=0
same() { # same <file>: a mesh byte for byte, a report but for its seconds
  if [[ "$1" == *.json ]]; then
    [ "$(timeless "$work/a/$1" "$work/a")" = "$(timeless "$work/b/$1" "$work/b")" ]
  else
    cmp -s "$work/a/$1" "$work/b/$1"
  fi
}
while IFS= read -r file; do
  if ! same "$file"; then
    echo "differs: $file"
    differ=1
  fi
done < <(cd "$work/a" && find . -type f | sort)
if [ "$(cd "$work/a" && find . -type f | sort)" != "$(cd "$work/b" && find . -type f | sort)" ]; then
  echo "the two builds wrote different sets of files"
  differ=1
fi
count="$(cd "$work/a" && find . -name '*.vtp' | wc -l)"
reports="$(cd "$work/a" && find . -name '*.json' | wc -l)"
if [ $differ -eq 0 ]; then
  echo "compare-builds: all $count meshes identical, and all $reports quality reports but for their seconds"
fi
exit $differ
