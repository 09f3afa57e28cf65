#!/usr/bin/env bash
# `stride robot-fmu` generation time (DARwIn-OP with its profile, the test quadruped) and the
# speed of generated plant FMUs run alone: a free pendulum (0.5 ms physics step, 60 s) and the
# quadruped standing (8 ms physics step, 60 s), in simulated seconds per wall second.
# Each measured REPEAT times (default 5); prints the median and the range.
# usage: bench/robot/plant_fmu.sh [REPEAT] [BUILD_DIR]   (defaults 5, build/)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
repeat="${1:-5}"
build="${2:-$root/build}"
stride="$build/bin/stride"
[ -x "$stride" ] || { echo "plant_fmu: $stride not found (build first)" >&2; exit 1; }
data="$root/tests/components/robot_fmu/data"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# prints the median and range of the numbers on stdin
summary() {
  LABEL="$1" python3 -c "
import os, statistics, sys
v = [float(x) for x in sys.stdin.read().split()]
print(f'median {statistics.median(v):.3f} (range {min(v):.3f}-{max(v):.3f}, n={len(v)}) ' + os.environ['LABEL'])"
}

seconds() {  # command...
  local start=$EPOCHREALTIME
  "$@" > "$out/last.txt" 2>&1 || { cat "$out/last.txt" >&2; exit 1; }
  python3 -c "print($EPOCHREALTIME - $start)"
}

cat > "$out/pendulum.xml" <<'PROFILE'
<plant_profile><physics step="0.0005"/>
<servo joints="pivot" torque_limit="0" static_friction="0" damping="0"/>
<pose joints="pivot" value="0.0872664626"/></plant_profile>
PROFILE
"$stride" robot-fmu "$data/pendulum.urdf" --profile "$out/pendulum.xml" -q -o "$out/pendulum.fmu"
"$stride" robot-fmu "$data/quadruped.urdf" --profile "$data/quadruped.profile.xml" -q \
  -o "$out/quadruped.fmu"
for plant in pendulum quadruped; do
  cat > "$out/$plant-system.xml" <<SYSTEM
<system name="$plant" version="1"><simulation start="0" stop="60" step="0.008"/>
<component name="robot" fmu="$out/$plant.fmu"/>
<record interval="0.104" file="results.csv"><signal name="robot.base_z"/></record></system>
SYSTEM
done

for name in darwin quadruped; do
  for ((i = 0; i < repeat; i++)); do
    if [ "$name" = darwin ]; then
      seconds "$stride" robot-fmu "$root/models/darwin-op/darwin-op.urdf" \
        --profile "$root/models/darwin-op/darwin-op.profile.xml" -q -o "$out/gen.fmu"
    else
      seconds "$stride" robot-fmu "$data/quadruped.urdf" \
        --profile "$data/quadruped.profile.xml" -q -o "$out/gen.fmu"
    fi
  done | summary "s to generate $name"
done
for plant in pendulum quadruped; do
  for ((i = 0; i < repeat; i++)); do
    rm -rf "$out/run"
    t=$(seconds "$stride" run "$out/$plant-system.xml" --quiet --threads 1 -o "$out/run")
    python3 -c "print(60 / $t)"
  done | summary "sim-s per wall-s, $plant (60 s, including loading the FMU)"
done
