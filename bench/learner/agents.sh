#!/usr/bin/env bash
# RL steps per wall second of Experiment 1 (paper protocol) learned by one agent (a plain run),
# by 2 agents in synchronous rounds, by 2 asynchronous agents and by 4 agents in synchronous
# rounds (more agents than cores: one agent's wait for a round leaves its core to another), agents
# on threads of one process sharing V (docs/swarm.md). Each case REPEAT times (default 3),
# alternating so that drifting machine load hits all alike; prints the median and range of each
# and the speed-ups.
# usage: bench/learner/agents.sh [STEPS] [REPEAT] [BUILD_DIR]   (defaults 3000, 3, build/)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
steps="${1:-3000}"
repeat="${2:-3}"
build="${3:-$root/build}"
stride="$build/bin/stride"
[ -x "$stride" ] || { echo "agents: $stride not found (build first)" >&2; exit 1; }
system="$root/models/experiments/exp1-learn-x20.xml"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

run_case() {  # name, extra arguments...
  local name="$1"
  shift
  rm -rf "$out/run"
  local start=$EPOCHREALTIME
  "$stride" run "$system" --quiet --no-plots --set learner.total_steps="$steps" \
    --set learner.snapshot_steps= --output "$out/run" "$@" > "$out/last.txt" 2>&1 ||
    { cat "$out/last.txt" >&2; echo "agents: $name failed" >&2; exit 1; }
  local end=$EPOCHREALTIME
  echo "$name $start $end" >> "$out/times.txt"
  echo "run $i, $name: $(python3 -c "print(f'{$steps / ($end - $start):.1f} RL steps/s')")" >&2
}

# <agents> follows <simulation> (the schema's order)
sed 's|\(<simulation [^>]*/>\)|\1\n  <agents count="2" mode="asynchronous"/>|' "$system" \
  > "$out/async.xml"
grep -q '<agents count="2" mode="asynchronous"/>' "$out/async.xml" ||
  { echo "agents: no one-line <simulation .../> element in $system" >&2; exit 1; }
for ((i = 1; i <= repeat; ++i)); do
  run_case one
  run_case sync2 --agents 2
  system_async="$out/async.xml"
  system_saved="$system"
  system="$system_async"
  run_case async2
  system="$system_saved"
  run_case sync4 --agents 4
done

python3 - "$out/times.txt" "$steps" <<'PY'
import statistics, sys
steps = float(sys.argv[2])
rates = {}
for line in open(sys.argv[1]):
    name, start, end = line.split()
    rates.setdefault(name, []).append(steps / (float(end) - float(start)))
labels = {"one": "1 agent (plain run)", "sync2": "2 agents, synchronous",
          "async2": "2 agents, asynchronous", "sync4": "4 agents, synchronous"}
for name in ("one", "sync2", "async2", "sync4"):
    r = rates[name]
    print(f"{labels[name]:24s} median {statistics.median(r):7.1f} RL steps/s  "
          f"(min {min(r):.1f}, max {max(r):.1f}, n={len(r)})")
for name in ("sync2", "async2", "sync4"):
    print(f"speed-up {labels[name]}: {statistics.median(rates[name]) / statistics.median(rates['one']):.2f}x")
PY
