#!/usr/bin/env bash
# Installs the Debian packages Stride needs, then the npm packages of package-lock.json (three.js,
# which the run viewer inlines into its pages); what is already present is skipped, so a second
# run does nothing. Needs root (or sudo) and apt; npm reads the registry only when node_modules/
# does not match the lock file.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config make
  libode-dev liburdfdom-dev libassimp-dev libeigen3-dev libceres-dev
  libtinyxml2-dev libzip-dev libsundials-dev zipcmp zipmerge ziptool zip unzip
  libcli11-dev cyclonedds-dev cyclonedds-tools libssl-dev iproute2 tcpdump linux-perf
  libgtest-dev libgmock-dev libbenchmark-dev
  valgrind libxml2-utils binutils patchelf clang-format gnuplot-nox python3
  clang libclang-rt-dev llvm gcovr
  g++-s390x-linux-gnu qemu-user
  nodejs chromium
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# Debian's nodejs comes without npm (NodeSource's includes it)
command -v npm >/dev/null 2>&1 || missing+=(npm)

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# npm packages, exactly as package-lock.json pins them (npm ci); skipped when installed already
root="$(cd "$(dirname "$0")/.." && pwd)"
if ! node -e 'const l = require(process.argv[1]), i = require(process.argv[2]);
              for (const [k, v] of Object.entries(l.packages)) {
                if (k && (!i.packages[k] || i.packages[k].version !== v.version)) process.exit(1);
              }' "$root/package-lock.json" "$root/node_modules/.package-lock.json" 2>/dev/null; then
  echo "install-deps: npm ci (package-lock.json)"
  (cd "$root" && npm ci --no-audit --no-fund --loglevel=error)
else
  echo "install-deps: npm packages present"
fi
