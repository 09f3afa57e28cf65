#!/usr/bin/env bash
# Two "hosts" on one machine: two network namespaces joined by a veth pair, a worker in one, the
# orchestrator in the other, both with the multi-host DDS configuration of docs/dds/. Checked:
#  - a worker that the network reaches refuses to start without --security or --insecure;
#  - with --insecure, the stride_test pair equals the in-process run byte for byte;
#  - with DDS Security (a keystore made here), the walk with the robot on the worker equals the
#    walk in process, and (when tcpdump is installed) a capture on the veth shows none of the
#    names, variable names among them, that the insecure run shows in plain text.
# Needs root (CAP_NET_ADMIN): otherwise it is skipped (exit 77) with the reason.
# usage: netns_test.sh STRIDE_CLI SOURCE_DIR
set -u
cli="$1"
src="$2"
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

tag="s$$"
ns_a="stride-a-$tag"
ns_b="stride-b-$tag"
work="$(mktemp -d)"
worker_pid=""
capture_pid=""
stop_worker() {
  [ -n "$worker_pid" ] && kill -TERM "$worker_pid" 2> /dev/null && wait "$worker_pid" 2> /dev/null
  worker_pid=""
}
cleanup() {
  stop_worker
  [ -n "$capture_pid" ] && kill "$capture_pid" 2> /dev/null
  ip netns del "$ns_a" 2> /dev/null
  ip netns del "$ns_b" 2> /dev/null
  rm -rf "$work"
}
trap cleanup EXIT

ip netns add "$ns_a" 2> "$work/err" || skip "cannot create a network namespace: $(cat "$work/err")"
ip netns add "$ns_b" || exit 1
ip link add "va$tag" type veth peer name "vb$tag" || skip "cannot create a veth pair"
ip link set "va$tag" netns "$ns_a" && ip link set "vb$tag" netns "$ns_b" || exit 1
ip -n "$ns_a" addr add 10.213.0.1/24 dev "va$tag" && ip -n "$ns_b" addr add 10.213.0.2/24 dev "vb$tag"
for ns in "$ns_a" "$ns_b"; do ip -n "$ns" link set lo up || exit 1; done
ip -n "$ns_a" link set "va$tag" up && ip -n "$ns_b" link set "vb$tag" up || exit 1

config="$src/docs/dds/multi-host.xml"
sed -e 's/stop="1"/stop="2"/' \
  -e 's/<component name="b" fmu="stride_test"/<component name="b" fmu="stride_test" worker="far"/' \
  "$src/tests/orchestrator/data/stride_test_pair.xml" > "$work/remote.xml"
grep -q 'worker="far"' "$work/remote.xml" || { echo "FAILED: could not place b in the test system"; exit 1; }
sed -e 's/stop="1"/stop="2"/' "$src/tests/orchestrator/data/stride_test_pair.xml" > "$work/local.xml"
sed -e 's/worker="far"/worker="w1"/' "$work/remote.xml" > "$work/remote-w1.xml"
# The pair names its FMU by bundled name; here it finds a copy stored without compression, so that
# its variable names are plain bytes in every packet that carries the archive unencrypted.
mkdir -p "$work/fmus/unpacked"
(cd "$work/fmus/unpacked" && unzip -q "$(dirname "$cli")/../fmus/stride_test.fmu" &&
  zip -q -0 -r ../stride_test.fmu .) || fail "could not repack stride_test.fmu"
export STRIDE_FMU_PATH="$work/fmus"
"$cli" run "$work/local.xml" --quiet --output "$work/local" || { echo "FAILED: in-process run"; exit 1; }

# start_worker NAME ARGS...: a worker in namespace A, waited for until it is ready
start_worker() {
  local name="$1"
  shift
  ip netns exec "$ns_a" env MY_IFACE="va$tag" PEER_ADDR=10.213.0.2 \
    "$cli" worker --name "$name" --domain 5 --dds-config "$config" "$@" > "$work/worker.log" 2>&1 &
  worker_pid=$!
  for _ in $(seq 100); do
    grep -q "ready" "$work/worker.log" && break
    sleep 0.1
  done
  grep -q "ready" "$work/worker.log" || { cat "$work/worker.log"; fail "worker not ready"; }
}
# capture FILE: tcpdump on the worker's veth into FILE until stop_capture
capture() {
  capture_pid=""
  [ -n "$tcpdump" ] || return 0
  ip netns exec "$ns_a" "$tcpdump" -i "va$tag" -U -w "$1" udp > "$work/tcpdump.log" 2>&1 &
  capture_pid=$!
  sleep 1  # tcpdump needs a moment before it sees packets
}
stop_capture() {
  [ -n "$capture_pid" ] && sleep 0.5 && kill -INT "$capture_pid" && wait "$capture_pid" 2> /dev/null
  capture_pid=""
}
tcpdump="$(command -v tcpdump || true)"
# names the pair's runs send: the FMU archive's entry names, the partition of the run's replies,
# and variable names of stride_test from its model description. (Topic names are no secret: the
# signed permissions document that lists them travels in the clear during the DDS Security
# handshake, by the standard's design.)
plain_names=(modelDescription.xml binaries/linux64 stride.run. logStatusWarning integral)

