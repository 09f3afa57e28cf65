#!/usr/bin/env bash
# check_fmu_exports.sh FILE.fmu
#
# Shared-library hygiene of an FMI 2.0 Co-Simulation FMU (docs/fmi-rules.md §2.1, §2.3):
#  - binaries/linux64/<modelIdentifier>.so exports ONLY fmi2* symbols (nm -D --defined-only),
#    and all 34 Co-Simulation functions are among them, as functions;
#  - every .so in binaries/linux64/ needs (readelf -d NEEDED) only libc, libm, libpthread, libdl,
#    librt, ld-linux-x86-64, or libraries shipped in the same folder of the FMU.
# Unpacks with `unzip` when present, else with `cmake -E tar` ($CMAKE_COMMAND or cmake).
# Exit status: 0 when clean, 1 on a finding, 2 on a usage or tool error.
set -euo pipefail

usage() { echo "usage: $(basename "$0") FILE.fmu" >&2; exit 2; }
[[ $# -eq 1 && $1 != -* ]] || usage
fmu=$1
[[ -f $fmu ]] || { echo "$fmu: error: no such file" >&2; exit 2; }
fmu_abs=$(cd "$(dirname "$fmu")" && pwd)/$(basename "$fmu")

for tool in nm readelf; do
  command -v "$tool" >/dev/null || { echo "$(basename "$0"): $tool not found" >&2; exit 2; }
done

work=$(mktemp -d "${TMPDIR:-/tmp}/fmu_exports_XXXXXX")
trap 'rm -rf "$work"' EXIT

if command -v unzip >/dev/null; then
  unzip -q "$fmu_abs" 'modelDescription.xml' 'binaries/linux64/*' -d "$work" 2>/dev/null || true
else
  (cd "$work" && "${CMAKE_COMMAND:-cmake}" -E tar xf "$fmu_abs") || true
fi

errors=0
error() { echo "$fmu: error: $*"; errors=$((errors + 1)); }

[[ -f $work/modelDescription.xml ]] || { error "[exports.archive] no modelDescription.xml"; exit 1; }
# modelIdentifier of <CoSimulation>, by plain text matching (attributes may span lines)
model_identifier=$(tr '\n\r\t' '   ' < "$work/modelDescription.xml" |
  grep -o '<CoSimulation[^>]*>' | head -n 1 |
  sed -n 's/.*[[:space:]]modelIdentifier[[:space:]]*=[[:space:]]*["'"'"']\([^"'"'"']*\)["'"'"'].*/\1/p')
[[ -n $model_identifier ]] || { error "[exports.archive] no CoSimulation@modelIdentifier"; exit 1; }

bin_dir=$work/binaries/linux64
so=$bin_dir/$model_identifier.so
[[ -f $so ]] || { error "[exports.archive] no binaries/linux64/$model_identifier.so"; exit 1; }

# --- exported symbols of the FMU library
symbols=$(nm -D --defined-only "$so" | awk 'NF >= 3 { print $2, $3 }') ||
  { error "[exports.nm] nm -D failed on $model_identifier.so"; exit 1; }
extra=()
declare -A exported=()
while read -r type name; do
  [[ -n ${name:-} ]] || continue
  name=${name%%@*}
  case $name in
    fmi2*) exported[$name]=$type ;;
    *) extra+=("$name ($type)") ;;
  esac
done <<< "$symbols"
if ((${#extra[@]} > 0)); then
  shown=$(printf '%s, ' "${extra[@]:0:20}")
  more=""
  ((${#extra[@]} > 20)) && more=" and $((${#extra[@]} - 20)) more"
  error "[exports.symbols] $model_identifier.so exports ${#extra[@]} non-fmi2 symbol(s): ${shown%, }$more" \
    "(build with -fvisibility=hidden and a version script { global: fmi2*; local: *; };" \
    "with -static-libstdc++ also -Wl,--exclude-libs,ALL)"
fi

functions=(fmi2GetTypesPlatform fmi2GetVersion fmi2SetDebugLogging fmi2Instantiate
  fmi2FreeInstance fmi2SetupExperiment fmi2EnterInitializationMode fmi2ExitInitializationMode
  fmi2Terminate fmi2Reset fmi2GetReal fmi2GetInteger fmi2GetBoolean fmi2GetString fmi2SetReal
  fmi2SetInteger fmi2SetBoolean fmi2SetString fmi2GetFMUstate fmi2SetFMUstate fmi2FreeFMUstate
  fmi2SerializedFMUstateSize fmi2SerializeFMUstate fmi2DeSerializeFMUstate
  fmi2GetDirectionalDerivative fmi2SetRealInputDerivatives fmi2GetRealOutputDerivatives
  fmi2DoStep fmi2CancelStep fmi2GetStatus fmi2GetRealStatus fmi2GetIntegerStatus
  fmi2GetBooleanStatus fmi2GetStringStatus)
missing=()
for f in "${functions[@]}"; do
  if [[ -z ${exported[$f]:-} ]]; then
    missing+=("$f")
  elif [[ ${exported[$f]} != [TtWi] ]]; then
    error "[exports.functions] $f is exported as nm type ${exported[$f]}, not as a function"
  fi
done
if ((${#missing[@]} > 0)); then
  error "[exports.functions] $model_identifier.so does not export ${#missing[@]} of the 34" \
    "FMI 2.0 Co-Simulation functions: ${missing[*]}"
fi

# --- NEEDED libraries of every shared library in binaries/linux64/
allowed_re='^(libc\.so\.6|libm\.so\.6|libpthread\.so\.0|libdl\.so\.2|librt\.so\.1|ld-linux-x86-64\.so\.2)$'
for lib in "$bin_dir"/*; do
  [[ -f $lib ]] || continue
  [[ $(basename "$lib") == *.so* ]] || continue
  needed=$(readelf -d "$lib" 2>/dev/null | sed -n 's/.*(NEEDED).*\[\(.*\)\].*/\1/p') ||
    { error "[exports.needed] readelf -d failed on $(basename "$lib")"; continue; }
  bundled=0
  while read -r dep; do
    [[ -n $dep ]] || continue
    if [[ $dep =~ $allowed_re ]]; then
      continue
    elif [[ -f $bin_dir/$dep ]]; then
      bundled=1
    else
      error "[exports.needed] $(basename "$lib") needs $dep, which is neither a base system" \
        "library (libc, libm, libpthread, libdl, librt, ld-linux) nor shipped in binaries/linux64/"
    fi
  done <<< "$needed"
  if ((bundled)) && ! readelf -d "$lib" | grep -E '\((RUNPATH|RPATH)\)' | grep -q '\$ORIGIN'; then
    error "[exports.needed] $(basename "$lib") needs libraries shipped next to it but has no" \
      "RPATH/RUNPATH \$ORIGIN to find them"
  fi
done

if ((errors > 0)); then
  exit 1
fi
echo "$fmu: ok: $model_identifier.so exports the 34 fmi2 functions only; NEEDED libraries allowed"
