#!/usr/bin/env bash
# What failover costs (docs/failover.md), on the 60 s walk with the robot on a worker
# (models/distributed/walk-robot-on-worker.xml), each measurement REPEAT times (default 5,
# alternating so that machine load hits all alike); prints medians and ranges.
#  1. State images: wall time without standby workers against `--standby s1 --snapshot-every N`
#     for N in INTERVALS (default "1 10 100"); the ratio per round, then its median. N = 1 (an
#     image after every step) shows what one image costs: (t1 - t0) / steps.
#  2. Failover time: a run with `--standby s1`, its worker w1 killed (SIGKILL) once the results
#     hold KILL_AT bytes (default 4 000 000, a fifth of the walk); the time from the kill to the
#     log line that says the robot continues on s1, which is written just before the first step
#     there. It holds the lapse of w1's DDS liveliness (1 s lease), loading the robot on s1 (the
#     archive is shipped in the first round only) and the replay.
#  3. Packets lost: the first 4 s of the walk with the worker and the run dropping 5 % of the
#     packets they send (Cyclone DDS's test option Internal/Test/XmitLossiness = 50), against no
#     loss; every lost packet waits for DDS's reliable repair (heartbeat, acknack, resend).
# usage: bench/remote/failover.sh [REPEAT] [BUILD_DIR] [DOMAIN] (defaults 5, build/, 153)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
# shellcheck source=bench/remote/lib.sh
source "$root/bench/remote/lib.sh"
repeat="${1:-5}"
build="${2:-$root/build}"
domain="${3:-153}"
intervals="${INTERVALS:-1 10 100}"
kill_at="${KILL_AT:-4000000}"
stride="$build/bin/stride"
walk="$root/models/distributed/walk-robot-on-worker.xml"
[ -x "$stride" ] || { echo "failover: $stride not found (build first)" >&2; exit 1; }
out="$(mktemp -d)"
declare -A pids=()
trap 'for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null; done; wait; rm -rf "$out"' EXIT

start_worker() {  # NAME [ARGS...]: starts it and waits until it is ready
  "$stride" worker --name "$1" --domain "$domain" "${@:2}" > "$out/$1.log" 2>&1 &
  pids[$1]=$!
  wait_ready "$out/$1.log"
}
start_worker w1
start_worker s1

timed() {  # LABEL ARGS...: appends "LABEL seconds" to times.txt
  local label="$1"
  shift
  local start=$EPOCHREALTIME
  "$stride" run "$walk" --quiet --domain "$domain" --output "$out/run" "$@" > "$out/last.txt" 2>&1 ||
    { cat "$out/last.txt" >&2; echo "failover: a run failed" >&2; exit 1; }
  local end=$EPOCHREALTIME
  rm -rf "$out/run"
  echo "$label $(python3 -c "print($end - $start)")" >> "$out/times.txt"
}

for ((i = 1; i <= repeat; ++i)); do
  timed plain
  for n in $intervals; do timed "every-$n" --standby s1 --snapshot-every "$n"; done
  echo "round $i of $repeat (images) done" >&2
done

for ((i = 1; i <= repeat; ++i)); do
  "$stride" run "$walk" --domain "$domain" --output "$out/run" --standby s1 > "$out/run.log" 2>&1 &
  run=$!
  until [ "$(stat -c %s "$out/run/results.csv" 2> /dev/null || echo 0)" -ge "$kill_at" ]; do
    kill -0 "$run" 2>/dev/null || { cat "$out/run.log" >&2; echo "failover: ended early" >&2; exit 1; }
    sleep 0.001
  done
  killed=$EPOCHREALTIME
  kill -KILL "${pids[w1]}"
  wait "${pids[w1]}" 2>/dev/null || true
  until grep -q "continues on standby worker 's1'" "$out/run.log"; do
    kill -0 "$run" 2>/dev/null || { cat "$out/run.log" >&2; echo "failover: no failover" >&2; exit 1; }
    sleep 0.001
  done
  took=$EPOCHREALTIME
  wait "$run" || { cat "$out/run.log" >&2; echo "failover: the run failed" >&2; exit 1; }
  replay=$(grep -o "steps replayed in [0-9]* ms" "$out/run.log" | grep -o "[0-9]* ms" | cut -d' ' -f1)
  echo "failover $(python3 -c "print($took - $killed)") $replay" >> "$out/times.txt"
  rm -rf "$out/run"
  # s1 now holds the run's instance no longer; w1 comes back for the next round
  start_worker w1
  echo "round $i of $repeat (failover) done" >&2
done

sed 's|</Internal>|<Test><XmitLossiness>50</XmitLossiness></Test></Internal>|' \
  "$root/remote/config/loopback.xml" > "$out/lossy.xml"
kill -TERM "${pids[w1]}" && wait "${pids[w1]}" 2>/dev/null || true
start_worker w1 --dds-config "$out/lossy.xml"
for ((i = 1; i <= repeat; ++i)); do
  timed lossy --stop-time 4 --dds-config "$out/lossy.xml"
  echo "round $i of $repeat (lossy) done" >&2
done
kill -TERM "${pids[w1]}" && wait "${pids[w1]}" 2>/dev/null || true
start_worker w1
for ((i = 1; i <= repeat; ++i)); do timed clean --stop-time 4; done

python3 - "$out/times.txt" "$intervals" <<'PY'
import collections, statistics, sys
t = collections.defaultdict(list)
replays = []
for line in open(sys.argv[1]):
    label, seconds, *rest = line.split()
    t[label].append(float(seconds))
    if rest:
        replays.append(float(rest[0]))
med = statistics.median
plain = t["plain"]
print(f"60 s walk, robot on a worker, no standby: median {med(plain):.2f} s "
      f"(min {min(plain):.2f}, max {max(plain):.2f}, n={len(plain)})")
for n in sys.argv[2].split():
    s = t[f"every-{n}"]
    r = [b / a for a, b in zip(plain, s)]
    print(f"  --snapshot-every {n}: median {med(s):.2f} s (min {min(s):.2f}, max {max(s):.2f}); "
          f"/ no standby: median x{med(r):.3f} (min x{min(r):.3f}, max x{max(r):.3f})")
f = t["failover"]
print(f"failover, kill to the first step on the standby: median {med(f) * 1e3:.0f} ms "
      f"(min {min(f) * 1e3:.0f}, max {max(f) * 1e3:.0f}, n={len(f)}); of it the load and "
      f"replay on the standby: median {med(replays):.0f} ms (min {min(replays):.0f}, "
      f"max {max(replays):.0f})")
for label, what in (("clean", "no loss"), ("lossy", "5 % of packets dropped")):
    s = t[label]
    print(f"4 s of the walk, robot on a worker, {what}: median {med(s):.2f} s "
          f"(min {min(s):.2f}, max {max(s):.2f})")
PY
