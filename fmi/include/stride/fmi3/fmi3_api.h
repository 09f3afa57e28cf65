/* FMI 3.0 C API, declared for Stride from the standard's C API and platform types, as
 * docs/fmi3-rules.md §1 sets them out.
 *
 * The type names, enumerator values and function signatures below are the binary interface of
 * the standard; they must stay exactly as the specification defines them. Unlike
 * stride/fmi2/fmi2_api.h, which declares only the Co-Simulation subset, every function of the
 * standard is declared: an FMI 3.0 FMU must export all of them, including those of interface
 * types and capabilities it does not support (they then return fmi3Error).
 *
 * Exported names: Stride builds binary FMUs only and exports the plain names (fmi3DoStep, ...),
 * as stride/fmi2/fmi2_api.h does for 2.0. The FMI3_FUNCTION_PREFIX renaming of the standard's
 * headers serves source-code FMUs linked into one executable; it is not provided here.
 */
#ifndef STRIDE_FMI3_FMI3_API_H
#define STRIDE_FMI3_FMI3_API_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- platform types: fixed-width, so there is no "types platform" string as in 2.0 ---- */
typedef void* fmi3Instance;            /* the FMU instance */
typedef void* fmi3InstanceEnvironment; /* the importer's pointer, handed back to callbacks */
typedef void* fmi3FMUState;            /* a saved FMU state */
typedef uint32_t fmi3ValueReference;   /* one namespace for all variable types */
typedef float fmi3Float32;
typedef double fmi3Float64;
typedef int8_t fmi3Int8;
typedef uint8_t fmi3UInt8;
typedef int16_t fmi3Int16;
typedef uint16_t fmi3UInt16;
typedef int32_t fmi3Int32;
typedef uint32_t fmi3UInt32;
typedef int64_t fmi3Int64;
typedef uint64_t fmi3UInt64;
typedef bool fmi3Boolean; /* C99 bool: one byte on the usual ABIs, not int as fmi2Boolean */
typedef char fmi3Char;
typedef const fmi3Char* fmi3String; /* NUL-terminated UTF-8 */
typedef uint8_t fmi3Byte;
typedef const fmi3Byte* fmi3Binary; /* length travels separately (valueSizes[]) */
typedef bool fmi3Clock;             /* active or inactive */

#define fmi3True true
#define fmi3False false

#define fmi3ClockActive true
#define fmi3ClockInactive false

/* what fmi3GetVersion returns, and what fmiVersion in modelDescription.xml holds */
#define fmi3Version "3.0"

/* ---- status and kinds ---- */
/* no fmi3Pending: the asynchronous doStep of 2.0 is gone */
typedef enum { fmi3OK, fmi3Warning, fmi3Discard, fmi3Error, fmi3Fatal } fmi3Status;

/* kind of one dependency reported by fmi3GetVariableDependencies */
typedef enum {
  fmi3Independent,
  fmi3Constant,
  fmi3Fixed,
  fmi3Tunable,
  fmi3Discrete,
  fmi3Dependent
} fmi3DependencyKind;

/* whether a clock interval is known, unchanged or new (fmi3GetInterval*) */
typedef enum {
  fmi3IntervalNotYetKnown,
  fmi3IntervalUnchanged,
  fmi3IntervalChanged
} fmi3IntervalQualifier;

/* ---- callbacks handed to fmi3Instantiate*: plain arguments, no struct as in 2.0 ---- */
/* no instanceName and no varargs: the message is already formatted */
typedef void (*fmi3LogMessageCallback)(fmi3InstanceEnvironment instanceEnvironment,
                                       fmi3Status status, fmi3String category, fmi3String message);