# no security, no --insecure: the worker refuses to start
if ip netns exec "$ns_a" env MY_IFACE="va$tag" PEER_ADDR=10.213.0.2 \
  "$cli" worker --name far --domain 5 --dds-config "$config" > "$work/refused.log" 2>&1; then
  fail "a worker reachable over the network started without --security or --insecure"
fi
grep -q "network interface 'va$tag'" "$work/refused.log" || { cat "$work/refused.log"; fail "refusal message"; }

start_worker far --insecure
capture "$work/insecure.pcap"

if ! ip netns exec "$ns_b" env MY_IFACE="vb$tag" PEER_ADDR=10.213.0.1 \
  "$cli" run "$work/remote.xml" --quiet --domain 5 --dds-config "$config" --output "$work/remote"; then
  echo "FAILED: run with b on the worker in the other namespace"
  cat "$work/worker.log"
  exit 1
fi
stop_capture
cmp "$work/local/results.csv" "$work/remote/results.csv" || fail "results differ"
grep -q "loaded stride_test" "$work/worker.log" || { cat "$work/worker.log"; fail "worker log"; }
grep -q "warning: --insecure" "$work/worker.log" || { cat "$work/worker.log"; fail "no --insecure warning"; }
stop_worker
if [ -n "$tcpdump" ]; then
  for name in "${plain_names[@]}"; do
    grep -aq "$name" "$work/insecure.pcap" || fail "the control capture lacks '$name' in plain text"
  done
fi

# the same hosts with DDS Security: the walk with the robot on the worker
"$cli" security init "$work/ks" --domains 5 > /dev/null || fail "keystore"
for id in w1 orchestrator; do "$cli" security add "$work/ks" "$id" > /dev/null || fail "identity $id"; done
"$cli" run "$src/models/walk.xml" --quiet --stop-time 2 --output "$work/walk-local" ||
  fail "in-process walk"
start_worker w1 --security "$work/ks/w1"
capture "$work/secure.pcap"
if ! ip netns exec "$ns_b" env MY_IFACE="vb$tag" PEER_ADDR=10.213.0.1 \
  "$cli" run "$src/models/distributed/walk-robot-on-worker.xml" --quiet --stop-time 2 --domain 5 \
  --dds-config "$config" --security "$work/ks/orchestrator" --output "$work/walk-remote"; then
  cat "$work/worker.log"
  fail "secure walk with the robot on the worker in the other namespace"
fi
# and the pair, whose archive shows its variable names when nothing protects it
ip netns exec "$ns_b" env MY_IFACE="vb$tag" PEER_ADDR=10.213.0.1 \
  "$cli" run "$work/remote-w1.xml" --quiet --domain 5 --dds-config "$config" \
  --security "$work/ks/orchestrator" --output "$work/secure-pair" || fail "secure pair run"
stop_capture
cmp "$work/local/results.csv" "$work/secure-pair/results.csv" || fail "secure pair differs"
cmp "$work/walk-local/results.csv" "$work/walk-remote/results.csv" || fail "secure walk differs"
grep -q "loaded robot" "$work/worker.log" || { cat "$work/worker.log"; fail "secure worker log"; }
if [ -z "$tcpdump" ]; then
  echo "PASSED: runs across two network namespaces equal the in-process runs (no tcpdump: capture not checked)"
  exit 0
fi
[ -s "$work/secure.pcap" ] || fail "nothing captured during the secure run"
for name in "${plain_names[@]}"; do
  if grep -aq "$name" "$work/secure.pcap"; then fail "'$name' crossed the wire in plain text"; fi
done
echo "PASSED: runs across two network namespaces equal the in-process runs; the secure one shows no names in plain text"
