/* The FMI 2.0 Model Exchange interface (FMI 2.0 standard, chapter 3): the event information
 * record and the functions an importer calls to integrate an FMU's equations itself. Written from
 * the standard's text; the common functions and types are in fmi2_api.h. */
#ifndef STRIDE_FMI2_FMI2_ME_API_H
#define STRIDE_FMI2_FMI2_ME_API_H

#include "stride/fmi2/fmi2_api.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What fmi2NewDiscreteStates reports after one pass of event iteration. */
typedef struct {
  fmi2Boolean newDiscreteStatesNeeded;
  fmi2Boolean terminateSimulation;
  fmi2Boolean nominalsOfContinuousStatesChanged;
  fmi2Boolean valuesOfContinuousStatesChanged;
  fmi2Boolean nextEventTimeDefined;
  fmi2Real nextEventTime;
} fmi2EventInfo;

/* ---- Model Exchange functions (10) ---- */
STRIDE_FMI2_EXPORT fmi2Status fmi2EnterEventMode(fmi2Component c);
STRIDE_FMI2_EXPORT fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo* eventInfo);
STRIDE_FMI2_EXPORT fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c);
STRIDE_FMI2_EXPORT fmi2Status
fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                            fmi2Boolean* enterEventMode, fmi2Boolean* terminateSimulation);
STRIDE_FMI2_EXPORT fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time);
STRIDE_FMI2_EXPORT fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[],
                                                      size_t nx);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[],
                                                 size_t nx);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[],
                                                     size_t ni);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c,
                                                                fmi2Real x_nominal[], size_t nx);

/* ---- pointer types, for importers that resolve the functions with dlsym ---- */
typedef fmi2Status fmi2EnterEventModeTYPE(fmi2Component);
typedef fmi2Status fmi2NewDiscreteStatesTYPE(fmi2Component, fmi2EventInfo*);
typedef fmi2Status fmi2EnterContinuousTimeModeTYPE(fmi2Component);
typedef fmi2Status fmi2CompletedIntegratorStepTYPE(fmi2Component, fmi2Boolean, fmi2Boolean*,
                                                   fmi2Boolean*);
typedef fmi2Status fmi2SetTimeTYPE(fmi2Component, fmi2Real);
typedef fmi2Status fmi2SetContinuousStatesTYPE(fmi2Component, const fmi2Real[], size_t);
typedef fmi2Status fmi2GetDerivativesTYPE(fmi2Component, fmi2Real[], size_t);
typedef fmi2Status fmi2GetEventIndicatorsTYPE(fmi2Component, fmi2Real[], size_t);
typedef fmi2Status fmi2GetContinuousStatesTYPE(fmi2Component, fmi2Real[], size_t);
typedef fmi2Status fmi2GetNominalsOfContinuousStatesTYPE(fmi2Component, fmi2Real[], size_t);

/* X-macro over the 10 Model Exchange function names. */
#define STRIDE_FMI2_ME_FUNCTIONS(X) \
  X(fmi2EnterEventMode)             \
  X(fmi2NewDiscreteStates)          \
  X(fmi2EnterContinuousTimeMode)    \
  X(fmi2CompletedIntegratorStep)    \
  X(fmi2SetTime)                    \
  X(fmi2SetContinuousStates)        \
  X(fmi2GetDerivatives)             \
  X(fmi2GetEventIndicators)         \
  X(fmi2GetContinuousStates)        \
  X(fmi2GetNominalsOfContinuousStates)

#ifdef __cplusplus
}
#endif

#endif /* STRIDE_FMI2_FMI2_ME_API_H */