/* Scheduled Execution: an output clock ticked */
typedef void (*fmi3ClockUpdateCallback)(fmi3InstanceEnvironment instanceEnvironment);
/* Co-Simulation: called by the FMU inside fmi3DoStep (Intermediate Update Mode) */
typedef void (*fmi3IntermediateUpdateCallback)(
    fmi3InstanceEnvironment instanceEnvironment, fmi3Float64 intermediateUpdateTime,
    fmi3Boolean intermediateVariableSetRequested, fmi3Boolean intermediateVariableGetAllowed,
    fmi3Boolean intermediateStepFinished, fmi3Boolean canReturnEarly,
    fmi3Boolean* earlyReturnRequested, fmi3Float64* earlyReturnTime);
/* Scheduled Execution: guard a critical section against preemption. The standard writes an
 * empty parameter list; (void) is the same type in C and what C++ means by () anyway. */
typedef void (*fmi3LockPreemptionCallback)(void);
typedef void (*fmi3UnlockPreemptionCallback)(void);

/* ---- export decoration: only these symbols leave an FMU's shared library ---- */
#if defined(STRIDE_FMI3_BUILDING_FMU)
#define STRIDE_FMI3_EXPORT __attribute__((visibility("default")))
#else
#define STRIDE_FMI3_EXPORT
#endif

/* ---- common functions: version, logging, instances, modes ---- */
STRIDE_FMI3_EXPORT const char* fmi3GetVersion(void);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn,
                                                  size_t nCategories,
                                                  const fmi3String categories[]);
STRIDE_FMI3_EXPORT fmi3Instance fmi3InstantiateModelExchange(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage);
STRIDE_FMI3_EXPORT fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate);
STRIDE_FMI3_EXPORT fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
    fmi3LockPreemptionCallback lockPreemption, fmi3UnlockPreemptionCallback unlockPreemption);
STRIDE_FMI3_EXPORT void fmi3FreeInstance(fmi3Instance instance);
/* takes over the arguments of 2.0's fmi2SetupExperiment */
STRIDE_FMI3_EXPORT fmi3Status fmi3EnterInitializationMode(
    fmi3Instance instance, fmi3Boolean toleranceDefined, fmi3Float64 tolerance,
    fmi3Float64 startTime, fmi3Boolean stopTimeDefined, fmi3Float64 stopTime);
STRIDE_FMI3_EXPORT fmi3Status fmi3ExitInitializationMode(fmi3Instance instance);
STRIDE_FMI3_EXPORT fmi3Status fmi3EnterEventMode(fmi3Instance instance);
STRIDE_FMI3_EXPORT fmi3Status fmi3Terminate(fmi3Instance instance);
STRIDE_FMI3_EXPORT fmi3Status fmi3Reset(fmi3Instance instance);

