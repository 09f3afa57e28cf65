#!/usr/bin/env bash
# libstride's overhead in the walking closed loop, counted in instructions (callgrind) instead of
# time: wall-clock medians on a shared 2-core VM move by +-10 % between runs, instruction counts
# do not. Runs one iteration of stride_walk and of hand_written_walk (orchestrator_bench) and
# compares what stride's execution spends in simulate_until with what the hand-written loop
# spends in the same component steps (each: the sets, doStep and gets of the exchanged variables).
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
# inclusive instructions of the functions whose names match $2 (summed)
inclusive() {
  callgrind_annotate --inclusive=yes --threshold=100 "$1" 2> /dev/null |
    grep -E "$2" | awk '{gsub(",", "", $1); s += $1} END {printf "%.0f\n", s}'
}

profile '^stride_walk' "$out/stride.out"
profile '^hand_written_walk' "$out/hand.out"
calls='fmu_component::step\('
stride=$(inclusive "$out/stride.out" 'execution::simulate_until\(')
hand=$(inclusive "$out/hand.out" "$calls")
in_fmus=$(inclusive "$out/stride.out" "$calls")
awk -v s="$stride" -v h="$hand" -v f="$in_fmus" 'BEGIN {
  printf "stride simulate_until: %.0f instructions (%.0f in FMU calls)\n", s, f
  printf "hand-written loop, FMU calls: %.0f instructions\n", h
  printf "ratio %.4f; orchestration %.0f instructions per 8 ms step (1250 steps)\n", s / h, (s - f) / 1250
}'
