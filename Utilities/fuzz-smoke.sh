#!/usr/bin/env bash
# A short libFuzzer run of the four fuzz targets (README, "Fuzzing"), part of the test command: builds
# them in build-fuzz (sanitizer-build.sh: clang and the sanitizers), then runs each target for
# SLICEMESH_FUZZ_SECONDS (default 22: about 90 s in all) with a fixed seed, from an empty corpus, or
# for StructureFuzzer from one small file of each kind it reads.
# A crash, a sanitizer report or a hang (over 20 s on one input) fails the run; libFuzzer leaves the
# input as build-fuzz/crash-* (or timeout-*) to turn into a regression test.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${SLICEMESH_FUZZ_SECONDS:-22}"
./Utilities/sanitizer-build.sh LogicFuzzer FinishingFuzzer VolumeFuzzer StructureFuzzer MakeStructureFuzzSeeds
# The third-party leaks the sanitizer run suppresses (Testing/lsan-suppressions.txt) are suppressed
# here too, for every target: libFuzzer checks each input for leaks, and a library's global made on
# first use (ITK's singletons, reached by whichever input first reads a volume) counts against the
# input that made it. Matching DCMTK's leak needs whole allocation stacks.
leaks="$PWD/Testing/lsan-suppressions.txt"
for fuzzer in LogicFuzzer FinishingFuzzer VolumeFuzzer StructureFuzzer; do
  rm -rf "build-fuzz/corpus/$fuzzer"
  mkdir -p "build-fuzz/corpus/$fuzzer"
  if [ "$fuzzer" = StructureFuzzer ]; then
    ./build-fuzz/Testing/Fuzz/MakeStructureFuzzSeeds "build-fuzz/corpus/$fuzzer"
  fi
  (cd build-fuzz && ASAN_OPTIONS=fast_unwind_on_malloc=0 LSAN_OPTIONS="suppressions=$leaks" \
    "./Testing/Fuzz/$fuzzer" -seed=1 -max_total_time="$seconds" -timeout=20 -print_final_stats=1 "corpus/$fuzzer")
  echo "SliceMesh: fuzz smoke run of $fuzzer passed"
done