/* ---- getters: nValues counts array elements, nValueReferences counts variables ---- */
STRIDE_FMI3_EXPORT fmi3Status fmi3GetFloat32(fmi3Instance instance,
                                             const fmi3ValueReference valueReferences[],
                                             size_t nValueReferences, fmi3Float32 values[],
                                             size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetFloat64(fmi3Instance instance,
                                             const fmi3ValueReference valueReferences[],
                                             size_t nValueReferences, fmi3Float64 values[],
                                             size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetInt8(fmi3Instance instance,
                                          const fmi3ValueReference valueReferences[],
                                          size_t nValueReferences, fmi3Int8 values[],
                                          size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetUInt8(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, fmi3UInt8 values[],
                                           size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetInt16(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, fmi3Int16 values[],
                                           size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetUInt16(fmi3Instance instance,
                                            const fmi3ValueReference valueReferences[],
                                            size_t nValueReferences, fmi3UInt16 values[],
                                            size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetInt32(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, fmi3Int32 values[],
                                           size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetUInt32(fmi3Instance instance,
                                            const fmi3ValueReference valueReferences[],
                                            size_t nValueReferences, fmi3UInt32 values[],
                                            size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetInt64(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, fmi3Int64 values[],
                                           size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetUInt64(fmi3Instance instance,
                                            const fmi3ValueReference valueReferences[],
                                            size_t nValueReferences, fmi3UInt64 values[],
                                            size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetBoolean(fmi3Instance instance,
                                             const fmi3ValueReference valueReferences[],
                                             size_t nValueReferences, fmi3Boolean values[],
                                             size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetString(fmi3Instance instance,
                                            const fmi3ValueReference valueReferences[],
                                            size_t nValueReferences, fmi3String values[],
                                            size_t nValues);
/* valueSizes[i] receives the byte length of values[i] */
STRIDE_FMI3_EXPORT fmi3Status fmi3GetBinary(fmi3Instance instance,
                                            const fmi3ValueReference valueReferences[],
                                            size_t nValueReferences, size_t valueSizes[],
                                            fmi3Binary values[], size_t nValues);
/* a clock variable is scalar: one value per value reference, so no nValues */
STRIDE_FMI3_EXPORT fmi3Status fmi3GetClock(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, fmi3Clock values[]);

/* ---- setters ---- */
STRIDE_FMI3_EXPORT fmi3Status fmi3SetFloat32(fmi3Instance instance,
                                             const fmi3ValueReference valueReferences[],
                                             size_t nValueReferences, const fmi3Float32 values[],
                                             size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetFloat64(fmi3Instance instance,
                                             const fmi3ValueReference valueReferences[],
                                             size_t nValueReferences, const fmi3Float64 values[],
                                             size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetInt8(fmi3Instance instance,
                                          const fmi3ValueReference valueReferences[],
                                          size_t nValueReferences, const fmi3Int8 values[],
                                          size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetUInt8(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, const fmi3UInt8 values[],
                                           size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetInt16(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, const fmi3Int16 values[],
                                           size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetUInt16(fmi3Instance instance,
                                            const fmi3ValueReference valueReferences[],
                                            size_t nValueReferences, const fmi3UInt16 values[],
                                            size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetInt32(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, const fmi3Int32 values[],
                                           size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetUInt32(fmi3Instance instance,
                                            const fmi3ValueReference valueReferences[],
                                            size_t nValueReferences, const fmi3UInt32 values[],
                                            size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetInt64(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, const fmi3Int64 values[],
                                           size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetUInt64(fmi3Instance instance,
                                            const fmi3ValueReference valueReferences[],
                                            size_t nValueReferences, const fmi3UInt64 values[],
                                            size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetBoolean(fmi3Instance instance,
                                             const fmi3ValueReference valueReferences[],
                                             size_t nValueReferences, const fmi3Boolean values[],
                                             size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetString(fmi3Instance instance,
                                            const fmi3ValueReference valueReferences[],
                                            size_t nValueReferences, const fmi3String values[],
                                            size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetBinary(fmi3Instance instance,
                                            const fmi3ValueReference valueReferences[],
                                            size_t nValueReferences, const size_t valueSizes[],
                                            const fmi3Binary values[], size_t nValues);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetClock(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, const fmi3Clock values[]);

/* ---- variable dependencies at run time (after structural parameters changed) ---- */
STRIDE_FMI3_EXPORT fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance,
                                                                  fmi3ValueReference valueReference,
                                                                  size_t* nDependencies);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetVariableDependencies(
    fmi3Instance instance, fmi3ValueReference dependent, size_t elementIndicesOfDependent[],
    fmi3ValueReference independents[], size_t elementIndicesOfIndependents[],
    fmi3DependencyKind dependencyKinds[], size_t nDependencies);

/* ---- FMU state: note "State" with a capital S and "Deserialize" in one word in 3.0 ---- */
STRIDE_FMI3_EXPORT fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState* FMUState);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState);
STRIDE_FMI3_EXPORT fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState* FMUState);
STRIDE_FMI3_EXPORT fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance,
                                                         fmi3FMUState FMUState, size_t* size);
STRIDE_FMI3_EXPORT fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState,
                                                    fmi3Byte serializedState[], size_t size);
STRIDE_FMI3_EXPORT fmi3Status fmi3DeserializeFMUState(fmi3Instance instance,
                                                      const fmi3Byte serializedState[], size_t size,
                                                      fmi3FMUState* FMUState);

/* ---- partial derivatives: seed is the vector multiplied with the Jacobian ---- */
STRIDE_FMI3_EXPORT fmi3Status fmi3GetDirectionalDerivative(
    fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
    fmi3Float64 sensitivity[], size_t nSensitivity);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetAdjointDerivative(
    fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
    fmi3Float64 sensitivity[], size_t nSensitivity);

/* ---- configuration (structural parameters, before init) and reconfiguration (tunable) ---- */
STRIDE_FMI3_EXPORT fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance);
STRIDE_FMI3_EXPORT fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance);

/* ---- clocks: intervals and shifts, as a decimal or as counter / resolution ---- */
STRIDE_FMI3_EXPORT fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance,
                                                     const fmi3ValueReference valueReferences[],
                                                     size_t nValueReferences,
                                                     fmi3Float64 intervals[],
                                                     fmi3IntervalQualifier qualifiers[]);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetIntervalFraction(
    fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
    fmi3UInt64 counters[], fmi3UInt64 resolutions[], fmi3IntervalQualifier qualifiers[]);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetShiftDecimal(fmi3Instance instance,
                                                  const fmi3ValueReference valueReferences[],
                                                  size_t nValueReferences, fmi3Float64 shifts[]);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetShiftFraction(fmi3Instance instance,
                                                   const fmi3ValueReference valueReferences[],
                                                   size_t nValueReferences, fmi3UInt64 counters[],
                                                   fmi3UInt64 resolutions[]);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance,
                                                     const fmi3ValueReference valueReferences[],
                                                     size_t nValueReferences,
                                                     const fmi3Float64 intervals[]);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetIntervalFraction(fmi3Instance instance,
                                                      const fmi3ValueReference valueReferences[],
                                                      size_t nValueReferences,
                                                      const fmi3UInt64 counters[],
                                                      const fmi3UInt64 resolutions[]);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetShiftDecimal(fmi3Instance instance,
                                                  const fmi3ValueReference valueReferences[],
                                                  size_t nValueReferences,
                                                  const fmi3Float64 shifts[]);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetShiftFraction(fmi3Instance instance,
                                                   const fmi3ValueReference valueReferences[],
                                                   size_t nValueReferences,
                                                   const fmi3UInt64 counters[],
                                                   const fmi3UInt64 resolutions[]);

/* ---- discrete states (Event Mode of Model Exchange and Co-Simulation) ---- */
STRIDE_FMI3_EXPORT fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance);
STRIDE_FMI3_EXPORT fmi3Status fmi3UpdateDiscreteStates(
    fmi3Instance instance, fmi3Boolean* discreteStatesNeedUpdate, fmi3Boolean* terminateSimulation,
    fmi3Boolean* nominalsOfContinuousStatesChanged, fmi3Boolean* valuesOfContinuousStatesChanged,
    fmi3Boolean* nextEventTimeDefined, fmi3Float64* nextEventTime);

/* ---- Model Exchange ---- */
STRIDE_FMI3_EXPORT fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance);
STRIDE_FMI3_EXPORT fmi3Status
fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                            fmi3Boolean* enterEventMode, fmi3Boolean* terminateSimulation);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time);
STRIDE_FMI3_EXPORT fmi3Status fmi3SetContinuousStates(fmi3Instance instance,
                                                      const fmi3Float64 continuousStates[],
                                                      size_t nContinuousStates);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance,
                                                                fmi3Float64 derivatives[],
                                                                size_t nContinuousStates);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetEventIndicators(fmi3Instance instance,
                                                     fmi3Float64 eventIndicators[],
                                                     size_t nEventIndicators);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetContinuousStates(fmi3Instance instance,
                                                      fmi3Float64 continuousStates[],
                                                      size_t nContinuousStates);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance,
                                                                fmi3Float64 nominals[],
                                                                size_t nContinuousStates);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance,
                                                             size_t* nEventIndicators);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance,
                                                              size_t* nContinuousStates);

/* ---- Co-Simulation ---- */
STRIDE_FMI3_EXPORT fmi3Status fmi3EnterStepMode(fmi3Instance instance);
STRIDE_FMI3_EXPORT fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance,
                                                       const fmi3ValueReference valueReferences[],
                                                       size_t nValueReferences,
                                                       const fmi3Int32 orders[],
                                                       fmi3Float64 values[], size_t nValues);
/* the four out arguments replace 2.0's fmi2CancelStep and fmi2Get*Status */
STRIDE_FMI3_EXPORT fmi3Status fmi3DoStep(
    fmi3Instance instance, fmi3Float64 currentCommunicationPoint, fmi3Float64 communicationStepSize,
    fmi3Boolean noSetFMUStatePriorToCurrentPoint, fmi3Boolean* eventHandlingNeeded,
    fmi3Boolean* terminateSimulation, fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime);

/* ---- Scheduled Execution ---- */
STRIDE_FMI3_EXPORT fmi3Status fmi3ActivateModelPartition(fmi3Instance instance,
                                                         fmi3ValueReference clockReference,
                                                         fmi3Float64 activationTime);

/* ---- function types, as importers resolve the functions with dlsym ---- */
typedef const char* fmi3GetVersionTYPE(void);
typedef fmi3Status fmi3SetDebugLoggingTYPE(fmi3Instance, fmi3Boolean, size_t, const fmi3String[]);
typedef fmi3Instance fmi3InstantiateModelExchangeTYPE(fmi3String, fmi3String, fmi3String,
                                                      fmi3Boolean, fmi3Boolean,
                                                      fmi3InstanceEnvironment,
                                                      fmi3LogMessageCallback);
typedef fmi3Instance fmi3InstantiateCoSimulationTYPE(fmi3String, fmi3String, fmi3String,
                                                     fmi3Boolean, fmi3Boolean, fmi3Boolean,
                                                     fmi3Boolean, const fmi3ValueReference[],
                                                     size_t, fmi3InstanceEnvironment,
                                                     fmi3LogMessageCallback,
                                                     fmi3IntermediateUpdateCallback);
typedef fmi3Instance fmi3InstantiateScheduledExecutionTYPE(
    fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean, fmi3InstanceEnvironment,
    fmi3LogMessageCallback, fmi3ClockUpdateCallback, fmi3LockPreemptionCallback,
    fmi3UnlockPreemptionCallback);
typedef void fmi3FreeInstanceTYPE(fmi3Instance);
typedef fmi3Status fmi3EnterInitializationModeTYPE(fmi3Instance, fmi3Boolean, fmi3Float64,
                                                   fmi3Float64, fmi3Boolean, fmi3Float64);
typedef fmi3Status fmi3ExitInitializationModeTYPE(fmi3Instance);
typedef fmi3Status fmi3EnterEventModeTYPE(fmi3Instance);
typedef fmi3Status fmi3TerminateTYPE(fmi3Instance);
typedef fmi3Status fmi3ResetTYPE(fmi3Instance);

typedef fmi3Status fmi3GetFloat32TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                      fmi3Float32[], size_t);
typedef fmi3Status fmi3GetFloat64TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                      fmi3Float64[], size_t);
typedef fmi3Status fmi3GetInt8TYPE(fmi3Instance, const fmi3ValueReference[], size_t, fmi3Int8[],
                                   size_t);
typedef fmi3Status fmi3GetUInt8TYPE(fmi3Instance, const fmi3ValueReference[], size_t, fmi3UInt8[],
                                    size_t);
typedef fmi3Status fmi3GetInt16TYPE(fmi3Instance, const fmi3ValueReference[], size_t, fmi3Int16[],
                                    size_t);
typedef fmi3Status fmi3GetUInt16TYPE(fmi3Instance, const fmi3ValueReference[], size_t, fmi3UInt16[],
                                     size_t);
typedef fmi3Status fmi3GetInt32TYPE(fmi3Instance, const fmi3ValueReference[], size_t, fmi3Int32[],
                                    size_t);
typedef fmi3Status fmi3GetUInt32TYPE(fmi3Instance, const fmi3ValueReference[], size_t, fmi3UInt32[],
                                     size_t);
typedef fmi3Status fmi3GetInt64TYPE(fmi3Instance, const fmi3ValueReference[], size_t, fmi3Int64[],
                                    size_t);
typedef fmi3Status fmi3GetUInt64TYPE(fmi3Instance, const fmi3ValueReference[], size_t, fmi3UInt64[],
                                     size_t);
typedef fmi3Status fmi3GetBooleanTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                      fmi3Boolean[], size_t);
typedef fmi3Status fmi3GetStringTYPE(fmi3Instance, const fmi3ValueReference[], size_t, fmi3String[],
                                     size_t);
typedef fmi3Status fmi3GetBinaryTYPE(fmi3Instance, const fmi3ValueReference[], size_t, size_t[],
                                     fmi3Binary[], size_t);
typedef fmi3Status fmi3GetClockTYPE(fmi3Instance, const fmi3ValueReference[], size_t, fmi3Clock[]);

typedef fmi3Status fmi3SetFloat32TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                      const fmi3Float32[], size_t);
typedef fmi3Status fmi3SetFloat64TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                      const fmi3Float64[], size_t);
typedef fmi3Status fmi3SetInt8TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                   const fmi3Int8[], size_t);
typedef fmi3Status fmi3SetUInt8TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                    const fmi3UInt8[], size_t);
typedef fmi3Status fmi3SetInt16TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                    const fmi3Int16[], size_t);
typedef fmi3Status fmi3SetUInt16TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                     const fmi3UInt16[], size_t);
typedef fmi3Status fmi3SetInt32TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                    const fmi3Int32[], size_t);
typedef fmi3Status fmi3SetUInt32TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                     const fmi3UInt32[], size_t);
typedef fmi3Status fmi3SetInt64TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                    const fmi3Int64[], size_t);
typedef fmi3Status fmi3SetUInt64TYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                     const fmi3UInt64[], size_t);
typedef fmi3Status fmi3SetBooleanTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                      const fmi3Boolean[], size_t);
typedef fmi3Status fmi3SetStringTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                     const fmi3String[], size_t);
typedef fmi3Status fmi3SetBinaryTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                     const size_t[], const fmi3Binary[], size_t);
typedef fmi3Status fmi3SetClockTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                    const fmi3Clock[]);

