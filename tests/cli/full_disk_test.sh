#!/usr/bin/env bash
# A full or read-only disk never passes for success: `stride calibrate` and `stride run` writing into a small
# tmpfs (in a private mount namespace) that fills up must exit non-zero naming the reason, leave
# no empty or half-written result in place of a complete one, and keep an older file intact.
# Needs root for the mount namespace; otherwise skipped (exit 77) with the reason.
# usage: full_disk_test.sh STRIDE_CLI SOURCE_DIR
set -u
cli="$1"
src="$2"
skip() {
  echo "SKIPPED: $*"
  exit 77
}
[ "$(id -u)" -eq 0 ] || skip "needs root to mount a small tmpfs (running as uid $(id -u))"
unshare -m true 2> /dev/null || skip "cannot create a mount namespace"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat > "$work/inside.sh" << 'INSIDE'
set -u
cli="$1"; src="$2"; disk="$3"
fail() { echo "FAIL: $*" >&2; exit 1; }
mount -t tmpfs -o size=256k stride-full-disk "$disk" || exit 77

# calibrate: an older output stays as it was, no .tmp is left, the exit status says it failed
printf '[Walking Config]\nx_offset = 1\n' > "$disk/fitted.ini"
cp "$disk/fitted.ini" "$disk/../fitted.before"
dd if=/dev/zero of="$disk/filler" bs=4k 2> /dev/null  # until the disk is full
"$cli" calibrate --target "$src/tests/calibration/data/walk_ready.csv" \
  --config "$src/components/gait_fmu/resources/config.ini" --output "$disk/fitted.ini" -q \
  2> "$disk/../calibrate.err" && fail "calibrate succeeded on a full disk"
grep -q "No space left on device" "$disk/../calibrate.err" ||
  fail "calibrate did not say why: $(cat "$disk/../calibrate.err")"
cmp -s "$disk/fitted.ini" "$disk/../fitted.before" || fail "the older fitted.ini was changed"
[ ! -e "$disk/fitted.ini.tmp" ] || fail "calibrate left fitted.ini.tmp"

# run: the results CSV does not fit; no "finished", an error naming the file, exit non-zero
rm -f "$disk/filler" "$disk/fitted.ini"
"$cli" run "$src/models/walk.xml" --stop-time 10 -o "$disk/run" > "$disk/../run.out" \
  2> "$disk/../run.err" && fail "stride run succeeded on a full disk"
grep -q "finished" "$disk/../run.out" "$disk/../run.err" && fail "stride run said finished"
grep -q "results.csv: No space left on device" "$disk/../run.err" ||
  fail "stride run did not name the file and the reason: $(cat "$disk/../run.err")"
# the manifest is whole (it says error) or absent, never a fragment
if [ -e "$disk/run/manifest.json" ]; then
  grep -q '"status": "error"' "$disk/run/manifest.json" ||
    fail "manifest: $(cat "$disk/run/manifest.json")"
fi
[ -z "$(find "$disk" -name '*.tmp')" ] || fail "temporary files left: $(find "$disk" -name '*.tmp')"

# a read-only disk: refused before the first step, with the folder named
mkdir "$disk/../ro"
mount -t tmpfs -o size=64k,ro stride-read-only "$disk/../ro" || exit 77
"$cli" run "$src/models/walk.xml" --stop-time 1 -o "$disk/../ro/run" > /dev/null \
  2> "$disk/../ro.err" && fail "stride run succeeded on a read-only disk"
grep -q "cannot create the output folder .*ro/run: Read-only file system" "$disk/../ro.err" ||
  fail "the read-only error does not name the folder and the reason: $(cat "$disk/../ro.err")"
echo "full and read-only disks: refused as they should be"
INSIDE
mkdir "$work/disk"
unshare -m bash "$work/inside.sh" "$cli" "$src" "$work/disk"
