#!/usr/bin/env bash
# Where one remote step's time goes: the walk with the robot on a worker
# (models/distributed/walk-robot-on-worker.xml) run to STOP seconds while `perf` records the
# kernel's scheduler switches and the processes' sendmsg/recvmsg calls; then, per step, the
# medians (10th–90th percentiles) of
#   request in flight   the run's sendmsg of the request → the worker's receive thread has it
#   worker receive      how long that thread then runs (decoding, delivery) before it sleeps
#   request to reply    the worker's receive thread has the request → the worker's sendmsg of
#                       the reply (the receive thread's part, the serving thread's pick-up, the
#                       component's step, encoding)
#   reply in flight     the worker's sendmsg → the run's receive thread has the reply
#   run receive         how long that thread then runs before it sleeps
#   reply to request    the run's receive thread has the reply → the run's next request sent
# MODE: none (default), sign or encrypt (worker and run with identities of one keystore).
# Needs `perf` and the right to trace the kernel (root, or kernel.perf_event_paranoid ≤ -1);
# exits with 77 (skipped) and says why when either is missing.
# usage: bench/remote/step_timeline.sh [MODE] [BUILD_DIR] [DOMAIN] [STOP]
#        (defaults none, build/, 186, 8)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
# shellcheck source=bench/remote/lib.sh
source "$root/bench/remote/lib.sh"
mode="${1:-none}"
build="${2:-$root/build}"
domain="${3:-186}"
stop="${4:-8}"
stride="$build/bin/stride"
[ -x "$stride" ] || { echo "step_timeline: $stride not found (build first)" >&2; exit 1; }
command -v perf > /dev/null || { echo "step_timeline: skipped: perf is not installed" >&2; exit 77; }
case "$mode" in
  none | sign | encrypt) ;;
  *) echo "step_timeline: MODE is none, sign or encrypt, not '$mode'" >&2; exit 1 ;;
esac
out="$(mktemp -d)"
worker=""
trap '[ -n "$worker" ] && kill -TERM "$worker" 2>/dev/null; wait; rm -rf "$out"' EXIT
events=(-e sched:sched_switch -e syscalls:sys_enter_sendmsg -e syscalls:sys_exit_recvmsg)
if ! perf record -q -a -o "$out/probe.data" "${events[@]}" -- true > "$out/probe.log" 2>&1; then
  echo "step_timeline: skipped: perf cannot trace the kernel here (root needed?):" \
    "$(head -1 "$out/probe.log")" >&2
  exit 77
fi

sed -e "s/stop=\"60\"/stop=\"$stop\"/" "$root/models/distributed/walk-robot-on-worker.xml" \
  > "$out/walk.xml"
worker_args=() run_args=(--domain "$domain" --quiet)
if [ "$mode" != none ]; then
  make_keystore "$stride" "$out/ks" "$domain" "$mode" w1 orchestrator
  worker_args=(--security "$out/ks/w1") run_args+=(--security "$out/ks/orchestrator")
fi
"$stride" worker --name w1 --domain "$domain" "${worker_args[@]}" > "$out/worker.log" 2>&1 &
worker=$!
wait_ready "$out/worker.log"
# the first run ships the FMU; the traced one finds it on the worker
"$stride" run "$out/walk.xml" "${run_args[@]}" --output "$out/first" > /dev/null
# the trace holds every process of the machine: the run writes its process id (the shell's, which
# it takes over) so that only its events and the worker's are read
# shellcheck disable=SC2016 # $$ and "$@" belong to the inner shell
perf record -q -a -o "$out/trace.data" "${events[@]}" -- \
  sh -c 'echo $$ > "$0"; exec "$@"' "$out/run.pid" \
  "$stride" run "$out/walk.xml" "${run_args[@]}" --output "$out/traced" > /dev/null 2> "$out/run.log" ||
  { cat "$out/run.log" >&2; echo "step_timeline: the traced run failed" >&2; exit 1; }
perf script -i "$out/trace.data" -F comm,pid,tid,cpu,time,event,trace > "$out/trace.txt" 2> /dev/null
python3 - "$out/trace.txt" "$worker" "$(cat "$out/run.pid")" "$mode" << 'PY'
import re, statistics, sys
trace, worker, run, mode = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
line = re.compile(r"\s*(\S+)\s+(\d+)/(\d+)\s+\[\d+\]\s+([\d.]+):\s+(\S+):\s*(.*)")
events = []  # (µs, side, thread name, thread id, event, detail)
for text in open(trace):
    m = line.match(text)
    if not m:
        continue
    comm, pid, tid, t, event, detail = m.groups()
    if int(pid) not in (worker, run):
        continue
    side = "worker" if int(pid) == worker else "run"
    events.append((float(t) * 1e6, side, comm, int(tid), event, detail))
step_size = 300  # a step's request or reply is larger than any acknowledgement or heartbeat
marks = []       # (µs, what): the step messages sent and received
wakes = {}       # receive thread → when its recvmsg returned with a step message
runs = {"worker": [], "run": []}
for t, side, comm, tid, event, detail in events:
    if event.endswith("sys_enter_sendmsg") and comm == "stride":
        marks.append((t, side + " sends"))
    elif event.endswith("sys_exit_recvmsg") and comm == "recvUC":
        size = int(detail.split()[-1], 16)
        if size > step_size:
            marks.append((t, side + " receives"))
            wakes[tid] = t
    elif event.endswith("sched_switch") and comm == "recvUC" and tid in wakes \
            and "prev_state=S" in detail:
        runs[side].append(t - wakes.pop(tid))
phases = {("run sends", "worker receives"): "request in flight",
          ("worker receives", "worker sends"): "request to reply",
          ("worker sends", "run receives"): "reply in flight",
          ("run receives", "run sends"): "reply to request"}
spans = {name: [] for name in phases.values()}
for (t0, a), (t1, b) in zip(marks, marks[1:]):
    if (a, b) in phases:
        spans[phases[(a, b)]].append(t1 - t0)
spans["worker receive"] = runs["worker"]
spans["run receive"] = runs["run"]
def show(name):
    v = sorted(spans[name])
    if not v:
        sys.exit(f"step_timeline: no '{name}' in the trace")
    print(f"  {name:18} {statistics.median(v):7.1f} µs ({v[len(v) // 10]:.1f}–{v[9 * len(v) // 10]:.1f})")
print(f"{mode}: {len(spans['request to reply'])} steps")
for name in ("request in flight", "worker receive", "request to reply", "reply in flight",
             "run receive", "reply to request"):
    show(name)
PY
