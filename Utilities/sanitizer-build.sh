#!/usr/bin/env bash
# Builds the named targets in build-fuzz, the instrumented tree that the test command's fuzzing
# (fuzz-smoke.sh) and its sanitizer run of the unit suites (sanitizer-run.sh) share: clang,
# AddressSanitizer + UndefinedBehaviorSanitizer, libFuzzer coverage (SLICEMESH_FUZZ). One tree
# compiles the libraries once for both.
set -euo pipefail
cd "$(dirname "$0")/.."
CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -DSLICEMESH_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz -j2 --target "$@"
