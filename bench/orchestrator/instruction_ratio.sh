#!/usr/bin/env bash
# libstride's overhead in the walking closed loop, counted in instructions (callgrind) instead of
# time: wall-clock medians on a shared 2-core VM move by +-10 % between runs, instruction counts
# do not. Profiles stride_walk and hand_written_walk (orchestrator_bench) and compares, per
# component step, what stride's execution spends in simulate_until with what the hand-written
# loop spends in the same component steps (each: the sets, doStep and gets of the exchanged
# variables). Per step, because Google Benchmark may run a different number of iterations.
# usage: bench/orchestrator/instruction_ratio.sh [BUILD_DIR]   (default build/)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build}"
bench="$build/bench/orchestrator/orchestrator_bench"
[ -x "$bench" ] || { echo "instruction_ratio: $bench not found (build first)" >&2; exit 1; }
command -v valgrind > /dev/null || { echo "instruction_ratio: valgrind not found" >&2; exit 1; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

profile() {  # benchmark filter, output file
  valgrind --tool=callgrind --callgrind-out-file="$2" "$bench" --benchmark_filter="$1" \
    --benchmark_min_time=0.000001 > /dev/null 2> "$2.log" ||
    { cat "$2.log" >&2; exit 1; }
}
profile '^stride_walk/' "$out/stride.out"
profile '^hand_written_walk' "$out/hand.out"

python3 - "$out/stride.out" "$out/hand.out" <<'PY'
import re, subprocess, sys

def inclusive(file, pattern):
    # inclusive instructions of the functions whose names match, summed
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", file],
                          capture_output=True, text=True).stdout
    total = 0
    for line in text.splitlines():
        m = re.match(r"\s*([\d,]+)\s", line)
        if m and re.search(pattern, line):
            total += int(m.group(1).replace(",", ""))
    return total

def calls(file, pattern):
    # how often functions whose names match were called (callgrind's calls= lines)
    # a compressed name is spelled out once, on an fn= or a cfn= line, and later given by number
    names, current, count = {}, None, 0
    for line in open(file, errors="replace"):
        m = re.match(r"(c?)fn=\((\d+)\)(?: (.*))?", line)
        if m:
            if m.group(3):
                names[m.group(2)] = m.group(3)
            if m.group(1):
                current = names.get(m.group(2), "")
        elif line.startswith("calls=") and current and re.search(pattern, current):
            count += int(line.split("=")[1].split()[0])
    return count

step = r"fmu_component::step\("
stride_file, hand_file = sys.argv[1], sys.argv[2]
stride_total = inclusive(stride_file, r"execution::simulate_until\(")
stride_in_steps = inclusive(stride_file, step)
stride_steps = calls(stride_file, step)
hand_total = inclusive(hand_file, step)
hand_steps = calls(hand_file, step)
if stride_steps == 0 or hand_steps == 0:
    sys.exit("instruction_ratio: no calls of fmu_component::step found in the profiles "
             "(renamed?)")
per_stride = stride_total / stride_steps
per_hand = hand_total / hand_steps
print(f"stride simulate_until: {stride_total} instructions over {stride_steps} component steps "
      f"({stride_in_steps} in the steps)")
print(f"hand-written loop: {hand_total} instructions in {hand_steps} component steps")
print(f"ratio {per_stride / per_hand:.4f} per component step; orchestration "
      f"{(stride_total - stride_in_steps) / (stride_steps / 2):.0f} instructions per 8 ms step "
      f"(two components)")
PY
