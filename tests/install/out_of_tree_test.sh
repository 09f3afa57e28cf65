#!/usr/bin/env bash
# Installs the build into a temporary prefix and checks the package: its layout, an out-of-tree
# component built with find_package(Stride) (the installed examples/walk_then_turn), the installed
# `stride` finding bundled FMUs and models by itself (no STRIDE_FMU_PATH), version and identifier
# errors. Running that component is the tutorial's test (tests/docs).
# Usage: out_of_tree_test.sh BUILD_DIR
set -euo pipefail
build="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
unset STRIDE_FMU_PATH

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
prefix="$work/prefix"
for f in bin/stride bin/stride-fmu-check share/stride/fmus/gait.fmu share/stride/fmus/robot.fmu \
         share/stride/fmus/learner.fmu share/stride/fmus/fmi3/gait.fmu share/stride/fmus/fmi3/robot.fmu \
         share/stride/fmus/fmi3/learner.fmu share/stride/models/walk.xml include/stride/sdk/fmu.hpp \
         share/stride/examples/walk_then_turn/CMakeLists.txt share/stride/examples/gait_host/gait_host.c \
         lib/cmake/Stride/StrideConfig.cmake lib/cmake/Stride/StrideConfigVersion.cmake; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done
# test components stay out of the package
[ ! -e "$prefix/share/stride/fmus/stride_test.fmu" ] || fail "the test FMU was installed"

# the component, built out of tree
cp -r "$prefix/share/stride/examples/walk_then_turn" "$work/src"
cmake -S "$work/src" -B "$work/src/build" -DCMAKE_PREFIX_PATH="$prefix" > "$work/configure.log"
cmake --build "$work/src/build" > "$work/build.log"
fmu="$work/src/build/fmus/walk_then_turn.fmu"
[ -f "$fmu" ] || fail "no $fmu"
"$prefix/bin/stride-fmu-check" "$fmu"
# and its FMI 3.0 FMU beside it, with the 3.0 binary layout
fmu3="$work/src/build/fmus/fmi3/walk_then_turn.fmu"
[ -f "$fmu3" ] || fail "no $fmu3"
# (listings go through variables: with pipefail, `unzip | grep -q` fails when grep stops reading early)
listing="$(unzip -l "$fmu3")"
grep -q "binaries/x86_64-linux/walk_then_turn.so" <<< "$listing" || fail "no 3.0 binary in $fmu3"
description="$(unzip -p "$fmu3" modelDescription.xml)"
grep -q 'fmiVersion="3.0"' <<< "$description" || fail "$fmu3 is not FMI 3.0"

# a shipped model by its name, resolved in share/stride/models, its FMUs in share/stride/fmus
cd "$work"
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
cp "$prefix/share/stride/examples/walk_then_turn/walk_then_turn.cpp" "$work/bad_id/"
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
