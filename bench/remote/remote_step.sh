#!/usr/bin/env bash
# The cost of a component on a `stride worker` over Cyclone DDS on loopback, against the same run
# in-process, each measurement REPEAT times (default 5, alternating so that machine load hits both
# alike); prints medians and ranges.
#  1. Round trip of one remote step: the stride_test pair (tests/orchestrator/data) with b on a
#     worker, run for 2 000 and for 20 000 steps; (t20000 - t2000) / 18 000 removes start-up and
#     is the wall time of one communication step, request and reply included.
#  2. The 60 s DARwIn-OP walk (models/walk.xml) with the robot on a worker
#     (models/distributed/walk-robot-on-worker.xml) against in-process: wall time, times real
#     time, and the ratio; and with gait and robot on one worker stepping as a group
#     (models/distributed/walk-on-one-worker.xml) against the two on two workers (two requests
#     per step, one after the other).
#  3. The start-up of a run with b on a worker (the 2 000-step run less its 2 000 steps): joining
#     the domain, finding the worker, shipping the FMU; with SECURITY, the DDS Security
#     handshakes too.
# SECURITY: none (default), sign or encrypt: workers and runs with identities of a keystore made
# with that protection (docs/distributed.md).
# usage: bench/remote/remote_step.sh [REPEAT] [BUILD_DIR] [DOMAIN] [SECURITY]
#        (defaults 5, build/, 90, none)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
# shellcheck source=bench/remote/lib.sh
source "$root/bench/remote/lib.sh"
repeat="${1:-5}"
build="${2:-$root/build}"
domain="${3:-90}"
security="${4:-none}"
stride="$build/bin/stride"
[ -x "$stride" ] || { echo "remote_step: $stride not found (build first)" >&2; exit 1; }
out="$(mktemp -d)"
worker=""
trap '[ -n "$worker" ] && kill -TERM $worker 2>/dev/null; wait; rm -rf "$out"' EXIT

w1_args=() w2_args=() run_args=(--domain "$domain")
case "$security" in
  none) ;;
  sign | encrypt)
    make_keystore "$stride" "$out/ks" "$domain" "$security" w1 w2 orchestrator
    w1_args=(--security "$out/ks/w1") w2_args=(--security "$out/ks/w2")
    run_args+=(--security "$out/ks/orchestrator") ;;
  *) echo "remote_step: SECURITY is none, sign or encrypt, not '$security'" >&2; exit 1 ;;
esac
echo "security: $security"
"$stride" worker --name w1 --domain "$domain" "${w1_args[@]}" > "$out/worker.log" 2>&1 &
worker=$!
"$stride" worker --name w2 --domain "$domain" "${w2_args[@]}" > "$out/worker2.log" 2>&1 &
worker="$worker $!"
for log in worker worker2; do wait_ready "$out/$log.log"; done
sed -e 's|<component name="robot" fmu="robot" worker="w1"/>|<component name="robot" fmu="robot" worker="w2"/>|' \
  "$root/models/distributed/walk-on-one-worker.xml" > "$out/walk-split.xml"
grep -q 'worker="w2"' "$out/walk-split.xml" || { echo "remote_step: cannot split the walk" >&2; exit 1; }

pair="$root/tests/orchestrator/data/stride_test_pair.xml"
for steps in 2000 20000; do
  stop=$(python3 -c "print($steps / 100)")
  sed -e "s/stop=\"1\"/stop=\"$stop\"/" "$pair" > "$out/local-$steps.xml"
  sed -e "s/<component name=\"b\" fmu=\"stride_test\"/& worker=\"w1\"/" "$out/local-$steps.xml" \
    > "$out/remote-$steps.xml"
done

timed() {  # LABEL SYSTEM ARGS...: appends "LABEL seconds" to times.txt
  local label="$1" system="$2"
  shift 2
  local start=$EPOCHREALTIME
  "$stride" run "$system" --quiet --output "$out/run" "$@" > "$out/last.txt" 2>&1 ||
    { cat "$out/last.txt" >&2; echo "remote_step: a run failed" >&2; exit 1; }
  local end=$EPOCHREALTIME
  rm -rf "$out/run"
  echo "$label $(python3 -c "print($end - $start)")" >> "$out/times.txt"
}

for ((i = 1; i <= repeat; ++i)); do
  for steps in 2000 20000; do
    timed "local-$steps" "$out/local-$steps.xml"
    timed "remote-$steps" "$out/remote-$steps.xml" "${run_args[@]}"
  done
  timed walk-local "$root/models/walk.xml"
  timed walk-remote "$root/models/distributed/walk-robot-on-worker.xml" "${run_args[@]}"
  timed walk-group "$root/models/distributed/walk-on-one-worker.xml" "${run_args[@]}"
  timed walk-split "$out/walk-split.xml" "${run_args[@]}"
  echo "round $i of $repeat done" >&2
done

python3 - "$out/times.txt" <<'PY'
import collections, statistics, sys
t = collections.defaultdict(list)
for line in open(sys.argv[1]):
    label, seconds = line.split()
    t[label].append(float(seconds))
med = lambda xs: statistics.median(xs)
def per_step(kind):
    return [(b - a) / 18000 * 1e6 for a, b in zip(t[f"{kind}-2000"], t[f"{kind}-20000"])]
for kind in ("local", "remote"):
    s = per_step(kind)
    print(f"pair, b {'on a worker' if kind == 'remote' else 'in process'}: "
          f"{med(s):.1f} us per step (min {min(s):.1f}, max {max(s):.1f}, n={len(s)})")
up = [t2000 - 2000 * s * 1e-6 for t2000, s in zip(t["remote-2000"], per_step("remote"))]
print(f"start-up of a run with b on a worker: {med(up) * 1e3:.0f} ms "
      f"(min {min(up) * 1e3:.0f}, max {max(up) * 1e3:.0f})")
for kind in ("local", "remote"):
    s = t[f"walk-{kind}"]
    print(f"60 s walk, robot {'on a worker' if kind == 'remote' else 'in process'}: median "
          f"{med(s):.2f} s = {60 / med(s):.0f}x real time (min {min(s):.2f}, max {max(s):.2f})")
r = [b / a for a, b in zip(t["walk-local"], t["walk-remote"])]
print(f"walk remote / in process: median {med(r):.2f}x (min {min(r):.2f}, max {max(r):.2f})")
for kind, what in (("group", "gait + robot on one worker (a group)"),
                   ("split", "gait on w1, robot on w2")):
    s = t[f"walk-{kind}"]
    print(f"60 s walk, {what}: median {med(s):.2f} s = {60 / med(s):.0f}x real time "
          f"(min {min(s):.2f}, max {max(s):.2f})")
PY
