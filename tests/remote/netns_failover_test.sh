#!/usr/bin/env bash
# Failover over a real network: three network namespaces on one bridge, "hosts" a (worker w1),
# c (standby s1) and b (the orchestrator), all with the multi-host DDS configuration of docs/dds/
# (unicast discovery, lease 1 s). The walk runs with the robot on w1 and --standby s1.
#   partition: w1's link is cut for 0.5 s (shorter than the lease): nothing changes, the run does
#              not fail over, the stall is logged and counted; then for 3 s: the robot fails over
#              to s1. Both CSVs equal the
#              in-process walk byte for byte, and w1, back on the network, serves the next run.
#   lossy:     w1 (host a) and the orchestrator (host b) talk over a link of their own that
#              delays every packet 2 ms ± 1 ms, drops 5 %, duplicates 1 % and sends 25 % at
#              once, overtaking delayed ones (netem's settings, made in user space by
#              lossy_link between two TUN devices): the CSV equals the in-process walk, and the
#              link did drop, duplicate and reorder packets.
#   delay:     not a test but a figure of BENCHMARKS.md (bench/remote/delayed_walk.sh): the walk
#              (STOP simulated seconds, default 60) over such a link with 2 ms delay only, its
#              wall time printed.
# Needs root (CAP_NET_ADMIN): otherwise it is skipped (exit 77) with the reason.
# usage: netns_failover_test.sh STRIDE_CLI SOURCE_DIR partition|lossy|delay [LOSSY_LINK [STOP]]
set -u
cli="$1"
src="$2"
mode="$3"
lossy_link="${4:-}"
stop="${5:-60}"
skip() {
  echo "SKIPPED: $*"
  exit 77
}
fail() {
  echo "FAILED: $*"
  exit 1
}
[ "$(id -u)" -eq 0 ] || skip "needs root to create network namespaces (running as uid $(id -u))"
command -v ip > /dev/null || skip "the ip tool (iproute2) is not installed"

tag="f$$"
sw="stride-sw-$tag"
work="$(mktemp -d)"
cleanup() {
  # `ip netns exec` forks: the processes inside are found by namespace, not by $!
  for h in a b c; do ip netns pids "stride-$h-$tag" 2> /dev/null | xargs -r kill -TERM; done
  sleep 0.5
  for h in a b c; do ip netns pids "stride-$h-$tag" 2> /dev/null | xargs -r kill -KILL; done
  wait 2> /dev/null
  for h in a b c; do ip netns del "stride-$h-$tag" 2> /dev/null; done
  ip netns del "$sw" 2> /dev/null
  rm -rf "$work"
}
trap cleanup EXIT

ip netns add "$sw" 2> "$work/err" || skip "cannot create a network namespace: $(cat "$work/err")"
ip -n "$sw" link add br0 type bridge || skip "cannot create a bridge"
ip -n "$sw" link set br0 up
declare -A addr=([a]=10.214.0.1 [b]=10.214.0.2 [c]=10.214.0.3)
for h in a b c; do
  ns="stride-$h-$tag"
  ip netns add "$ns" || exit 1
  ip link add "v$h$tag" type veth peer name "s$h$tag" || skip "cannot create a veth pair"
  ip link set "v$h$tag" netns "$ns" && ip link set "s$h$tag" netns "$sw" || exit 1
  ip -n "$sw" link set "s$h$tag" master br0 && ip -n "$sw" link set "s$h$tag" up || exit 1
  ip -n "$ns" addr add "${addr[$h]}/24" dev "v$h$tag" || exit 1
  ip -n "$ns" link set lo up && ip -n "$ns" link set "v$h$tag" up || exit 1
done
# the shipped multi-host configuration with every host as a peer
peers="<Peer address=\"${addr[a]}\"/><Peer address=\"${addr[b]}\"/><Peer address=\"${addr[c]}\"/>"
sed -e "s|<Peer address=\"\${PEER_ADDR}\"/>|$peers|" "$src/docs/dds/multi-host.xml" > "$work/dds.xml"
grep -q "${addr[c]}" "$work/dds.xml" || fail "could not list the peers in the DDS configuration"

