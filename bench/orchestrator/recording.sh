#!/usr/bin/env bash
# What recording costs the run: the 60 s walk (models/walk.xml, in process) recording every
# output (190 columns, the default) against recording one signal, REPEAT times each (default 7),
# alternating so that machine load hits both alike. The results file is written on a thread of
# its own; what the run's thread pays per row is the difference of the two, per step. Prints the
# medians, ranges and wall and CPU time.
# usage: bench/orchestrator/recording.sh [REPEAT] [BUILD_DIR]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
repeat="${1:-7}"
build="${2:-$root/build}"
stride="$build/bin/stride"
[ -x "$stride" ] || { echo "recording: $stride not found (build first)" >&2; exit 1; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

run() {  # NAME ARGS...: runs the walk, prints "NAME wall-seconds cpu-seconds"
  local name="$1"
  shift
  /usr/bin/time -f "$name %e %U %S" -o "$out/time" \
    "$stride" run "$root/models/walk.xml" --quiet --no-plots --force --output "$out/$name" "$@" \
    > /dev/null
  awk '{ print $1, $2, $3 + $4 }' "$out/time"
}

for _ in $(seq "$repeat"); do
  run all
  run one --signals robot.gyro_fb
done > "$out/times"
[ "$(head -1 "$out/all/results.csv" | tr ',' '\n' | wc -l)" -gt 100 ] ||
  { echo "recording: the walk records fewer columns than expected" >&2; exit 1; }
python3 - "$out/times" << 'PY'
import statistics, sys
wall, cpu = {}, {}
for line in open(sys.argv[1]):
    name, w, c = line.split()
    wall.setdefault(name, []).append(float(w))
    cpu.setdefault(name, []).append(float(c))
med = statistics.median
for name in ("all", "one"):
    print(f"{name:>3}: wall median {med(wall[name]):.3f} s ({min(wall[name]):.3f}-"
          f"{max(wall[name]):.3f}), CPU median {med(cpu[name]):.3f} s")
extra = (med(wall["all"]) - med(wall["one"])) / 7500 * 1e6
print(f"recording every output costs the run {extra:.1f} us of wall time per step")
PY
