#!/usr/bin/env bash
# The start-up of a run with the robot on a worker: the walk stopped after ten steps (walk.sh to
# 0.08 s), so that its wall time is almost all start-up (reading the system, describing the FMUs,
# joining the DDS domain, finding the worker and, with security, the DDS Security handshake).
# usage: bench/remote/startup.sh [REPEAT] [BUILDS] [DOMAIN] [MODES]
#        (defaults 15, build/, 174, none; BUILDS and MODES as for walk.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
exec "$root/bench/remote/walk.sh" "${1:-15}" "${2:-$root/build}" "${3:-174}" "${4:-none}" 0.08
