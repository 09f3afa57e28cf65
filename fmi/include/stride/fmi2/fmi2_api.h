/* FMI 2.0 Co-Simulation C API, declared for Stride from the FMI 2.0.x specification.
 *
 * The type names, enumerator values and function signatures below are the binary interface of
 * the standard; they must stay exactly as the specification defines them. Only the
 * Co-Simulation subset (25 common + 9 Co-Simulation functions) is declared.
 */
#ifndef STRIDE_FMI2_FMI2_API_H
#define STRIDE_FMI2_FMI2_API_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- platform types ("default" types platform) ---- */
typedef void* fmi2Component;
typedef void* fmi2ComponentEnvironment;
typedef void* fmi2FMUstate;
typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Integer;
typedef int fmi2Boolean;
typedef char fmi2Char;
typedef const fmi2Char* fmi2String;
typedef char fmi2Byte;

#define fmi2True 1
#define fmi2False 0

#define STRIDE_FMI2_TYPES_PLATFORM "default"
#define STRIDE_FMI2_VERSION "2.0"

/* ---- status and kinds ---- */
typedef enum { fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending } fmi2Status;

typedef enum { fmi2ModelExchange, fmi2CoSimulation } fmi2Type;

typedef enum {
  fmi2DoStepStatus,
  fmi2PendingStatus,
  fmi2LastSuccessfulTime,
  fmi2Terminated
} fmi2StatusKind;

/* ---- callbacks handed to fmi2Instantiate ---- */
typedef void (*fmi2CallbackLogger)(fmi2ComponentEnvironment componentEnvironment,
                                   fmi2String instanceName, fmi2Status status, fmi2String category,
                                   fmi2String message, ...);
typedef void* (*fmi2CallbackAllocateMemory)(size_t nobj, size_t size);
typedef void (*fmi2CallbackFreeMemory)(void* obj);
typedef void (*fmi2StepFinished)(fmi2ComponentEnvironment componentEnvironment, fmi2Status status);

typedef struct {
  const fmi2CallbackLogger logger;
  const fmi2CallbackAllocateMemory allocateMemory;
  const fmi2CallbackFreeMemory freeMemory;
  const fmi2StepFinished stepFinished;
  const fmi2ComponentEnvironment componentEnvironment;
} fmi2CallbackFunctions;

/* ---- export decoration: only these symbols leave an FMU's shared library ---- */
#if defined(STRIDE_FMI2_BUILDING_FMU)
#define STRIDE_FMI2_EXPORT __attribute__((visibility("default")))
#else
#define STRIDE_FMI2_EXPORT
#endif

/* ---- common functions (25) ---- */
STRIDE_FMI2_EXPORT const char* fmi2GetTypesPlatform(void);
STRIDE_FMI2_EXPORT const char* fmi2GetVersion(void);
STRIDE_FMI2_EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn,
                                                  size_t nCategories,
                                                  const fmi2String categories[]);
STRIDE_FMI2_EXPORT fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType,
                                                 fmi2String fmuGUID, fmi2String fmuResourceLocation,
                                                 const fmi2CallbackFunctions* functions,
                                                 fmi2Boolean visible, fmi2Boolean loggingOn);
STRIDE_FMI2_EXPORT void fmi2FreeInstance(fmi2Component c);
STRIDE_FMI2_EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                                                  fmi2Real tolerance, fmi2Real startTime,
                                                  fmi2Boolean stopTimeDefined, fmi2Real stopTime);
STRIDE_FMI2_EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c);
STRIDE_FMI2_EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c);
STRIDE_FMI2_EXPORT fmi2Status fmi2Terminate(fmi2Component c);
STRIDE_FMI2_EXPORT fmi2Status fmi2Reset(fmi2Component c);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[],
                                          size_t nvr, fmi2Real value[]);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[],
                                             size_t nvr, fmi2Integer value[]);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                                             size_t nvr, fmi2Boolean value[]);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[],
                                            size_t nvr, fmi2String value[]);
STRIDE_FMI2_EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[],
                                          size_t nvr, const fmi2Real value[]);
STRIDE_FMI2_EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[],
                                             size_t nvr, const fmi2Integer value[]);
