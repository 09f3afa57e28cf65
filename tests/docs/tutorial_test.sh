#!/usr/bin/env bash
# Runs the shell blocks of docs/tutorial.md in order, as one script, with HOME and PREFIX in a
# temporary folder and the build folder where the tutorial expects it (`build/` of the source
# folder), then checks what the tutorial says the reader gets.
# Usage: tutorial_test.sh BUILD_DIR TUTORIAL.md
set -euo pipefail
build="$1"
tutorial="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
unset STRIDE_FMU_PATH
export HOME="$work/home" PREFIX="$work/prefix"
mkdir -p "$HOME" "$work/source"
ln -s "$build" "$work/source/build"

awk '/^```sh$/ { on = 1; next } /^```/ { on = 0 } on' "$tutorial" > "$work/tutorial.sh"
[ "$(grep -c . "$work/tutorial.sh")" -ge 15 ] || fail "too few commands found in $tutorial"
(cd "$work/source" && bash -euo pipefail "$work/tutorial.sh") || fail "a tutorial command failed"

cd "$HOME/stride-tutorial/walk_then_turn"
column() { # column NAME FILE: prints "time value" rows of that column
  awk -F, -v name="$1" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; if (!c) exit 1; next }
                        { print $1, $c }' "$2"
}

# run1: 0..15 s every 0.04 s; the controller turns exactly from its forward_time, 5 s
[ "$(wc -l < run1/results.csv)" -eq 377 ] || fail "run1/results.csv: $(wc -l < run1/results.csv) lines"
switch="$(column controller.turning run1/results.csv | awk '$2 == 1 { print $1; exit }')"
[ "$switch" = "5" ] || fail "turning began at t = '$switch', expected 5"
grep -q '"status": "ok"' run1/manifest.json || fail "run1 manifest: $(cat run1/manifest.json)"

# run2: the signals asked for on the command line, and the turn to the left the tutorial shows
header="$(head -1 run2/results.csv)"
grep -q "robot.yaw" <<< "$header" || fail "run2 did not record robot.yaw"
grep -q "gait.a_move" <<< "$header" || fail "run2 did not record gait.a_move"
column robot.yaw run2/results.csv | awk '
  NR > 1 { d = $2 - prev; if (d > 3.14159265) d -= 2 * 3.14159265; if (d < -3.14159265) d += 2 * 3.14159265; yaw += d }
  { prev = $2; if ($1 == 5) at5 = yaw; if ($1 == 10) at10 = yaw }
  END {
    if (at5 < -0.3 || at5 > 0.3) { print "yaw moved " at5 " rad while walking straight"; exit 1 }
    if (at10 - at5 < 1.0) { print "yaw grew only " at10 - at5 " rad in 5 s of turning left"; exit 1 }
  }' || fail "run2 path"

# the figures of `stride plot`, as PNG
pngs=(run2/figures/*.png)
[ -e "${pngs[0]}" ] || fail "stride plot wrote no PNG figures"
for png in "${pngs[@]}"; do
  [ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "$png is not a PNG"
done

# gait_host: 2 s of the gait driven from plain C, every 0.248 s and the last step
[ "$(wc -l < hips.csv)" -eq 11 ] || fail "hips.csv: $(wc -l < hips.csv) lines"
awk -F, 'NR > 1 { if ($2 !~ /^-?[0-9]+\.[0-9]+$/) bad = 1; seen[$2] = 1 }
         END { n = 0; for (k in seen) n++; exit (bad || n < 5) }' hips.csv ||
  fail "hips.csv does not show a walking hip: $(cat hips.csv)"
echo "tutorial: ok"
