#!/usr/bin/env bash
# The start-up of a run with the robot on a worker: the walk (models/distributed/
# walk-robot-on-worker.xml) stopped after ten steps, so that its wall time is almost all start-up
# (reading the system, describing the FMUs, joining the DDS domain, finding the worker and, with
# SECURITY, the DDS Security handshake). The worker keeps the robot FMU from a first, untimed run,
# as it does between the runs of a study. Prints the median and range of REPEAT runs.
# SECURITY: none (default) or encrypt (worker and run with identities of one keystore).
# usage: bench/remote/startup.sh [REPEAT] [BUILD_DIR] [DOMAIN] [SECURITY]
#        (defaults 15, build/, 174, none)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
repeat="${1:-15}"
build="${2:-$root/build}"
domain="${3:-174}"
security="${4:-none}"
stride="$build/bin/stride"
[ -x "$stride" ] || { echo "startup: $stride not found (build first)" >&2; exit 1; }
out="$(mktemp -d)"
worker=""
trap '[ -n "$worker" ] && kill -TERM $worker 2>/dev/null; wait; rm -rf "$out"' EXIT

worker_args=() run_args=(--domain "$domain" --quiet)
case "$security" in
  none) ;;
  encrypt)
    "$stride" security init "$out/ks" --domains "$domain" > /dev/null
    for id in w1 orchestrator; do "$stride" security add "$out/ks" "$id" > /dev/null; done
    worker_args=(--security "$out/ks/w1") run_args+=(--security "$out/ks/orchestrator") ;;
  *) echo "startup: SECURITY is none or encrypt, not '$security'" >&2; exit 1 ;;
esac
sed -e 's/stop="60"/stop="0.08"/' "$root/models/distributed/walk-robot-on-worker.xml" \
  > "$out/short.xml"
grep -q 'stop="0.08"' "$out/short.xml" || { echo "startup: cannot shorten the walk" >&2; exit 1; }
"$stride" worker --name w1 --domain "$domain" "${worker_args[@]}" > "$out/worker.log" 2>&1 &
worker=$!
for _ in $(seq 100); do grep -q ready "$out/worker.log" && break; sleep 0.1; done
grep -q ready "$out/worker.log" || { cat "$out/worker.log" >&2; exit 1; }

run() {
  "$stride" run "$out/short.xml" "${run_args[@]}" --output "$out/run" > "$out/last.txt" 2>&1 ||
    { cat "$out/last.txt" >&2; echo "startup: a run failed" >&2; exit 1; }
  rm -rf "$out/run"
}
run  # ships the FMU
for ((i = 1; i <= repeat; ++i)); do
  start=$EPOCHREALTIME
  run
  end=$EPOCHREALTIME
  python3 -c "print($end - $start)" >> "$out/times.txt"
done
sort -g "$out/times.txt" | awk -v s="$security" -v n="$repeat" '
  { t[NR] = $1 }
  END { printf "start-up, security %s: median %.3f s (%.3f-%.3f), %d runs\n",
        s, t[int((NR + 1) / 2)], t[1], t[NR], n }'
