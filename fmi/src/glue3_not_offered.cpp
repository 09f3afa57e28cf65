// The FMI 3.0 functions of features Stride FMUs do not offer. Each must still be exported; each
// answers fmi3Error and logs why (docs/fmi3-rules.md §4).
#include "glue3.hpp"

using namespace stride::sdk::glue;

namespace {
constexpr const char* k_no_events = "hasEventMode is false";
constexpr const char* k_no_clocks = "the FMU has no clocks";
constexpr const char* k_no_me = "the FMU offers Co-Simulation only";
}  // namespace

extern "C" {

fmi3Status fmi3EnterEventMode(fmi3Instance i) {
  return not_offered(i, "fmi3EnterEventMode", k_no_events);
}
fmi3Status fmi3EnterStepMode(fmi3Instance i) {
  return not_offered(i, "fmi3EnterStepMode", k_no_events);
}
fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance i) {
  return not_offered(i, "fmi3EvaluateDiscreteStates", k_no_events);
}
fmi3Status fmi3UpdateDiscreteStates(fmi3Instance i, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*,
                                    fmi3Boolean*, fmi3Boolean*, fmi3Float64*) {
  return not_offered(i, "fmi3UpdateDiscreteStates", k_no_events);
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance i, fmi3ValueReference, size_t*) {
  return not_offered(i, "fmi3GetNumberOfVariableDependencies",
                     "providesPerElementDependencies is false");
}
fmi3Status fmi3GetVariableDependencies(fmi3Instance i, fmi3ValueReference, size_t[],
                                       fmi3ValueReference[], size_t[], fmi3DependencyKind[],
                                       size_t) {
  return not_offered(i, "fmi3GetVariableDependencies", "providesPerElementDependencies is false");
}
fmi3Status fmi3GetDirectionalDerivative(fmi3Instance i, const fmi3ValueReference[], size_t,
                                        const fmi3ValueReference[], size_t, const fmi3Float64[],
                                        size_t, fmi3Float64[], size_t) {
  return not_offered(i, "fmi3GetDirectionalDerivative", "providesDirectionalDerivatives is false");
}
fmi3Status fmi3GetAdjointDerivative(fmi3Instance i, const fmi3ValueReference[], size_t,
                                    const fmi3ValueReference[], size_t, const fmi3Float64[], size_t,
                                    fmi3Float64[], size_t) {
  return not_offered(i, "fmi3GetAdjointDerivative", "providesAdjointDerivatives is false");
}
fmi3Status fmi3GetOutputDerivatives(fmi3Instance i, const fmi3ValueReference[], size_t,
                                    const fmi3Int32[], fmi3Float64[], size_t) {
  return not_offered(i, "fmi3GetOutputDerivatives", "maxOutputDerivativeOrder is 0");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance i) {
  return not_offered(i, "fmi3EnterConfigurationMode", "the FMU has no structural parameters");
}
fmi3Status fmi3ExitConfigurationMode(fmi3Instance i) {
  return not_offered(i, "fmi3ExitConfigurationMode", "the FMU has no structural parameters");
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance i, const fmi3ValueReference[], size_t, fmi3Float64[],
                                  fmi3IntervalQualifier[]) {
  return not_offered(i, "fmi3GetIntervalDecimal", k_no_clocks);
}
fmi3Status fmi3GetIntervalFraction(fmi3Instance i, const fmi3ValueReference[], size_t, fmi3UInt64[],
                                   fmi3UInt64[], fmi3IntervalQualifier[]) {
  return not_offered(i, "fmi3GetIntervalFraction", k_no_clocks);
}
fmi3Status fmi3GetShiftDecimal(fmi3Instance i, const fmi3ValueReference[], size_t, fmi3Float64[]) {
  return not_offered(i, "fmi3GetShiftDecimal", k_no_clocks);
}
fmi3Status fmi3GetShiftFraction(fmi3Instance i, const fmi3ValueReference[], size_t, fmi3UInt64[],
                                fmi3UInt64[]) {
  return not_offered(i, "fmi3GetShiftFraction", k_no_clocks);
}
fmi3Status fmi3SetIntervalDecimal(fmi3Instance i, const fmi3ValueReference[], size_t,
                                  const fmi3Float64[]) {
  return not_offered(i, "fmi3SetIntervalDecimal", k_no_clocks);
}
fmi3Status fmi3SetIntervalFraction(fmi3Instance i, const fmi3ValueReference[], size_t,
                                   const fmi3UInt64[], const fmi3UInt64[]) {
  return not_offered(i, "fmi3SetIntervalFraction", k_no_clocks);
}
fmi3Status fmi3SetShiftDecimal(fmi3Instance i, const fmi3ValueReference[], size_t,
                               const fmi3Float64[]) {
  return not_offered(i, "fmi3SetShiftDecimal", k_no_clocks);
}
fmi3Status fmi3SetShiftFraction(fmi3Instance i, const fmi3ValueReference[], size_t,
                                const fmi3UInt64[], const fmi3UInt64[]) {
  return not_offered(i, "fmi3SetShiftFraction", k_no_clocks);
}
fmi3Status fmi3ActivateModelPartition(fmi3Instance i, fmi3ValueReference, fmi3Float64) {
  return not_offered(i, "fmi3ActivateModelPartition", "the FMU offers no Scheduled Execution");
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance i) {
  return not_offered(i, "fmi3EnterContinuousTimeMode", k_no_me);
}
fmi3Status fmi3CompletedIntegratorStep(fmi3Instance i, fmi3Boolean, fmi3Boolean*, fmi3Boolean*) {
  return not_offered(i, "fmi3CompletedIntegratorStep", k_no_me);
}
fmi3Status fmi3SetTime(fmi3Instance i, fmi3Float64) {
  return not_offered(i, "fmi3SetTime", k_no_me);
}
fmi3Status fmi3SetContinuousStates(fmi3Instance i, const fmi3Float64[], size_t) {
  return not_offered(i, "fmi3SetContinuousStates", k_no_me);
}
fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance i, fmi3Float64[], size_t) {
  return not_offered(i, "fmi3GetContinuousStateDerivatives", k_no_me);
}
fmi3Status fmi3GetEventIndicators(fmi3Instance i, fmi3Float64[], size_t) {
  return not_offered(i, "fmi3GetEventIndicators", k_no_me);
}
fmi3Status fmi3GetContinuousStates(fmi3Instance i, fmi3Float64[], size_t) {
  return not_offered(i, "fmi3GetContinuousStates", k_no_me);
}
fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance i, fmi3Float64[], size_t) {
  return not_offered(i, "fmi3GetNominalsOfContinuousStates", k_no_me);
}
fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance i, size_t*) {
  return not_offered(i, "fmi3GetNumberOfEventIndicators", k_no_me);
}
fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance i, size_t*) {
  return not_offered(i, "fmi3GetNumberOfContinuousStates", k_no_me);
}

}  // extern "C"
