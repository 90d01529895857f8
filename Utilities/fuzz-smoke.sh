#!/usr/bin/env bash
# A short libFuzzer run of the three fuzz targets (README, "Fuzzing"), part of the test command: builds
# build-fuzz with clang and the sanitizers (only the fuzz targets and the libraries they link), then
# runs each target for SLICEMESH_FUZZ_SECONDS (default 30) from an empty corpus with a fixed seed.
# A crash, a sanitizer report or a hang (over 20 s on one input) fails the run; libFuzzer leaves the
# input as build-fuzz/crash-* (or timeout-*) to turn into a regression test.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${SLICEMESH_FUZZ_SECONDS:-30}"
CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -DSLICEMESH_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz -j2 --target LogicFuzzer FinishingFuzzer VolumeFuzzer
for fuzzer in LogicFuzzer FinishingFuzzer VolumeFuzzer; do
  rm -rf "build-fuzz/corpus/$fuzzer"
  mkdir -p "build-fuzz/corpus/$fuzzer"
  (cd build-fuzz && "./Testing/Fuzz/$fuzzer" -seed=1 -max_total_time="$seconds" -timeout=20 -print_final_stats=1 \
    "corpus/$fuzzer")
  echo "SliceMesh: fuzz smoke run of $fuzzer passed"
done
