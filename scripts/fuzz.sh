#!/usr/bin/env bash
# A fuzzing campaign on the sanitizer build (scripts/sanitize.sh builds it): every target of
# fuzz/ for SECONDS (default 600), PARALLEL at a time (default 2), starting from its seed corpus.
# New inputs go to build-sanitize/fuzz/new-inputs/<target>/, crashes to build-sanitize/fuzz/crashes/.
# Prints one line per target: runs, coverage, corpus size, and whether it found anything.
# usage: scripts/fuzz.sh [SECONDS] [PARALLEL]
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${STRIDE_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
seconds="${1:-600}"
parallel="${2:-2}"
targets=(system_xml_fuzz suite_xml_fuzz model_description_fuzz fmu_check_fuzz fmu_archive_fuzz
         config_ini_fuzz posture_fuzz urdf_fuzz checkpoint_fuzz view_frames_fuzz)
for t in "${targets[@]}"; do
  [ -x "$build/fuzz/$t" ] || { echo "fuzz: $build/fuzz/$t not built (run scripts/sanitize.sh)"; exit 1; }
done
mkdir -p "$build/fuzz/crashes" "$build/fuzz/logs"
export LSAN_OPTIONS="suppressions=$root/fuzz/lsan.supp"

run_one() {
  local t="$1"
  mkdir -p "$build/fuzz/new-inputs/$t"
  "$build/fuzz/$t" -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$build/fuzz/crashes/$t-" \
    "$build/fuzz/new-inputs/$t" "$root/fuzz/corpus/$t" > "$build/fuzz/logs/$t.log" 2>&1
  local rc=$?
  local runs cov corpus
  runs="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$build/fuzz/logs/$t.log" | grep -o '[0-9]*$')"
  cov="$(grep -o 'cov: [0-9]*' "$build/fuzz/logs/$t.log" | tail -1 | grep -o '[0-9]*')"
  corpus="$(ls "$build/fuzz/new-inputs/$t" | wc -l)"
  if [ "$rc" -eq 0 ]; then
    echo "fuzz: $t: ${seconds} s, ${runs:-?} runs, coverage ${cov:-?}, corpus $corpus new inputs, nothing found"
  else
    echo "fuzz: $t: FOUND A PROBLEM (exit $rc), see $build/fuzz/logs/$t.log and $build/fuzz/crashes/"
  fi
  return "$rc"
}

status=0
running=0
for t in "${targets[@]}"; do
  run_one "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$parallel" ]; then
    wait -n || status=1
    running=$((running - 1))
  fi
done
while [ "$running" -gt 0 ]; do
  wait -n || status=1
  running=$((running - 1))
done
exit "$status"