typedef fmi3Status fmi3GetNumberOfVariableDependenciesTYPE(fmi3Instance, fmi3ValueReference,
                                                           size_t*);
typedef fmi3Status fmi3GetVariableDependenciesTYPE(fmi3Instance, fmi3ValueReference, size_t[],
                                                   fmi3ValueReference[], size_t[],
                                                   fmi3DependencyKind[], size_t);

typedef fmi3Status fmi3GetFMUStateTYPE(fmi3Instance, fmi3FMUState*);
typedef fmi3Status fmi3SetFMUStateTYPE(fmi3Instance, fmi3FMUState);
typedef fmi3Status fmi3FreeFMUStateTYPE(fmi3Instance, fmi3FMUState*);
typedef fmi3Status fmi3SerializedFMUStateSizeTYPE(fmi3Instance, fmi3FMUState, size_t*);
typedef fmi3Status fmi3SerializeFMUStateTYPE(fmi3Instance, fmi3FMUState, fmi3Byte[], size_t);
typedef fmi3Status fmi3DeserializeFMUStateTYPE(fmi3Instance, const fmi3Byte[], size_t,
                                               fmi3FMUState*);

typedef fmi3Status fmi3GetDirectionalDerivativeTYPE(fmi3Instance, const fmi3ValueReference[],
                                                    size_t, const fmi3ValueReference[], size_t,
                                                    const fmi3Float64[], size_t, fmi3Float64[],
                                                    size_t);
