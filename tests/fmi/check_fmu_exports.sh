#!/usr/bin/env bash
# check_fmu_exports.sh FILE.fmu [2|3]
#
# Shared-library hygiene of an FMI 2.0 (default) or FMI 3.0 FMU
# (docs/fmi-rules.md §2.1, §2.3; docs/fmi3-rules.md §1, §6):
#  - binaries/linux64/<modelIdentifier>.so (3.0: binaries/x86_64-linux/) exports ONLY fmi2*
#    (fmi3*) symbols (nm -D --defined-only), and the functions of its interface types are among
#    them, as functions: for 2.0 the 25 common ones plus the 9 of Co-Simulation and/or the 10 of
#    Model Exchange (one binary per distinct modelIdentifier of <CoSimulation> and
#    <ModelExchange>, each with the functions of the elements naming it); for 3.0 all 75
#    functions, whatever the interface types, in each binary the two elements name;
#  - every .so in that folder needs (readelf -d NEEDED) only libc, libm, libpthread, libdl,
#    librt, ld-linux-x86-64, or libraries shipped in the same folder of the FMU.
# Unpacks with `unzip` when present, else with `cmake -E tar` ($CMAKE_COMMAND or cmake).
# Exit status: 0 when clean, 1 on a finding, 2 on a usage or tool error.
set -euo pipefail