STRIDE_FMI2_EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                                             size_t nvr, const fmi2Boolean value[]);
STRIDE_FMI2_EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[],
                                            size_t nvr, const fmi2String value[]);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate);
STRIDE_FMI2_EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate);
STRIDE_FMI2_EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate);
STRIDE_FMI2_EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate,
                                                         size_t* size);
STRIDE_FMI2_EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate,
                                                    fmi2Byte serializedState[], size_t size);
STRIDE_FMI2_EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c,
                                                      const fmi2Byte serializedState[], size_t size,
                                                      fmi2FMUstate* FMUstate);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetDirectionalDerivative(fmi2Component c,
                                                           const fmi2ValueReference vUnknown_ref[],
                                                           size_t nUnknown,
                                                           const fmi2ValueReference vKnown_ref[],
                                                           size_t nKnown, const fmi2Real dvKnown[],
                                                           fmi2Real dvUnknown[]);

/* ---- Co-Simulation functions (9) ---- */
STRIDE_FMI2_EXPORT fmi2Status fmi2SetRealInputDerivatives(fmi2Component c,
                                                          const fmi2ValueReference vr[], size_t nvr,
                                                          const fmi2Integer order[],
                                                          const fmi2Real value[]);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c,
                                                           const fmi2ValueReference vr[],
                                                           size_t nvr, const fmi2Integer order[],
                                                           fmi2Real value[]);
STRIDE_FMI2_EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                                         fmi2Real communicationStepSize,
                                         fmi2Boolean noSetFMUStatePriorToCurrentPoint);
STRIDE_FMI2_EXPORT fmi2Status fmi2CancelStep(fmi2Component c);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s,
                                            fmi2Status* value);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s,
                                                fmi2Real* value);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s,
                                                   fmi2Integer* value);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s,
                                                   fmi2Boolean* value);
STRIDE_FMI2_EXPORT fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s,
                                                  fmi2String* value);

/* ---- pointer types, as importers resolve the functions with dlsym ---- */
typedef const char* fmi2GetTypesPlatformTYPE(void);
typedef const char* fmi2GetVersionTYPE(void);
typedef fmi2Status fmi2SetDebugLoggingTYPE(fmi2Component, fmi2Boolean, size_t, const fmi2String[]);
typedef fmi2Component fmi2InstantiateTYPE(fmi2String, fmi2Type, fmi2String, fmi2String,
                                          const fmi2CallbackFunctions*, fmi2Boolean, fmi2Boolean);
typedef void fmi2FreeInstanceTYPE(fmi2Component);
typedef fmi2Status fmi2SetupExperimentTYPE(fmi2Component, fmi2Boolean, fmi2Real, fmi2Real,
                                           fmi2Boolean, fmi2Real);
typedef fmi2Status fmi2EnterInitializationModeTYPE(fmi2Component);
typedef fmi2Status fmi2ExitInitializationModeTYPE(fmi2Component);
typedef fmi2Status fmi2TerminateTYPE(fmi2Component);
typedef fmi2Status fmi2ResetTYPE(fmi2Component);
typedef fmi2Status fmi2GetRealTYPE(fmi2Component, const fmi2ValueReference[], size_t, fmi2Real[]);
typedef fmi2Status fmi2GetIntegerTYPE(fmi2Component, const fmi2ValueReference[], size_t,
                                      fmi2Integer[]);
typedef fmi2Status fmi2GetBooleanTYPE(fmi2Component, const fmi2ValueReference[], size_t,
                                      fmi2Boolean[]);
typedef fmi2Status fmi2GetStringTYPE(fmi2Component, const fmi2ValueReference[], size_t,
                                     fmi2String[]);
typedef fmi2Status fmi2SetRealTYPE(fmi2Component, const fmi2ValueReference[], size_t,
                                   const fmi2Real[]);
typedef fmi2Status fmi2SetIntegerTYPE(fmi2Component, const fmi2ValueReference[], size_t,
                                      const fmi2Integer[]);
typedef fmi2Status fmi2SetBooleanTYPE(fmi2Component, const fmi2ValueReference[], size_t,
                                      const fmi2Boolean[]);
