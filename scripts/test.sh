#!/usr/bin/env bash
# The whole test suite: install dependencies, build, run every test through CTest; then the same
# suite again on the AddressSanitizer + UndefinedBehaviorSanitizer build with the fuzz targets
# (scripts/sanitize.sh; STRIDE_SKIP_SANITIZE=1 leaves it out), and on the gcov build that reports
# coverage per folder and fails under the floors (scripts/coverage.sh; STRIDE_SKIP_COVERAGE=1
# leaves it out). Arguments go to every ctest run.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
(cd "${STRIDE_BUILD_DIR:-$root/build}" && ctest --output-on-failure -j "${STRIDE_JOBS:-2}" "$@")
if [ "${STRIDE_SKIP_SANITIZE:-0}" != 1 ]; then
  "$root/scripts/sanitize.sh" "$@"
fi
if [ "${STRIDE_SKIP_COVERAGE:-0}" != 1 ]; then
  "$root/scripts/coverage.sh" "$@"
fi
