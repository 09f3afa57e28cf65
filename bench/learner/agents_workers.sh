#!/usr/bin/env bash
# RL steps per wall second of Experiment 1 (paper protocol) learned by N synchronous agents on
# N loopback `stride worker` processes (docs/swarm.md: agent k's loop steps as one group on its
# worker, one DDS round trip per 8 ms communication step), for each N given, REPEAT times
# (default 3); prints the median and range for each N.
# usage: bench/learner/agents_workers.sh [STEPS] [REPEAT] [BUILD_DIR] [N ...]
#        (defaults 2000, 3, build/, 2 4)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
steps="${1:-2000}"
repeat="${2:-3}"
build="${3:-$root/build}"
shift $(($# < 3 ? $# : 3))
counts=("$@")
[ ${#counts[@]} -gt 0 ] || counts=(2 4)
stride="$build/bin/stride"
[ -x "$stride" ] || { echo "agents_workers: $stride not found (build first)" >&2; exit 1; }
domain=97
out="$(mktemp -d)"
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2> /dev/null || true; done
  wait 2> /dev/null || true
  rm -rf "$out"
}
trap cleanup EXIT

max=0
for n in "${counts[@]}"; do ((n > max)) && max=$n; done
names=()
for ((w = 1; w <= max; ++w)); do
  "$stride" worker --name "bw$w" --domain "$domain" > "$out/bw$w.log" 2>&1 &
  pids+=($!)
  names+=("bw$w")
done
for ((w = 1; w <= max; ++w)); do
  for _ in $(seq 200); do grep -q " ready on DDS domain " "$out/bw$w.log" && break; sleep 0.05; done
done

for n in "${counts[@]}"; do
  # <agents> follows <simulation> (the schema's order)
  sed "s|\(<simulation [^>]*/>\)|\1\n  <agents count=\"$n\" workers=\"${names[*]:0:$n}\"/>|" \
    "$root/models/experiments/exp1-learn-x20.xml" > "$out/agents$n.xml"
  grep -q "<agents count=\"$n\"" "$out/agents$n.xml" ||
    { echo "agents_workers: no one-line <simulation .../> element to follow" >&2; exit 1; }
done
for ((i = 1; i <= repeat; ++i)); do
  for n in "${counts[@]}"; do
    rm -rf "$out/run"
    start=$EPOCHREALTIME
    "$stride" run "$out/agents$n.xml" --quiet --no-plots --domain "$domain" \
      --set learner.total_steps="$steps" --set learner.snapshot_steps= --output "$out/run" \
      > "$out/last.txt" 2>&1 || { cat "$out/last.txt" >&2; echo "agents_workers: failed" >&2; exit 1; }
    end=$EPOCHREALTIME
    echo "$n $start $end" >> "$out/times.txt"
    echo "run $i, $n agents on workers: $(python3 -c "print(f'{$steps / ($end - $start):.1f} RL steps/s')")" >&2
  done
done

python3 - "$out/times.txt" "$steps" <<'PY'
import statistics, sys
steps = float(sys.argv[2])
rates = {}
for line in open(sys.argv[1]):
    n, start, end = line.split()
    rates.setdefault(int(n), []).append(steps / (float(end) - float(start)))
for n in sorted(rates):
    r = rates[n]
    print(f"{n} agents on {n} workers: median {statistics.median(r):7.1f} RL steps/s  "
          f"(min {min(r):.1f}, max {max(r):.1f}, n={len(r)})")
PY
