#!/usr/bin/env bash
# Wall time of the speed map (`stride sweep --collect speed-map`: every state of Experiment 1's
# grid, 455 points of models/experiments/evaluate-point.xml, 60 s simulated each) with --jobs 1
# and with --jobs 2, each REPEAT times (default 1: a map takes minutes), alternating so that
# drifting machine load hits both alike; every repetition starts from an empty folder. Prints the
# median and range of each and the median speed-up. Points are independent, so with N cores the
# ideal is N times faster. GRID and STOP_TIME make a smaller map for a quick look.
# usage: bench/sweep/speed_map_jobs.sh [REPEAT] [BUILD_DIR] [GRID] [STOP_TIME]
#        (defaults 1, build/, period_time:450:960:15,swing_right_left:15:39:2, 60)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
repeat="${1:-1}"
build="${2:-$root/build}"
grid="${3:-period_time:450:960:15,swing_right_left:15:39:2}"
stop="${4:-60}"
stride="$build/bin/stride"
[ -x "$stride" ] || { echo "speed_map_jobs: $stride not found (build first)" >&2; exit 1; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

for ((i = 1; i <= repeat; ++i)); do
  for jobs in 1 2; do
    rm -rf "$out/map"
    start=$EPOCHREALTIME
    "$stride" sweep "$root/models/experiments/evaluate-point.xml" --collect speed-map \
      --grid "eval.eval_point=$grid" --stop-time "$stop" --jobs "$jobs" --quiet \
      --output "$out/map" > "$out/last.txt" ||
      { cat "$out/last.txt" >&2; echo "speed_map_jobs: the sweep failed" >&2; exit 1; }
    end=$EPOCHREALTIME
    echo "$jobs $start $end" >> "$out/times.txt"
    echo "run $i, --jobs $jobs: $(python3 -c "print(f'{$end - $start:.1f} s')"); $(head -n1 "$out/last.txt")" >&2
  done
done

python3 - "$out/times.txt" <<'PY'
import statistics, sys
t = {1: [], 2: []}
for line in open(sys.argv[1]):
    jobs, start, end = line.split()
    t[int(jobs)].append(float(end) - float(start))
for jobs in (1, 2):
    s = t[jobs]
    print(f"--jobs {jobs}: median {statistics.median(s):.1f} s  (min {min(s):.1f}, max {max(s):.1f}, n={len(s)})")
ratios = [a / b for a, b in zip(t[1], t[2])]
print(f"speed-up with 2 jobs: median {statistics.median(ratios):.2f}x  "
      f"(min {min(ratios):.2f}, max {max(ratios):.2f})")
PY
