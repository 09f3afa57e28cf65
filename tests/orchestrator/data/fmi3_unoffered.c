/* The FMI 3.0 functions none of the hand-written test FMUs offers (Scheduled Execution, clocks,
 * dependencies, derivatives, configuration mode, discrete-state evaluation): every 3.0 binary
 * exports all functions of the API, and these answer fmi3Error or NULL as docs/fmi3-rules.md §4
 * asks. Linked into fmi3_kinds and the 3.0 Model Exchange test FMUs (me_fmus/). */
#include <stddef.h>

#include "stride/fmi3/fmi3_api.h"

#define UNUSED(x) (void)(x)

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String a, fmi3String b, fmi3String c,
                                               fmi3Boolean d, fmi3Boolean e,
                                               fmi3InstanceEnvironment f, fmi3LogMessageCallback g,
                                               fmi3ClockUpdateCallback h,
                                               fmi3LockPreemptionCallback i,
                                               fmi3UnlockPreemptionCallback j) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e), UNUSED(f), UNUSED(g), UNUSED(h);
  UNUSED(i), UNUSED(j);
  return NULL;
}
fmi3Status fmi3GetClock(fmi3Instance a, const fmi3ValueReference b[], size_t c, fmi3Clock d[]) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d);
  return fmi3Error;
}
fmi3Status fmi3SetClock(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                        const fmi3Clock d[]) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d);
  return fmi3Error;
}
fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance a, fmi3ValueReference b, size_t* c) {
  UNUSED(a), UNUSED(b), UNUSED(c);
  return fmi3Error;
}
fmi3Status fmi3GetVariableDependencies(fmi3Instance a, fmi3ValueReference b, size_t c[],
                                       fmi3ValueReference d[], size_t e[], fmi3DependencyKind f[],
                                       size_t g) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e), UNUSED(f), UNUSED(g);
  return fmi3Error;
}
fmi3Status fmi3GetDirectionalDerivative(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                                        const fmi3ValueReference d[], size_t e,
                                        const fmi3Float64 f[], size_t g, fmi3Float64 h[],
                                        size_t i) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e), UNUSED(f), UNUSED(g), UNUSED(h);
  UNUSED(i);
  return fmi3Error;
}
fmi3Status fmi3GetAdjointDerivative(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                                    const fmi3ValueReference d[], size_t e, const fmi3Float64 f[],
                                    size_t g, fmi3Float64 h[], size_t i) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e), UNUSED(f), UNUSED(g), UNUSED(h);
  UNUSED(i);
  return fmi3Error;
}
fmi3Status fmi3EnterConfigurationMode(fmi3Instance a) {
  UNUSED(a);
  return fmi3Error;
}
fmi3Status fmi3ExitConfigurationMode(fmi3Instance a) {
  UNUSED(a);
  return fmi3Error;
}
fmi3Status fmi3GetIntervalDecimal(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                                  fmi3Float64 d[], fmi3IntervalQualifier e[]) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e);
  return fmi3Error;
}
fmi3Status fmi3GetIntervalFraction(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                                   fmi3UInt64 d[], fmi3UInt64 e[], fmi3IntervalQualifier f[]) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e), UNUSED(f);
  return fmi3Error;
}
fmi3Status fmi3GetShiftDecimal(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                               fmi3Float64 d[]) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d);
  return fmi3Error;
}
fmi3Status fmi3GetShiftFraction(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                                fmi3UInt64 d[], fmi3UInt64 e[]) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e);
  return fmi3Error;
}
fmi3Status fmi3SetIntervalDecimal(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                                  const fmi3Float64 d[]) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d);
  return fmi3Error;
}
fmi3Status fmi3SetIntervalFraction(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                                   const fmi3UInt64 d[], const fmi3UInt64 e[]) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e);
  return fmi3Error;
}
fmi3Status fmi3SetShiftDecimal(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                               const fmi3Float64 d[]) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d);
  return fmi3Error;
}
fmi3Status fmi3SetShiftFraction(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                                const fmi3UInt64 d[], const fmi3UInt64 e[]) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e);
  return fmi3Error;
}
fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance a) {
  UNUSED(a);
  return fmi3Error;
}
fmi3Status fmi3ActivateModelPartition(fmi3Instance a, fmi3ValueReference b, fmi3Float64 c) {
  UNUSED(a), UNUSED(b), UNUSED(c);
  return fmi3Error;
}