iface=v  # the hosts talk on their veth (v) or, over the lossy link, their TUN device (t)
on() {  # HOST COMMAND...: runs it in that host's namespace with its interface
  local h="$1"
  shift
  ip netns exec "stride-$h-$tag" env MY_IFACE="$iface$h$tag" "$@"
}
start_worker() {  # HOST NAME: a worker, waited for until it is ready
  on "$1" "$cli" worker --name "$2" --domain 6 --dds-config "$work/dds.xml" --insecure \
    > "$work/$2.log" 2>&1 &
  for _ in $(seq 100); do
    grep -q "ready" "$work/$2.log" && return
    sleep 0.1
  done
  cat "$work/$2.log"
  fail "worker $2 not ready"
}
start_run() {  # NAME ARGS...: the walk with the robot on w1, in the background (pid in run_pid)
  local name="$1"
  shift
  on b "$cli" run "$src/models/distributed/walk-robot-on-worker.xml" --domain 6 \
    --dds-config "$work/dds.xml" --output "$work/$name" "$@" > "$work/$name.log" 2>&1 &
  run_pid=$!
}
wait_results() {  # NAME BYTES: until the run's results hold BYTES
  for _ in $(seq 30000); do
    [ "$(stat -c %s "$work/$1/results.csv" 2> /dev/null || echo 0)" -ge "$2" ] && return
    kill -0 "$run_pid" 2> /dev/null || { cat "$work/$1.log"; fail "$1 ended early"; }
    sleep 0.002
  done
  fail "$1: no results"
}
cut() {  # SECONDS: host a's port of the bridge forwards nothing for that long. Its link stays
  # up, as when a switch in between stalls: a link going down would also flush the hosts' ARP
  # entries, which then take up to a second more to come back after the link.
  bridge -n "$sw" link set dev "sa$tag" state 0 || fail "cannot disable the bridge port"
  sleep "$1"
  bridge -n "$sw" link set dev "sa$tag" state 3 || fail "cannot enable the bridge port"
}
finish_run() {  # NAME: waits for it; it must succeed and equal the in-process walk
  wait "$run_pid" || { cat "$work/$1.log"; fail "$1 failed"; }
  cmp -s "$work/local/results.csv" "$work/$1/results.csv" || fail "$1: results differ"
}
start_lossy_link() {  # LOSSY_LINK OPTIONS...: hosts a and b joined by it (10.215.0.1 and .2)
  [ -x "$lossy_link" ] || fail "the lossy_link helper is not given"
  for h in a b; do
    on "$h" ip tuntap add dev "t$h$tag" mode tun 2> "$work/tun.err" ||
      skip "no TUN devices here ($(head -c 200 "$work/tun.err"))"
  done
  on a ip addr add 10.215.0.1 peer 10.215.0.2 dev "ta$tag" && on a ip link set "ta$tag" up &&
    on b ip addr add 10.215.0.2 peer 10.215.0.1 dev "tb$tag" && on b ip link set "tb$tag" up ||
    fail "cannot set up the TUN devices"
  "$lossy_link" "/run/netns/stride-a-$tag" "ta$tag" "/run/netns/stride-b-$tag" "tb$tag" "$@" \
    > "$work/link.log" 2>&1 &
  link_pid=$!
  for _ in $(seq 100); do
    grep -q ready "$work/link.log" && break
    sleep 0.05
  done
  grep -q ready "$work/link.log" || { cat "$work/link.log"; fail "lossy_link did not start"; }
  iface=t
  sed -e "s|<Peer address=\"\${PEER_ADDR}\"/>|<Peer address=\"10.215.0.1\"/><Peer address=\"10.215.0.2\"/>|" \
    "$src/docs/dds/multi-host.xml" > "$work/dds.xml"
}
stop_lossy_link() {  # waits for the link to end; what it did is then in link_counts
  kill -TERM "$link_pid"
  wait "$link_pid"  # in this shell: a subshell cannot wait for it
  link_counts=$(grep "packets" "$work/link.log") ||
    { cat "$work/link.log"; fail "lossy_link did not say what it did"; }
  echo "$link_counts"
}

"$cli" run "$src/models/walk.xml" --quiet --output "$work/local" || fail "in-process walk"
fifth=$(($(stat -c %s "$work/local/results.csv") / 5))

case "$mode" in
  partition)
    start_worker a w1
    start_worker c s1
    # a cut shorter than the lease: the run waits and goes on where it was
    start_run short --standby s1
    wait_results short "$fifth"
    cut 0.5
    finish_run short
    grep -q "is lost" "$work/short.log" && { cat "$work/short.log"; fail "a 0.5 s cut failed over"; }
    # but it is told: each reply the cut held up is one line and counted
    stalls=$(grep -c "the network held up the reply of worker 'w1'" "$work/short.log")
    [ "$stalls" -ge 1 ] || { cat "$work/short.log"; fail "the 0.5 s cut was not logged"; }
    grep -q "\"stalls\": $stalls}" "$work/short/manifest.json" ||
      { cat "$work/short/manifest.json"; fail "the manifest does not count $stalls stalls"; }
    # a cut longer than the lease: the robot fails over to s1
    start_run long --standby s1
    wait_results long "$fifth"
    cut 3
    finish_run long
    grep -q "worker 'w1' is lost after t = .* continues on standby worker 's1'" "$work/long.log" ||
      { cat "$work/long.log"; fail "no failover line"; }
    grep -q '"failovers": 1' "$work/long/manifest.json" || fail "the manifest does not count it"
    # w1, back on the network, is not held by the old run and serves the next one
    start_run next --quiet
    finish_run next
    echo "PASSED: a 0.5 s cut changes nothing but a logged and counted stall, a 3 s cut fails over to the standby; every CSV equals the in-process walk; the worker that came back serves the next run"
    ;;
  lossy)
    start_lossy_link --delay 2 --jitter 1 --loss 0.05 --duplicate 0.01 --reorder 0.25 --seed 7
    "$cli" run "$src/models/walk.xml" --quiet --stop-time 10 --output "$work/local" --force ||
      fail "in-process walk"
    start_worker a w1
    start_run lossy --quiet --stop-time 10
    finish_run lossy
    stop_lossy_link
    for n in dropped duplicated reordered; do
      echo "$link_counts" | grep -Eq "[1-9][0-9]* $n" || fail "the link never $n a packet"
    done
    echo "PASSED: over a link with 2 ms ± 1 ms delay, 5 % loss, 1 % duplicates and reordering the CSV equals the in-process walk"
    ;;
  delay)
    start_lossy_link --delay 2 --jitter 0
    start_worker a w1
    "$cli" run "$src/models/walk.xml" --quiet --stop-time "$stop" --output "$work/local" --force ||
      fail "in-process walk"
    start=$(date +%s.%N)
    start_run delayed --quiet --stop-time "$stop"
    finish_run delayed
    end=$(date +%s.%N)
    stop_lossy_link
    echo "the $stop s walk with the robot on a worker 2 ms away (4 ms round trip): $(echo "$end - $start" | bc) s"
    ;;
  *) fail "mode is partition or lossy, not '$mode'" ;;
esac
