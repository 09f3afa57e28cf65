#!/usr/bin/env bash
# What periodic checkpoints cost (`stride run --checkpoint-every S`, docs/system-xml.md): the
# 60 s walk (models/walk.xml, in process) without checkpoints and with one every S simulated
# seconds for S in EVERY (default "10 1"), REPEAT times each (default 5), alternating so that
# machine load hits all alike. Prints the median wall time of each and the cost per checkpoint.
# usage: bench/orchestrator/checkpoint_every.sh [REPEAT] [BUILD_DIR]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
repeat="${1:-5}"
build="${2:-$root/build}"
every="${EVERY:-10 1}"
stride="$build/bin/stride"
[ -x "$stride" ] || { echo "checkpoint_every: $stride not found (build first)" >&2; exit 1; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

wall() {  # NAME ARGS...: runs the walk, prints "NAME seconds"
  local name="$1"
  shift
  local start end
  start=$(date +%s.%N)
  "$stride" run "$root/models/walk.xml" --quiet --no-plots --force --output "$out/$name" "$@" \
    > /dev/null
  end=$(date +%s.%N)
  echo "$name $(echo "$end - $start" | bc)"
}

for _ in $(seq "$repeat"); do
  wall none
  for s in $every; do wall "every-$s" --checkpoint-every "$s"; done
done > "$out/times"
for s in $every; do
  cmp -s "$out/none/results.csv" "$out/every-$s/results.csv" ||
    { echo "checkpoint_every: the results differ with --checkpoint-every $s" >&2; exit 1; }
done
python3 - "$out/times" "$every" << 'PY'
import statistics, sys
times = {}
for line in open(sys.argv[1]):
    name, t = line.split()
    times.setdefault(name, []).append(float(t))
med = statistics.median
base = med(times["none"])
print(f"60 s walk without checkpoints: median {base:.3f} s "
      f"(min {min(times['none']):.3f}, max {max(times['none']):.3f})")
for s in sys.argv[2].split():
    t = times[f"every-{s}"]
    n = int(60 / float(s))
    print(f"  --checkpoint-every {s} ({n} checkpoints): median {med(t):.3f} s "
          f"(min {min(t):.3f}, max {max(t):.3f}); {(med(t) - base) / n * 1e3:.2f} ms each")
PY