typedef fmi3Status fmi3GetAdjointDerivativeTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                                const fmi3ValueReference[], size_t,
                                                const fmi3Float64[], size_t, fmi3Float64[], size_t);

typedef fmi3Status fmi3EnterConfigurationModeTYPE(fmi3Instance);
typedef fmi3Status fmi3ExitConfigurationModeTYPE(fmi3Instance);

typedef fmi3Status fmi3GetIntervalDecimalTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                              fmi3Float64[], fmi3IntervalQualifier[]);
typedef fmi3Status fmi3GetIntervalFractionTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                               fmi3UInt64[], fmi3UInt64[], fmi3IntervalQualifier[]);
typedef fmi3Status fmi3GetShiftDecimalTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                           fmi3Float64[]);
typedef fmi3Status fmi3GetShiftFractionTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                            fmi3UInt64[], fmi3UInt64[]);
typedef fmi3Status fmi3SetIntervalDecimalTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                              const fmi3Float64[]);
typedef fmi3Status fmi3SetIntervalFractionTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                               const fmi3UInt64[], const fmi3UInt64[]);
typedef fmi3Status fmi3SetShiftDecimalTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                           const fmi3Float64[]);
typedef fmi3Status fmi3SetShiftFractionTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                            const fmi3UInt64[], const fmi3UInt64[]);

