#!/usr/bin/env bash
# The Logic and Reliability suites under AddressSanitizer + UndefinedBehaviorSanitizer, part of the
# test command (Documentation/Reliability.md, "Sanitizers"): builds the two test programs in
# build-fuzz (sanitizer-build.sh: clang, the tree the fuzz smoke run uses, so the libraries are
# compiled once for both) and runs them. Any sanitizer report fails the run. The property tests run
# SLICEMESH_PROPERTY_CASES masks per kind (default here 20; the plain build's suite runs more).
set -euo pipefail
cd "$(dirname "$0")/.."
./Utilities/sanitizer-build.sh LogicTests ReliabilityTests
export LSAN_OPTIONS="suppressions=$PWD/Testing/lsan-suppressions.txt"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export SLICEMESH_PROPERTY_CASES="${SLICEMESH_PROPERTY_CASES:-20}"
build-fuzz/Testing/Logic/LogicTests --gtest_brief=1
build-fuzz/Testing/Reliability/ReliabilityTests --gtest_brief=1
echo "SliceMesh: sanitizer run of the Logic and Reliability suites passed"
