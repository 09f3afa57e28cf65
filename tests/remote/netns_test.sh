#!/usr/bin/env bash
# Two "hosts" on one machine: two network namespaces joined by a veth pair, a worker in one, the
# orchestrator in the other, both with the multi-host DDS configuration of docs/dds/. The run must
# equal the in-process run byte for byte. Needs root (CAP_NET_ADMIN): otherwise it is skipped
# (exit 77) with the reason.
# usage: netns_test.sh STRIDE_CLI SOURCE_DIR
set -u
cli="$1"
src="$2"
skip() {
  echo "SKIPPED: $*"
  exit 77
}
[ "$(id -u)" -eq 0 ] || skip "needs root to create network namespaces (running as uid $(id -u))"
command -v ip > /dev/null || skip "the ip tool (iproute2) is not installed"

tag="s$$"
ns_a="stride-a-$tag"
ns_b="stride-b-$tag"
work="$(mktemp -d)"
worker_pid=""
cleanup() {
  [ -n "$worker_pid" ] && kill -TERM "$worker_pid" 2> /dev/null && wait "$worker_pid" 2> /dev/null
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
# the pair names its FMU by bundled name: both systems live in the scratch folder
"$cli" run "$work/local.xml" --quiet --output "$work/local" || { echo "FAILED: in-process run"; exit 1; }

ip netns exec "$ns_a" env MY_IFACE="va$tag" PEER_ADDR=10.213.0.2 \
  "$cli" worker --name far --domain 5 --dds-config "$config" > "$work/worker.log" 2>&1 &
worker_pid=$!
for _ in $(seq 100); do
  grep -q "ready" "$work/worker.log" && break
  sleep 0.1
done
grep -q "ready" "$work/worker.log" || { echo "FAILED: worker not ready"; cat "$work/worker.log"; exit 1; }

if ! ip netns exec "$ns_b" env MY_IFACE="vb$tag" PEER_ADDR=10.213.0.1 \
  "$cli" run "$work/remote.xml" --quiet --domain 5 --dds-config "$config" --output "$work/remote"; then
  echo "FAILED: run with b on the worker in the other namespace"
  cat "$work/worker.log"
  exit 1
fi
cmp "$work/local/results.csv" "$work/remote/results.csv" || { echo "FAILED: results differ"; exit 1; }
grep -q "loaded stride_test" "$work/worker.log" || { echo "FAILED: worker log"; cat "$work/worker.log"; exit 1; }
echo "PASSED: the run across two network namespaces equals the in-process run"