typedef fmi3Status fmi3EvaluateDiscreteStatesTYPE(fmi3Instance);
typedef fmi3Status fmi3UpdateDiscreteStatesTYPE(fmi3Instance, fmi3Boolean*, fmi3Boolean*,
                                                fmi3Boolean*, fmi3Boolean*, fmi3Boolean*,
                                                fmi3Float64*);

typedef fmi3Status fmi3EnterContinuousTimeModeTYPE(fmi3Instance);
typedef fmi3Status fmi3CompletedIntegratorStepTYPE(fmi3Instance, fmi3Boolean, fmi3Boolean*,
                                                   fmi3Boolean*);
typedef fmi3Status fmi3SetTimeTYPE(fmi3Instance, fmi3Float64);
typedef fmi3Status fmi3SetContinuousStatesTYPE(fmi3Instance, const fmi3Float64[], size_t);
typedef fmi3Status fmi3GetContinuousStateDerivativesTYPE(fmi3Instance, fmi3Float64[], size_t);
typedef fmi3Status fmi3GetEventIndicatorsTYPE(fmi3Instance, fmi3Float64[], size_t);
typedef fmi3Status fmi3GetContinuousStatesTYPE(fmi3Instance, fmi3Float64[], size_t);
typedef fmi3Status fmi3GetNominalsOfContinuousStatesTYPE(fmi3Instance, fmi3Float64[], size_t);
typedef fmi3Status fmi3GetNumberOfEventIndicatorsTYPE(fmi3Instance, size_t*);
typedef fmi3Status fmi3GetNumberOfContinuousStatesTYPE(fmi3Instance, size_t*);

