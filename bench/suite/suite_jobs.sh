#!/usr/bin/env bash
# Wall time of a regression suite run by `stride test` with --jobs 1 and with --jobs 2, each
# REPEAT times (default 5), alternating so that drifting machine load hits both alike; prints the
# median and range of each and the median speed-up. Cases are separate processes, so with N cores
# the ideal is min(N, cases) times faster, less what the longest case leaves unshared.
# usage: bench/suite/suite_jobs.sh [SUITE] [REPEAT] [BUILD_DIR]
#        (defaults models/regression/darwin.xml, 5, build/)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
suite="${1:-$root/models/regression/darwin.xml}"
repeat="${2:-5}"
build="${3:-$root/build}"
stride="$build/bin/stride"
[ -x "$stride" ] || { echo "suite_jobs: $stride not found (build first)" >&2; exit 1; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

for ((i = 1; i <= repeat; ++i)); do
  for jobs in 1 2; do
    start=$EPOCHREALTIME
    "$stride" test "$suite" --jobs "$jobs" --quiet --output "$out/run" > "$out/last.txt" ||
      { cat "$out/last.txt" >&2; echo "suite_jobs: the suite failed" >&2; exit 1; }
    end=$EPOCHREALTIME
    echo "$jobs $start $end" >> "$out/times.txt"
    echo "run $i, --jobs $jobs: $(tail -n1 "$out/last.txt")" >&2
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
    print(f"--jobs {jobs}: median {statistics.median(s):.2f} s  (min {min(s):.2f}, max {max(s):.2f}, n={len(s)})")
ratios = [a / b for a, b in zip(t[1], t[2])]
print(f"speed-up with 2 jobs: median {statistics.median(ratios):.2f}x  "
      f"(min {min(ratios):.2f}, max {max(ratios):.2f})")
PY
