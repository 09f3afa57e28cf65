#!/usr/bin/env bash
# Installs the build into a temporary prefix, builds examples/walk_then_turn against it with
# find_package(Stride), and runs it with the installed `stride`, which must find the bundled
# FMUs and models by itself (no STRIDE_FMU_PATH).
# Usage: out_of_tree_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$1"
source="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
unset STRIDE_FMU_PATH

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
prefix="$work/prefix"
for f in bin/stride bin/stride-fmu-check share/stride/fmus/gait.fmu share/stride/fmus/robot.fmu \
         share/stride/fmus/learner.fmu share/stride/models/walk.xml include/stride/sdk/fmu.hpp \
         lib/cmake/Stride/StrideConfig.cmake lib/cmake/Stride/StrideConfigVersion.cmake; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done
# test components stay out of the package
[ ! -e "$prefix/share/stride/fmus/stride_test.fmu" ] || fail "the test FMU was installed"

# the component, built out of tree
cp -r "$source/examples/walk_then_turn" "$work/src"
cmake -S "$work/src" -B "$work/src/build" -DCMAKE_PREFIX_PATH="$prefix" > "$work/configure.log"
cmake --build "$work/src/build" > "$work/build.log"
fmu="$work/src/build/fmus/walk_then_turn.fmu"
[ -f "$fmu" ] || fail "no $fmu"
"$prefix/bin/stride-fmu-check" "$fmu"

# run with the installed stride: bundled gait and robot come from share/stride/fmus
cd "$work/src"
"$prefix/bin/stride" run system.xml --stop-time 6 -o out -q
# the controller switches to turning exactly at its forward_time (5 s), recorded every 0.04 s
switch="$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "controller.turning") c = i }
                   NR > 1 && $c == 1 { print $1; exit }' out/results.csv)"
[ "$switch" = "5" ] || fail "turning began at t = '$switch', expected 5"
rows="$(wc -l < out/results.csv)"
[ "$rows" -eq 152 ] || fail "results.csv has $rows lines, expected 1 header + 151 rows (0..6 s by 0.04 s)"

# a shipped model by its name, resolved in share/stride/models
"$prefix/bin/stride" validate walk.xml -q
if "$prefix/bin/stride" validate no-such-model.xml 2> "$work/err.txt"; then
  fail "a missing model was accepted"
fi
grep -q "share/stride/models" "$work/err.txt" || fail "the error does not say where it looked: $(cat "$work/err.txt")"

# a version the package does not provide is refused by find_package
mkdir "$work/too_new"
cat > "$work/too_new/CMakeLists.txt" << 'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(too_new LANGUAGES CXX)
find_package(Stride 9.0 REQUIRED)
CMAKE
if cmake -S "$work/too_new" -B "$work/too_new/build" -DCMAKE_PREFIX_PATH="$prefix" \
     > "$work/too_new.log" 2>&1; then
  fail "find_package(Stride 9.0) succeeded"
fi

# an identifier that is not a C identifier stops the configure step with a message
mkdir "$work/bad_id"
cp "$source/examples/walk_then_turn/walk_then_turn.cpp" "$work/bad_id/"
cat > "$work/bad_id/CMakeLists.txt" << 'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(bad_id LANGUAGES CXX)
find_package(Stride REQUIRED)
stride_add_fmu(bad IDENTIFIER "two words" SOURCES walk_then_turn.cpp)
CMAKE
if cmake -S "$work/bad_id" -B "$work/bad_id/build" -DCMAKE_PREFIX_PATH="$prefix" \
     > "$work/bad_id.log" 2>&1; then
  fail "an FMU identifier with a space was accepted"
fi
grep -q "identifier 'two words'" "$work/bad_id.log" || fail "no clear message: $(cat "$work/bad_id.log")"
echo "installed package: ok"
