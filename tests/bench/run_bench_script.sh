#!/usr/bin/env bash
# usage: run_bench_script.sh EXPECTED SCRIPT ARGS...
# Runs a bench script; fails when it fails or when its output lacks the line EXPECTED (an
# extended regular expression) that its summary prints.
set -uo pipefail
expected="$1"
shift
out="$("$@" 2>&1)"
status=$?
printf '%s\n' "$out"
[ $status -eq 77 ] && exit 77  # skipped by the script, which said why
if [ $status -ne 0 ]; then
  echo "run_bench_script: $1 exited with $status" >&2
  exit 1
fi
grep -Eq -- "$expected" <<< "$out" ||
  { echo "run_bench_script: $1 printed no line matching '$expected'" >&2; exit 1; }