usage() { echo "usage: $(basename "$0") FILE.fmu [2|3]" >&2; exit 2; }
[[ ($# -eq 1 || ($# -eq 2 && ($2 == 2 || $2 == 3))) && $1 != -* ]] || usage
fmu=$1
version=${2:-2}
if ((version == 3)); then
  platform=x86_64-linux
  prefix=fmi3
else
  platform=linux64
  prefix=fmi2
fi
[[ -f $fmu ]] || { echo "$fmu: error: no such file" >&2; exit 2; }
fmu_abs=$(cd "$(dirname "$fmu")" && pwd)/$(basename "$fmu")

for tool in nm readelf; do
  command -v "$tool" >/dev/null || { echo "$(basename "$0"): $tool not found" >&2; exit 2; }
done

work=$(mktemp -d "${TMPDIR:-/tmp}/fmu_exports_XXXXXX")
trap 'rm -rf "$work"' EXIT

if command -v unzip >/dev/null; then
  unzip -q "$fmu_abs" 'modelDescription.xml' "binaries/$platform/*" -d "$work" 2>/dev/null || true
else
  (cd "$work" && "${CMAKE_COMMAND:-cmake}" -E tar xf "$fmu_abs") || true
fi

errors=0
error() { echo "$fmu: error: $*"; errors=$((errors + 1)); }

[[ -f $work/modelDescription.xml ]] || { error "[exports.archive] no modelDescription.xml"; exit 1; }
# the modelIdentifier of an interface element, by plain text matching (attributes may span lines)
model_identifier_of() {
  tr '\n\r\t' '   ' < "$work/modelDescription.xml" |
    grep -o "<$1[[:space:]/>][^>]*>" | head -n 1 |
    sed -n 's/.*[[:space:]]modelIdentifier[[:space:]]*=[[:space:]]*["'"'"']\([^"'"'"']*\)["'"'"'].*/\1/p' ||
    true
}

functions_common=(fmi2GetTypesPlatform fmi2GetVersion fmi2SetDebugLogging fmi2Instantiate
  fmi2FreeInstance fmi2SetupExperiment fmi2EnterInitializationMode fmi2ExitInitializationMode
  fmi2Terminate fmi2Reset fmi2GetReal fmi2GetInteger fmi2GetBoolean fmi2GetString fmi2SetReal
  fmi2SetInteger fmi2SetBoolean fmi2SetString fmi2GetFMUstate fmi2SetFMUstate fmi2FreeFMUstate
  fmi2SerializedFMUstateSize fmi2SerializeFMUstate fmi2DeSerializeFMUstate
  fmi2GetDirectionalDerivative)
functions_cs=(fmi2SetRealInputDerivatives fmi2GetRealOutputDerivatives fmi2DoStep fmi2CancelStep
  fmi2GetStatus fmi2GetRealStatus fmi2GetIntegerStatus fmi2GetBooleanStatus fmi2GetStringStatus)
functions_me=(fmi2EnterEventMode fmi2NewDiscreteStates fmi2EnterContinuousTimeMode
  fmi2CompletedIntegratorStep fmi2SetTime fmi2SetContinuousStates fmi2GetDerivatives
  fmi2GetEventIndicators fmi2GetContinuousStates fmi2GetNominalsOfContinuousStates)
# every FMI 3.0 function, also those of Model Exchange and Scheduled Execution
functions3=(fmi3GetVersion fmi3SetDebugLogging fmi3InstantiateModelExchange
  fmi3InstantiateCoSimulation fmi3InstantiateScheduledExecution fmi3FreeInstance
  fmi3EnterInitializationMode fmi3ExitInitializationMode fmi3EnterEventMode fmi3Terminate
  fmi3Reset fmi3GetFloat32 fmi3GetFloat64 fmi3GetInt8 fmi3GetUInt8 fmi3GetInt16 fmi3GetUInt16
  fmi3GetInt32 fmi3GetUInt32 fmi3GetInt64 fmi3GetUInt64 fmi3GetBoolean fmi3GetString
  fmi3GetBinary fmi3GetClock fmi3SetFloat32 fmi3SetFloat64 fmi3SetInt8 fmi3SetUInt8
  fmi3SetInt16 fmi3SetUInt16 fmi3SetInt32 fmi3SetUInt32 fmi3SetInt64 fmi3SetUInt64
  fmi3SetBoolean fmi3SetString fmi3SetBinary fmi3SetClock fmi3GetNumberOfVariableDependencies
  fmi3GetVariableDependencies fmi3GetFMUState fmi3SetFMUState fmi3FreeFMUState
  fmi3SerializedFMUStateSize fmi3SerializeFMUState fmi3DeserializeFMUState
  fmi3GetDirectionalDerivative fmi3GetAdjointDerivative fmi3EnterConfigurationMode
  fmi3ExitConfigurationMode fmi3GetIntervalDecimal fmi3GetIntervalFraction fmi3GetShiftDecimal
  fmi3GetShiftFraction fmi3SetIntervalDecimal fmi3SetIntervalFraction fmi3SetShiftDecimal
  fmi3SetShiftFraction fmi3EvaluateDiscreteStates fmi3UpdateDiscreteStates
  fmi3EnterContinuousTimeMode fmi3CompletedIntegratorStep fmi3SetTime fmi3SetContinuousStates
  fmi3GetContinuousStateDerivatives fmi3GetEventIndicators fmi3GetContinuousStates
  fmi3GetNominalsOfContinuousStates fmi3GetNumberOfEventIndicators
  fmi3GetNumberOfContinuousStates fmi3EnterStepMode fmi3GetOutputDerivatives fmi3DoStep
  fmi3ActivateModelPartition)

# the binaries to check: model identifier -> the interface types whose functions it must export
cs_identifier=$(model_identifier_of CoSimulation)
me_identifier=$(model_identifier_of ModelExchange)
[[ -n $cs_identifier || -n $me_identifier ]] ||
  { error "[exports.archive] no CoSimulation@modelIdentifier or ModelExchange@modelIdentifier"; exit 1; }
declare -A interfaces=()
[[ -z $cs_identifier ]] || interfaces[$cs_identifier]="cs"
[[ -z $me_identifier ]] || interfaces[$me_identifier]="${interfaces[$me_identifier]:-} me"

bin_dir=$work/binaries/$platform
checked=()
for model_identifier in $(printf '%s\n' "${!interfaces[@]}" | sort); do
  so=$bin_dir/$model_identifier.so
  [[ -f $so ]] || { error "[exports.archive] no binaries/$platform/$model_identifier.so"; continue; }

  # --- exported symbols of the FMU library
  symbols=$(nm -D --defined-only "$so" | awk 'NF >= 3 { print $2, $3 }') ||
    { error "[exports.nm] nm -D failed on $model_identifier.so"; continue; }
  extra=()
  declare -A exported=()
  while read -r type name; do
    [[ -n ${name:-} ]] || continue
    name=${name%%@*}
    case $name in
      "$prefix"*) exported[$name]=$type ;;
      *) extra+=("$name ($type)") ;;
    esac
  done <<< "$symbols"
  if ((${#extra[@]} > 0)); then
    shown=$(printf '%s, ' "${extra[@]:0:20}")
    more=""
    ((${#extra[@]} > 20)) && more=" and $((${#extra[@]} - 20)) more"
    error "[exports.symbols] $model_identifier.so exports ${#extra[@]} non-$prefix symbol(s): ${shown%, }$more" \
      "(build with -fvisibility=hidden and a version script { global: $prefix*; local: *; };" \
      "with -static-libstdc++ also -Wl,--exclude-libs,ALL)"
  fi

  if ((version == 3)); then
    functions=("${functions3[@]}")
    what="FMI 3.0 functions"
  else
    functions=("${functions_common[@]}")
    kinds=()
    if [[ ${interfaces[$model_identifier]} == *cs* ]]; then
      functions+=("${functions_cs[@]}")
      kinds+=("Co-Simulation")
    fi
    if [[ ${interfaces[$model_identifier]} == *me* ]]; then
      functions+=("${functions_me[@]}")
      kinds+=("Model Exchange")
    fi
    what="FMI 2.0 $(IFS=+; echo "${kinds[*]}") functions"
    what=${what//+/ + }
  fi
  missing=()
  for f in "${functions[@]}"; do
    if [[ -z ${exported[$f]:-} ]]; then
      missing+=("$f")
    elif [[ ${exported[$f]} != [TtWi] ]]; then
      error "[exports.functions] $f is exported as nm type ${exported[$f]}, not as a function"
    fi
  done
  if ((${#missing[@]} > 0)); then
    error "[exports.functions] $model_identifier.so does not export ${#missing[@]} of the" \
      "${#functions[@]} $what: ${missing[*]}"
  fi
  unset exported
  checked+=("$model_identifier.so exports the ${#functions[@]} $what")
done

# --- NEEDED libraries of every shared library in binaries/<platform>/
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
        "library (libc, libm, libpthread, libdl, librt, ld-linux) nor shipped in binaries/$platform/"
    fi
  done <<< "$needed"
  if ((bundled)) && ! grep -qE '\((RUNPATH|RPATH)\).*\$ORIGIN' <<< "$(readelf -d "$lib")"; then
    error "[exports.needed] $(basename "$lib") needs libraries shipped next to it but has no" \
      "RPATH/RUNPATH \$ORIGIN to find them"
  fi
done

if ((errors > 0)); then
  exit 1
fi
echo "$fmu: ok: $(printf '%s; ' "${checked[@]}")only $prefix symbols; NEEDED libraries allowed"
