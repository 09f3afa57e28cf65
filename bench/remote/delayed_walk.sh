#!/usr/bin/env bash
# The walk's speed with its worker 2 ms away (docs/failover.md): the 60 s walk with the robot on
# a worker in another network namespace, joined to the orchestrator's by a link that delays every
# packet 2 ms each way (tests/remote/lossy_link between two TUN devices), REPEAT times (default
# 3); prints each wall time and the median. Every step is one request and one reply, so the
# walk is bounded by 7 500 round trips of 4 ms. STOP (default 60) shortens the walk. Needs root,
# as the test it runs (otherwise it exits 77, saying so).
# usage: bench/remote/delayed_walk.sh [REPEAT] [BUILD_DIR] [STOP]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
repeat="${1:-3}"
build="${2:-$root/build}"
stop="${3:-60}"
[ "$(id -u)" -eq 0 ] || { echo "delayed_walk: needs root for network namespaces"; exit 77; }
link="$build/tests/remote/lossy_link"
[ -x "$link" ] || { echo "delayed_walk: $link not found (build first)" >&2; exit 1; }
times=()
for _ in $(seq "$repeat"); do
  line=$("$root/tests/remote/netns_failover_test.sh" "$build/bin/stride" "$root" delay "$link" \
    "$stop" | grep "s walk with")
  echo "$line"
  times+=("${line##*: }")
done
printf '%s\n' "${times[@]}" | sed 's/ s$//' | sort -n |
  awk -v stop="$stop" '{ t[NR] = $1 }
    END { m = t[int((NR + 1) / 2)]; printf "median %.2f s = %.2f x real time\n", m, stop / m }'
