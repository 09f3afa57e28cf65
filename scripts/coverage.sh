#!/usr/bin/env bash
# The test suite again on a gcov-instrumented GCC build in build-coverage/ (or
# $STRIDE_COVERAGE_BUILD_DIR), then gcovr: line and branch coverage per source folder, printed
# and written with the HTML report, the JSON data and the untested functions into
# build-coverage/coverage/. Fails when a test fails or a folder is under its floor in
# scripts/coverage-floors.txt. Incremental like build.sh; arguments go to ctest (and then the
# floors, which are the whole suite's, are not checked).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${STRIDE_COVERAGE_BUILD_DIR:-$root/build-coverage}"
out="$build/coverage"

if [ ! -f "$build/build.ninja" ]; then
  # NDEBUG as in the Release build; the optimisation level is cmake/StrideCoverage.cmake's
  CC=gcc CXX=g++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DSTRIDE_COVERAGE=ON -DSTRIDE_BUILD_BENCHMARKS=OFF
fi
start=$SECONDS
cmake --build "$build" -j "${STRIDE_JOBS:-2}"
built=$SECONDS

# counters of an earlier run would add up with this one's
find "$build" -name '*.gcda' -delete
rm -rf "$out"
mkdir -p "$out/html"
# a failing test still leaves its counters: report them, then fail
status=0
# gcov's runtime reports counters it could not merge or write here, not on the tests' stderr
export GCOV_ERROR_FILE="$out/gcov-errors.txt"
(cd "$build" && ctest --output-on-failure -j "${STRIDE_JOBS:-2}" "$@") || status=$?
tested=$SECONDS
if [ -s "$GCOV_ERROR_FILE" ]; then
  echo "coverage: gcov lost counters, the figures would be wrong ($GCOV_ERROR_FILE):" >&2
  head -20 "$GCOV_ERROR_FILE" >&2
  status=1
fi

# only the project's source folders count (not tests/, bench/, fuzz/, examples/, build trees or
# system headers); the branches that only exceptions take, and those gcc marks unreachable, are
# left out, or every call that may throw would count as an untested branch. gcovr 5.2 can hang
# after a gcov parse error instead of exiting: the timeout makes that a failure (it takes well
# under a minute otherwise)
cd "$root"
timeout 900 gcovr --root "$root" "$build" -j "${STRIDE_JOBS:-2}" \
  --filter '(common|fmi|orchestrator|components|remote|suite|study|calibration|viewer|cli)/' \
  --exclude-throw-branches --exclude-unreachable-branches \
  --json-summary-pretty --json-summary "$out/summary.json" --json "$out/coverage.json" \
  --html-details "$out/html/index.html" --html-title "Stride coverage"
# the floors are those of the whole suite: with ctest arguments (a subset, say) only report
floors=(--floors "$root/scripts/coverage-floors.txt")
if [ $# -gt 0 ]; then
  floors=()
  echo "coverage: ctest arguments given, the floors are not checked"
fi
python3 "$root/scripts/coverage_report.py" --summary-json "$out/summary.json" \
  --json "$out/coverage.json" --build "$build" "${floors[@]}" --out-dir "$out" || status=$?
echo "coverage: report in $out (summary.txt, html/index.html, untested-functions.txt)"
echo "coverage: build $((built - start)) s, tests $((tested - built)) s, report $((SECONDS - tested)) s"
exit "$status"
