/* The FMI 3.0 functions fmi3_kinds does not offer besides those of ../fmi3_unoffered.c: Model
 * Exchange, event mode and step mode. They answer fmi3Error or NULL as docs/fmi3-rules.md §4
 * asks. */
#include "stride/fmi3/fmi3_api.h"

#define UNUSED(x) (void)(x)

fmi3Instance fmi3InstantiateModelExchange(fmi3String a, fmi3String b, fmi3String c, fmi3Boolean d,
                                          fmi3Boolean e, fmi3InstanceEnvironment f,
                                          fmi3LogMessageCallback g) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e), UNUSED(f), UNUSED(g);
  return NULL;
}
fmi3Status fmi3EnterEventMode(fmi3Instance a) {
  UNUSED(a);
  return fmi3Error;
}
fmi3Status fmi3UpdateDiscreteStates(fmi3Instance a, fmi3Boolean* b, fmi3Boolean* c, fmi3Boolean* d,
                                    fmi3Boolean* e, fmi3Boolean* f, fmi3Float64* g) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e), UNUSED(f), UNUSED(g);
  return fmi3Error;
}
fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance a) {
  UNUSED(a);
  return fmi3Error;
}
fmi3Status fmi3CompletedIntegratorStep(fmi3Instance a, fmi3Boolean b, fmi3Boolean* c,
                                       fmi3Boolean* d) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d);
  return fmi3Error;
}
fmi3Status fmi3SetTime(fmi3Instance a, fmi3Float64 b) {
  UNUSED(a), UNUSED(b);
  return fmi3Error;
}
fmi3Status fmi3SetContinuousStates(fmi3Instance a, const fmi3Float64 b[], size_t c) {
  UNUSED(a), UNUSED(b), UNUSED(c);
  return fmi3Error;
}
fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance a, fmi3Float64 b[], size_t c) {
  UNUSED(a), UNUSED(b), UNUSED(c);
  return fmi3Error;
}
fmi3Status fmi3GetEventIndicators(fmi3Instance a, fmi3Float64 b[], size_t c) {
  UNUSED(a), UNUSED(b), UNUSED(c);
  return fmi3Error;
}
fmi3Status fmi3GetContinuousStates(fmi3Instance a, fmi3Float64 b[], size_t c) {
  UNUSED(a), UNUSED(b), UNUSED(c);
  return fmi3Error;
}
fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance a, fmi3Float64 b[], size_t c) {
  UNUSED(a), UNUSED(b), UNUSED(c);
  return fmi3Error;
}
fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance a, size_t* b) {
  UNUSED(a), UNUSED(b);
  return fmi3Error;
}
fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance a, size_t* b) {
  UNUSED(a), UNUSED(b);
  return fmi3Error;
}
fmi3Status fmi3EnterStepMode(fmi3Instance a) {
  UNUSED(a);
  return fmi3Error;
}
fmi3Status fmi3GetOutputDerivatives(fmi3Instance a, const fmi3ValueReference b[], size_t c,
                                    const fmi3Int32 d[], fmi3Float64 e[], size_t f) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e), UNUSED(f);
  return fmi3Error;
}
