/* The Co-Simulation functions of the 3.0 API, which the Model Exchange test FMUs do not offer;
 * the rest they do not offer is in ../data/fmi3_unoffered.c. Every 3.0 binary exports all
 * functions of the API; these answer with a refusal. */
#include <stddef.h>

#include "stride/fmi3/fmi3_api.h"

#define UNUSED(x) (void)(x)

fmi3Instance fmi3InstantiateCoSimulation(fmi3String a, fmi3String b, fmi3String c, fmi3Boolean d,
                                         fmi3Boolean e, fmi3Boolean f, fmi3Boolean g,
                                         const fmi3ValueReference h[], size_t i,
                                         fmi3InstanceEnvironment j, fmi3LogMessageCallback k,
                                         fmi3IntermediateUpdateCallback l) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e), UNUSED(f), UNUSED(g), UNUSED(h);
  UNUSED(i), UNUSED(j), UNUSED(k), UNUSED(l);
  return NULL;
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
fmi3Status fmi3DoStep(fmi3Instance a, fmi3Float64 b, fmi3Float64 c, fmi3Boolean d, fmi3Boolean* e,
                      fmi3Boolean* f, fmi3Boolean* g, fmi3Float64* h) {
  UNUSED(a), UNUSED(b), UNUSED(c), UNUSED(d), UNUSED(e), UNUSED(f), UNUSED(g), UNUSED(h);
  return fmi3Error;
}
