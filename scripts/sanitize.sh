#!/usr/bin/env bash
# The test suite again on a build with AddressSanitizer + UndefinedBehaviorSanitizer (Clang) in
# build-sanitize/ (or $STRIDE_SANITIZE_BUILD_DIR), the libFuzzer targets of every parser included
# (fuzz/: each replays its corpus and runs a fixed number of mutations). Any sanitizer report
# fails its test. Incremental like build.sh; arguments go to ctest.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${STRIDE_SANITIZE_BUILD_DIR:-$root/build-sanitize}"

if [ ! -f "$build/build.ninja" ]; then
  # -O1: the usual sanitizer trade-off between build time, run time and precise reports
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
    -DSTRIDE_SANITIZE=ON -DSTRIDE_BUILD_BENCHMARKS=OFF
fi
cmake --build "$build" -j "${STRIDE_JOBS:-2}"
cd "$build"
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$root/fuzz/lsan.supp"
ctest --output-on-failure -j "${STRIDE_JOBS:-2}" "$@"