typedef fmi3Status fmi3EnterStepModeTYPE(fmi3Instance);
typedef fmi3Status fmi3GetOutputDerivativesTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                                const fmi3Int32[], fmi3Float64[], size_t);
typedef fmi3Status fmi3DoStepTYPE(fmi3Instance, fmi3Float64, fmi3Float64, fmi3Boolean, fmi3Boolean*,
                                  fmi3Boolean*, fmi3Boolean*, fmi3Float64*);

typedef fmi3Status fmi3ActivateModelPartitionTYPE(fmi3Instance, fmi3ValueReference, fmi3Float64);

/* X-macro over all 75 function names (61 common, 10 Model Exchange, 3 Co-Simulation,
 * 1 Scheduled Execution), for importers that resolve them in a loop and for export checks. */
#define STRIDE_FMI3_FUNCTIONS(X)         \
  X(fmi3GetVersion)                      \
  X(fmi3SetDebugLogging)                 \
  X(fmi3InstantiateModelExchange)        \
  X(fmi3InstantiateCoSimulation)         \
  X(fmi3InstantiateScheduledExecution)   \
  X(fmi3FreeInstance)                    \
  X(fmi3EnterInitializationMode)         \
  X(fmi3ExitInitializationMode)          \
  X(fmi3EnterEventMode)                  \
  X(fmi3Terminate)                       \
  X(fmi3Reset)                           \
  X(fmi3GetFloat32)                      \
  X(fmi3GetFloat64)                      \
  X(fmi3GetInt8)                         \
  X(fmi3GetUInt8)                        \
  X(fmi3GetInt16)                        \
  X(fmi3GetUInt16)                       \
  X(fmi3GetInt32)                        \
  X(fmi3GetUInt32)                       \
  X(fmi3GetInt64)                        \
  X(fmi3GetUInt64)                       \
  X(fmi3GetBoolean)                      \
  X(fmi3GetString)                       \
  X(fmi3GetBinary)                       \
  X(fmi3GetClock)                        \
  X(fmi3SetFloat32)                      \
  X(fmi3SetFloat64)                      \
  X(fmi3SetInt8)                         \
  X(fmi3SetUInt8)                        \
  X(fmi3SetInt16)                        \
  X(fmi3SetUInt16)                       \
  X(fmi3SetInt32)                        \
  X(fmi3SetUInt32)                       \
  X(fmi3SetInt64)                        \
  X(fmi3SetUInt64)                       \
  X(fmi3SetBoolean)                      \
  X(fmi3SetString)                       \
  X(fmi3SetBinary)                       \
  X(fmi3SetClock)                        \
  X(fmi3GetNumberOfVariableDependencies) \
  X(fmi3GetVariableDependencies)         \
  X(fmi3GetFMUState)                     \
  X(fmi3SetFMUState)                     \
  X(fmi3FreeFMUState)                    \
  X(fmi3SerializedFMUStateSize)          \
  X(fmi3SerializeFMUState)               \
  X(fmi3DeserializeFMUState)             \
  X(fmi3GetDirectionalDerivative)        \
  X(fmi3GetAdjointDerivative)            \
  X(fmi3EnterConfigurationMode)          \
  X(fmi3ExitConfigurationMode)           \
  X(fmi3GetIntervalDecimal)              \
  X(fmi3GetIntervalFraction)             \
  X(fmi3GetShiftDecimal)                 \
  X(fmi3GetShiftFraction)                \
  X(fmi3SetIntervalDecimal)              \
  X(fmi3SetIntervalFraction)             \
  X(fmi3SetShiftDecimal)                 \
  X(fmi3SetShiftFraction)                \
  X(fmi3EvaluateDiscreteStates)          \
  X(fmi3UpdateDiscreteStates)            \
  X(fmi3EnterContinuousTimeMode)         \
  X(fmi3CompletedIntegratorStep)         \
  X(fmi3SetTime)                         \
  X(fmi3SetContinuousStates)             \
  X(fmi3GetContinuousStateDerivatives)   \
  X(fmi3GetEventIndicators)              \
  X(fmi3GetContinuousStates)             \
  X(fmi3GetNominalsOfContinuousStates)   \
  X(fmi3GetNumberOfEventIndicators)      \
  X(fmi3GetNumberOfContinuousStates)     \
  X(fmi3EnterStepMode)                   \
  X(fmi3GetOutputDerivatives)            \
  X(fmi3DoStep)                          \
  X(fmi3ActivateModelPartition)

#ifdef __cplusplus
}
#endif

#endif /* STRIDE_FMI3_FMI3_API_H */
