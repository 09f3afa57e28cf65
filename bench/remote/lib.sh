# shellcheck shell=bash
# Sourced by the remote benches: their keystores and their workers' start.

# make_keystore STRIDE DIR DOMAIN PROTECTION NAME...: a keystore for DOMAIN made with
# PROTECTION (sign or encrypt), with one identity per NAME
make_keystore() {
  local stride="$1" dir="$2" domain="$3" protection="$4" name
  "$stride" security init "$dir" --domains "$domain" --protection "$protection" > /dev/null
  for name in "${@:5}"; do "$stride" security add "$dir" "$name" > /dev/null; done
}

# wait_ready LOG: returns once the worker writing LOG says it is ready; after 10 s without,
# prints LOG and exits the bench
wait_ready() {
  for _ in $(seq 100); do grep -q ready "$1" && return; sleep 0.1; done
  cat "$1" >&2
  exit 1
}
