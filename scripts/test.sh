#!/usr/bin/env bash
# The whole test suite: install dependencies, build, run every test through CTest.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
cd "${STRIDE_BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "${STRIDE_JOBS:-2}" "$@"
