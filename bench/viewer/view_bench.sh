#!/usr/bin/env bash
# The run viewer's figures for BENCHMARKS.md: size of the page and time to write it for the
# 60 s walk (models/walk.xml --record-view) and, with --learner, for the 12 000-step learner demo
# (models/experiments/demo.xml, a few minutes to run); the frame rate of playback in headless
# Chromium. Each time is the median of 5 runs (playback: of 3).
# bench/viewer/view_bench.sh BUILD_DIR [--learner]
set -euo pipefail
build="$(cd "${1:?usage: view_bench.sh BUILD_DIR [--learner]}" && pwd)"
root="$(cd "$(dirname "$0")/../.." && pwd)"
stride="$build/bin/stride"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

# seconds of `stride view ARGS`, median of 5
time_view() {
  for _ in 1 2 3 4 5; do
    local t0 t1
    t0=$(date +%s.%N)
    "$stride" view "$@" --quiet
    t1=$(date +%s.%N)
    echo "$t1 - $t0" | bc -l
  done | median
}

echo "== 60 s walk"
"$stride" run "$root/models/walk.xml" --record-view --quiet -o "$work/walk"
echo "view.csv: $(stat -c %s "$work/walk/view.csv") bytes, $(($(wc -l < "$work/walk/view.csv") - 1)) rows"
echo "stride view: $(time_view "$work/walk") s (median of 5)"
echo "view.html: $(stat -c %s "$work/walk/view.html") bytes"
for _ in 1 2 3; do
  node --experimental-websocket "$root/bench/viewer/playback_fps.js" "$work/walk/view.html" 3 |
    awk '{print $2}'
done | median | sed 's/^/playback: /; s/$/ frames\/s (median of 3, 3 s each, 1280x720)/'

if [ "${2:-}" = "--learner" ]; then
  echo "== learner demo (12 000 RL steps)"
  # about 5 simulated hours: every 0.096 s (12 base steps) keeps view.csv near 0.2 GB
  "$stride" run "$root/models/experiments/demo.xml" --record-view --record-view-interval 0.096 \
    --quiet --no-plots -o "$work/demo"
  echo "view.csv: $(stat -c %s "$work/demo/view.csv") bytes, $(($(wc -l < "$work/demo/view.csv") - 1)) rows"
  echo "stride view: $(time_view "$work/demo") s (median of 5)"
  echo "view.html: $(stat -c %s "$work/demo/view.html") bytes"
fi
