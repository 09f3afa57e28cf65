#!/usr/bin/env bash
# Installs the Debian packages Stride needs; packages already present are skipped, so a second
# run does nothing. Needs root (or sudo) and apt.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config make
  libode-dev liburdfdom-dev libeigen3-dev libceres-dev
  libtinyxml2-dev libzip-dev zipcmp zipmerge ziptool zip unzip
  libcli11-dev cyclonedds-dev cyclonedds-tools libssl-dev iproute2
  libgtest-dev libgmock-dev libbenchmark-dev
  valgrind libxml2-utils binutils patchelf clang-format gnuplot-nox python3
  clang libclang-rt-dev llvm
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
