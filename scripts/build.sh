#!/usr/bin/env bash
# Configures (once) and builds Stride in Release mode into build/ (or $STRIDE_BUILD_DIR).
# Incremental: a second run rebuilds only what changed. With CI set, warnings are errors.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${STRIDE_BUILD_DIR:-$root/build}"
werror=OFF
[ -n "${CI:-}" ] && werror=ON

if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSTRIDE_WERROR=$werror
elif [ "$(grep -s '^STRIDE_WERROR:' "$build/CMakeCache.txt" | cut -d= -f2)" != "$werror" ]; then
  cmake "$build" -DSTRIDE_WERROR=$werror
fi
cmake --build "$build" -j "${STRIDE_JOBS:-2}"
