#!/usr/bin/env bash
# The main job: install dependencies, build, then `stride run` (arguments are passed on; none
# runs the embedded default scenario).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
exec "${STRIDE_BUILD_DIR:-$root/build}/bin/stride" run "$@"