typedef fmi2Status fmi2SetStringTYPE(fmi2Component, const fmi2ValueReference[], size_t,
                                     const fmi2String[]);
typedef fmi2Status fmi2GetFMUstateTYPE(fmi2Component, fmi2FMUstate*);
typedef fmi2Status fmi2SetFMUstateTYPE(fmi2Component, fmi2FMUstate);
typedef fmi2Status fmi2FreeFMUstateTYPE(fmi2Component, fmi2FMUstate*);
typedef fmi2Status fmi2SerializedFMUstateSizeTYPE(fmi2Component, fmi2FMUstate, size_t*);
typedef fmi2Status fmi2SerializeFMUstateTYPE(fmi2Component, fmi2FMUstate, fmi2Byte[], size_t);
typedef fmi2Status fmi2DeSerializeFMUstateTYPE(fmi2Component, const fmi2Byte[], size_t,
                                               fmi2FMUstate*);
typedef fmi2Status fmi2GetDirectionalDerivativeTYPE(fmi2Component, const fmi2ValueReference[],
                                                    size_t, const fmi2ValueReference[], size_t,
                                                    const fmi2Real[], fmi2Real[]);
typedef fmi2Status fmi2SetRealInputDerivativesTYPE(fmi2Component, const fmi2ValueReference[],
                                                   size_t, const fmi2Integer[], const fmi2Real[]);
typedef fmi2Status fmi2GetRealOutputDerivativesTYPE(fmi2Component, const fmi2ValueReference[],
                                                    size_t, const fmi2Integer[], fmi2Real[]);
typedef fmi2Status fmi2DoStepTYPE(fmi2Component, fmi2Real, fmi2Real, fmi2Boolean);
typedef fmi2Status fmi2CancelStepTYPE(fmi2Component);
typedef fmi2Status fmi2GetStatusTYPE(fmi2Component, const fmi2StatusKind, fmi2Status*);
typedef fmi2Status fmi2GetRealStatusTYPE(fmi2Component, const fmi2StatusKind, fmi2Real*);
typedef fmi2Status fmi2GetIntegerStatusTYPE(fmi2Component, const fmi2StatusKind, fmi2Integer*);
typedef fmi2Status fmi2GetBooleanStatusTYPE(fmi2Component, const fmi2StatusKind, fmi2Boolean*);
typedef fmi2Status fmi2GetStringStatusTYPE(fmi2Component, const fmi2StatusKind, fmi2String*);

/* X-macro over the 34 function names, for importers that resolve them in a loop. */
#define STRIDE_FMI2_CS_FUNCTIONS(X) \
  X(fmi2GetTypesPlatform)           \
  X(fmi2GetVersion)                 \
  X(fmi2SetDebugLogging)            \
  X(fmi2Instantiate)                \
  X(fmi2FreeInstance)               \
  X(fmi2SetupExperiment)            \
  X(fmi2EnterInitializationMode)    \
  X(fmi2ExitInitializationMode)     \
  X(fmi2Terminate)                  \
  X(fmi2Reset)                      \
  X(fmi2GetReal)                    \
  X(fmi2GetInteger)                 \
  X(fmi2GetBoolean)                 \
  X(fmi2GetString)                  \
  X(fmi2SetReal)                    \
  X(fmi2SetInteger)                 \
  X(fmi2SetBoolean)                 \
  X(fmi2SetString)                  \
  X(fmi2GetFMUstate)                \
  X(fmi2SetFMUstate)                \
  X(fmi2FreeFMUstate)               \
  X(fmi2SerializedFMUstateSize)     \
  X(fmi2SerializeFMUstate)          \
  X(fmi2DeSerializeFMUstate)        \
  X(fmi2GetDirectionalDerivative)   \
  X(fmi2SetRealInputDerivatives)    \
  X(fmi2GetRealOutputDerivatives)   \
  X(fmi2DoStep)                     \
  X(fmi2CancelStep)                 \
  X(fmi2GetStatus)                  \
  X(fmi2GetRealStatus)              \
  X(fmi2GetIntegerStatus)           \
  X(fmi2GetBooleanStatus)           \
  X(fmi2GetStringStatus)

#ifdef __cplusplus
}
#endif

#endif /* STRIDE_FMI2_FMI2_API_H */
