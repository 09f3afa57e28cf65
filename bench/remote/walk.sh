#!/usr/bin/env bash
# The walk with the robot on a worker (models/distributed/walk-robot-on-worker.xml), run REPEAT
# times to STOP seconds of simulated time. Prints the median and range of the whole process's wall
# time and of the simulation loop alone (the manifest's wall_time_s). The worker keeps the robot
# FMU from a first, untimed run, as it does between the runs of a study.
# MODES: one or several of none (no security), sign, encrypt (worker and run with identities of
# one keystore made with that protection) and local (the same walk in process, models/walk.xml,
# no worker), separated by commas; default none.
# BUILDS: one build directory, or several separated by commas.
# Every build runs in every mode; the runs take turns, so that the machine's changes of speed from
# minute to minute fall on each alike. Pair k (build, mode) has its own worker on domain
# DOMAIN + k and, with security, its own keystore.
# usage: bench/remote/walk.sh [REPEAT] [BUILDS] [DOMAIN] [MODES] [STOP]
#        (defaults 15, build/, 174, none, 60)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
# shellcheck source=bench/remote/lib.sh
source "$root/bench/remote/lib.sh"
repeat="${1:-15}"
IFS=, read -r -a builds <<< "${2:-$root/build}"
domain="${3:-174}"
IFS=, read -r -a modes <<< "${4:-none}"
stop="${5:-60}"
for b in "${builds[@]}"; do
  [ -x "$b/bin/stride" ] || { echo "walk: $b/bin/stride not found (build first)" >&2; exit 1; }
done
for m in "${modes[@]}"; do
  case "$m" in
    none | sign | encrypt | local) ;;
    *) echo "walk: a mode is none, sign, encrypt or local, not '$m'" >&2; exit 1 ;;
  esac
done
out="$(mktemp -d)"
workers=()
trap 'for w in "${workers[@]}"; do kill -TERM "$w" 2>/dev/null; done; wait; rm -rf "$out"' EXIT
for system in distributed/walk-robot-on-worker walk; do
  sed -e "s/stop=\"60\"/stop=\"$stop\"/" "$root/models/$system.xml" > "$out/${system##*/}.xml"
  grep -q "stop=\"$stop\"" "$out/${system##*/}.xml" ||
    { echo "walk: cannot set the stop time of $system.xml" >&2; exit 1; }
done

# pair k: a build in a mode, with its own worker (on domain DOMAIN + k) and, with security, a
# keystore made by the build's own `stride security init`: a change on either side is measured
# whole
pair_build=() pair_mode=() run_args=()
for b in "${builds[@]}"; do
  for m in "${modes[@]}"; do
    k=${#pair_build[@]} pair_build+=("$b") pair_mode+=("$m")
    stride="$b/bin/stride" d=$((domain + k)) worker_args=()
    if [ "$m" = local ]; then
      run_args[k]="$out/walk.xml --quiet"
      continue
    fi
    run_args[k]="$out/walk-robot-on-worker.xml --domain $d --quiet"
    if [ "$m" != none ]; then
      make_keystore "$stride" "$out/ks$k" "$d" "$m" w1 orchestrator
      worker_args=(--security "$out/ks$k/w1")
      run_args[k]+=" --security $out/ks$k/orchestrator"
    fi
    "$stride" worker --name w1 --domain "$d" "${worker_args[@]}" > "$out/worker$k.log" 2>&1 &
    workers+=($!)
    wait_ready "$out/worker$k.log"
  done
done

# appends "whole loop" seconds of one run of pair number $1 to $2
run() {
  local start end
  start=$EPOCHREALTIME
  # shellcheck disable=SC2086 # the arguments hold no spaces
  "${pair_build[$1]}/bin/stride" run ${run_args[$1]} --output "$out/run" \
    > "$out/last.txt" 2>&1 ||
    { cat "$out/last.txt" >&2; echo "walk: a run failed" >&2; exit 1; }
  end=$EPOCHREALTIME
  python3 - "$start" "$end" "$out/run/manifest.json" >> "$2" << 'EOF'
import json, sys
print(float(sys.argv[2]) - float(sys.argv[1]), json.load(open(sys.argv[3]))["wall_time_s"])
EOF
  rm -rf "$out/run"
}
for k in "${!pair_build[@]}"; do run "$k" /dev/null; done  # ships the FMU
for ((i = 1; i <= repeat; ++i)); do
  for k in "${!pair_build[@]}"; do run "$k" "$out/times.$k"; done
done
for k in "${!pair_build[@]}"; do
  python3 - "$out/times.$k" "${pair_build[$k]}" "${pair_mode[$k]}" "$stop" << 'EOF'
import statistics, sys
rows = [tuple(map(float, l.split())) for l in open(sys.argv[1])]
whole, loop = ([r[i] for r in rows] for i in (0, 1))
print(f"{sys.argv[2]}: walk to {sys.argv[4]} s, {sys.argv[3]}, {len(rows)} runs: "
      f"whole {statistics.median(whole):.3f} s ({min(whole):.3f}-{max(whole):.3f}), "
      f"loop {statistics.median(loop):.3f} s ({min(loop):.3f}-{max(loop):.3f}), "
      f"{float(sys.argv[4]) / statistics.median(whole):.1f}x real time")
EOF
done
