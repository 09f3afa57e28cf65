/* fmu3_importer: a foreign FMI 3.0 Co-Simulation importer in plain C11.
 *
 * The first half of this header declares what the importer uses of FMI 3.0, written from the
 * standard's fmi3PlatformTypes.h and fmi3FunctionTypes.h (no Stride header on purpose: an FMU that
 * only works with Stride's own declarations fails here). The second half is what the importer's
 * files share. */
#ifndef STRIDE_TESTS_FMU3_IMPORTER_H
#define STRIDE_TESTS_FMU3_IMPORTER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* ---- FMI 3.0 platform types: all of fixed width */
typedef void* fmi3Instance;
typedef void* fmi3InstanceEnvironment;
typedef void* fmi3FMUState;
typedef uint32_t fmi3ValueReference;
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
typedef bool fmi3Boolean;
typedef char fmi3Char;
typedef const fmi3Char* fmi3String;
typedef uint8_t fmi3Byte;
typedef const fmi3Byte* fmi3Binary;
typedef bool fmi3Clock;
#define fmi3True true
#define fmi3False false

typedef enum { fmi3OK, fmi3Warning, fmi3Discard, fmi3Error, fmi3Fatal } fmi3Status;
typedef enum {
  fmi3Independent,
  fmi3Constant,
  fmi3Fixed,
  fmi3Tunable,
  fmi3Discrete,
  fmi3Dependent
} fmi3DependencyKind;
typedef enum {
  fmi3IntervalNotYetKnown,
  fmi3IntervalUnchanged,
  fmi3IntervalChanged
} fmi3IntervalQualifier;

/* ---- callbacks */
typedef void fmi3LogMessageCallback(fmi3InstanceEnvironment instanceEnvironment, fmi3Status status,
                                    fmi3String category, fmi3String message);
typedef void fmi3ClockUpdateCallback(fmi3InstanceEnvironment instanceEnvironment);
typedef void fmi3IntermediateUpdateCallback(
    fmi3InstanceEnvironment instanceEnvironment, fmi3Float64 intermediateUpdateTime,
    fmi3Boolean intermediateVariableSetRequested, fmi3Boolean intermediateVariableGetAllowed,
    fmi3Boolean intermediateStepFinished, fmi3Boolean canReturnEarly,
    fmi3Boolean* earlyReturnRequested, fmi3Float64* earlyReturnTime);
typedef void fmi3LockPreemptionCallback(void);
typedef void fmi3UnlockPreemptionCallback(void);

/* ---- function types, <name>TYPE as in fmi3FunctionTypes.h */
typedef const char* fmi3GetVersionTYPE(void);
typedef fmi3Status fmi3SetDebugLoggingTYPE(fmi3Instance, fmi3Boolean loggingOn, size_t nCategories,
                                           const fmi3String categories[]);
typedef fmi3Instance fmi3InstantiateModelExchangeTYPE(fmi3String instanceName,
                                                      fmi3String instantiationToken,
                                                      fmi3String resourcePath, fmi3Boolean visible,
                                                      fmi3Boolean loggingOn,
                                                      fmi3InstanceEnvironment,
                                                      fmi3LogMessageCallback* logMessage);
typedef fmi3Instance fmi3InstantiateCoSimulationTYPE(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment,
    fmi3LogMessageCallback* logMessage, fmi3IntermediateUpdateCallback* intermediateUpdate);
typedef fmi3Instance fmi3InstantiateScheduledExecutionTYPE(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment,
    fmi3LogMessageCallback* logMessage, fmi3ClockUpdateCallback* clockUpdate,
    fmi3LockPreemptionCallback* lockPreemption, fmi3UnlockPreemptionCallback* unlockPreemption);
typedef void fmi3FreeInstanceTYPE(fmi3Instance);
typedef fmi3Status fmi3EnterInitializationModeTYPE(fmi3Instance, fmi3Boolean toleranceDefined,
                                                   fmi3Float64 tolerance, fmi3Float64 startTime,
                                                   fmi3Boolean stopTimeDefined,
                                                   fmi3Float64 stopTime);
typedef fmi3Status fmi3InstanceOnlyTYPE(fmi3Instance);
#define FMI3_GETSET_TYPES(T)                                                                      \
  typedef fmi3Status fmi3Get##T##TYPE(fmi3Instance, const fmi3ValueReference valueReferences[],   \
                                      size_t nValueReferences, fmi3##T values[], size_t nValues); \
  typedef fmi3Status fmi3Set##T##TYPE(fmi3Instance, const fmi3ValueReference valueReferences[],   \
                                      size_t nValueReferences, const fmi3##T values[],            \
                                      size_t nValues);
FMI3_GETSET_TYPES(Float32)
FMI3_GETSET_TYPES(Float64)
FMI3_GETSET_TYPES(Int8)
FMI3_GETSET_TYPES(UInt8)
FMI3_GETSET_TYPES(Int16)
FMI3_GETSET_TYPES(UInt16)
FMI3_GETSET_TYPES(Int32)
FMI3_GETSET_TYPES(UInt32)
FMI3_GETSET_TYPES(Int64)
FMI3_GETSET_TYPES(UInt64)
FMI3_GETSET_TYPES(Boolean)
FMI3_GETSET_TYPES(String)
#undef FMI3_GETSET_TYPES
typedef fmi3Status fmi3GetBinaryTYPE(fmi3Instance, const fmi3ValueReference valueReferences[],
                                     size_t nValueReferences, size_t valueSizes[],
                                     fmi3Binary values[], size_t nValues);
typedef fmi3Status fmi3SetBinaryTYPE(fmi3Instance, const fmi3ValueReference valueReferences[],
                                     size_t nValueReferences, const size_t valueSizes[],
                                     const fmi3Binary values[], size_t nValues);
typedef fmi3Status fmi3GetClockTYPE(fmi3Instance, const fmi3ValueReference valueReferences[],
                                    size_t nValueReferences, fmi3Clock values[]);
typedef fmi3Status fmi3SetClockTYPE(fmi3Instance, const fmi3ValueReference valueReferences[],
                                    size_t nValueReferences, const fmi3Clock values[]);
typedef fmi3Status fmi3GetNumberOfVariableDependenciesTYPE(fmi3Instance, fmi3ValueReference,
                                                           size_t* nDependencies);
typedef fmi3Status fmi3GetVariableDependenciesTYPE(fmi3Instance, fmi3ValueReference dependent,
                                                   size_t elementIndicesOfDependent[],
                                                   fmi3ValueReference independents[],
                                                   size_t elementIndicesOfIndependents[],
                                                   fmi3DependencyKind dependencyKinds[],
                                                   size_t nDependencies);
typedef fmi3Status fmi3GetFMUStateTYPE(fmi3Instance, fmi3FMUState* FMUState);
typedef fmi3Status fmi3SetFMUStateTYPE(fmi3Instance, fmi3FMUState FMUState);
typedef fmi3Status fmi3FreeFMUStateTYPE(fmi3Instance, fmi3FMUState* FMUState);
typedef fmi3Status fmi3SerializedFMUStateSizeTYPE(fmi3Instance, fmi3FMUState FMUState,
                                                  size_t* size);
typedef fmi3Status fmi3SerializeFMUStateTYPE(fmi3Instance, fmi3FMUState FMUState,
                                             fmi3Byte serializedState[], size_t size);
typedef fmi3Status fmi3DeserializeFMUStateTYPE(fmi3Instance, const fmi3Byte serializedState[],
                                               size_t size, fmi3FMUState* FMUState);
typedef fmi3Status fmi3GetDerivativeTYPE(fmi3Instance, const fmi3ValueReference unknowns[],
                                         size_t nUnknowns, const fmi3ValueReference knowns[],
                                         size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                         fmi3Float64 sensitivity[], size_t nSensitivity);
typedef fmi3Status fmi3GetIntervalDecimalTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                              fmi3Float64 intervals[],
                                              fmi3IntervalQualifier qualifiers[]);
typedef fmi3Status fmi3GetIntervalFractionTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                               fmi3UInt64 counters[], fmi3UInt64 resolutions[],
                                               fmi3IntervalQualifier qualifiers[]);
typedef fmi3Status fmi3GetShiftDecimalTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                           fmi3Float64 shifts[]);
typedef fmi3Status fmi3GetShiftFractionTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                            fmi3UInt64 counters[], fmi3UInt64 resolutions[]);
typedef fmi3Status fmi3SetIntervalDecimalTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                              const fmi3Float64 intervals[]);
typedef fmi3Status fmi3SetIntervalFractionTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                               const fmi3UInt64 counters[],
                                               const fmi3UInt64 resolutions[]);
typedef fmi3Status fmi3SetShiftDecimalTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                           const fmi3Float64 shifts[]);
typedef fmi3Status fmi3SetShiftFractionTYPE(fmi3Instance, const fmi3ValueReference[], size_t,
                                            const fmi3UInt64 counters[],
                                            const fmi3UInt64 resolutions[]);
typedef fmi3Status fmi3UpdateDiscreteStatesTYPE(fmi3Instance, fmi3Boolean* discreteStatesNeedUpdate,
                                                fmi3Boolean* terminateSimulation,
                                                fmi3Boolean* nominalsOfContinuousStatesChanged,
                                                fmi3Boolean* valuesOfContinuousStatesChanged,
                                                fmi3Boolean* nextEventTimeDefined,
                                                fmi3Float64* nextEventTime);
typedef fmi3Status fmi3CompletedIntegratorStepTYPE(fmi3Instance,
                                                   fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                                   fmi3Boolean* enterEventMode,
                                                   fmi3Boolean* terminateSimulation);
typedef fmi3Status fmi3SetTimeTYPE(fmi3Instance, fmi3Float64 time);
/* Set/GetContinuousStates, GetContinuousStateDerivatives, GetEventIndicators, GetNominals... */
typedef fmi3Status fmi3SetFloat64ArrayTYPE(fmi3Instance, const fmi3Float64 values[], size_t n);
typedef fmi3Status fmi3GetFloat64ArrayTYPE(fmi3Instance, fmi3Float64 values[], size_t n);
typedef fmi3Status fmi3GetCountTYPE(fmi3Instance, size_t* n);
typedef fmi3Status fmi3GetOutputDerivativesTYPE(fmi3Instance,
                                                const fmi3ValueReference valueReferences[],
                                                size_t nValueReferences, const fmi3Int32 orders[],
                                                fmi3Float64 values[], size_t nValues);
typedef fmi3Status fmi3DoStepTYPE(fmi3Instance, fmi3Float64 currentCommunicationPoint,
                                  fmi3Float64 communicationStepSize,
                                  fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                  fmi3Boolean* eventHandlingNeeded,
                                  fmi3Boolean* terminateSimulation, fmi3Boolean* earlyReturn,
                                  fmi3Float64* lastSuccessfulTime);
typedef fmi3Status fmi3ActivateModelPartitionTYPE(fmi3Instance, fmi3ValueReference clockReference,
                                                  fmi3Float64 activationTime);

/* All functions an FMU exports, whatever its interface types (X(name, function type)). */
#define FMU3_FUNCTIONS(X)                                                         \
  X(fmi3GetVersion, fmi3GetVersionTYPE)                                           \
  X(fmi3SetDebugLogging, fmi3SetDebugLoggingTYPE)                                 \
  X(fmi3InstantiateModelExchange, fmi3InstantiateModelExchangeTYPE)               \
  X(fmi3InstantiateCoSimulation, fmi3InstantiateCoSimulationTYPE)                 \
  X(fmi3InstantiateScheduledExecution, fmi3InstantiateScheduledExecutionTYPE)     \
  X(fmi3FreeInstance, fmi3FreeInstanceTYPE)                                       \
  X(fmi3EnterInitializationMode, fmi3EnterInitializationModeTYPE)                 \
  X(fmi3ExitInitializationMode, fmi3InstanceOnlyTYPE)                             \
  X(fmi3EnterEventMode, fmi3InstanceOnlyTYPE)                                     \
  X(fmi3Terminate, fmi3InstanceOnlyTYPE)                                          \
  X(fmi3Reset, fmi3InstanceOnlyTYPE)                                              \
  X(fmi3GetFloat32, fmi3GetFloat32TYPE)                                           \
  X(fmi3GetFloat64, fmi3GetFloat64TYPE)                                           \
  X(fmi3GetInt8, fmi3GetInt8TYPE)                                                 \
  X(fmi3GetUInt8, fmi3GetUInt8TYPE)                                               \
  X(fmi3GetInt16, fmi3GetInt16TYPE)                                               \
  X(fmi3GetUInt16, fmi3GetUInt16TYPE)                                             \
  X(fmi3GetInt32, fmi3GetInt32TYPE)                                               \
  X(fmi3GetUInt32, fmi3GetUInt32TYPE)                                             \
  X(fmi3GetInt64, fmi3GetInt64TYPE)                                               \
  X(fmi3GetUInt64, fmi3GetUInt64TYPE)                                             \
  X(fmi3GetBoolean, fmi3GetBooleanTYPE)                                           \
  X(fmi3GetString, fmi3GetStringTYPE)                                             \
  X(fmi3GetBinary, fmi3GetBinaryTYPE)                                             \
  X(fmi3GetClock, fmi3GetClockTYPE)                                               \
  X(fmi3SetFloat32, fmi3SetFloat32TYPE)                                           \
  X(fmi3SetFloat64, fmi3SetFloat64TYPE)                                           \
  X(fmi3SetInt8, fmi3SetInt8TYPE)                                                 \
  X(fmi3SetUInt8, fmi3SetUInt8TYPE)                                               \
  X(fmi3SetInt16, fmi3SetInt16TYPE)                                               \
  X(fmi3SetUInt16, fmi3SetUInt16TYPE)                                             \
  X(fmi3SetInt32, fmi3SetInt32TYPE)                                               \
  X(fmi3SetUInt32, fmi3SetUInt32TYPE)                                             \
  X(fmi3SetInt64, fmi3SetInt64TYPE)                                               \
  X(fmi3SetUInt64, fmi3SetUInt64TYPE)                                             \
  X(fmi3SetBoolean, fmi3SetBooleanTYPE)                                           \
  X(fmi3SetString, fmi3SetStringTYPE)                                             \
  X(fmi3SetBinary, fmi3SetBinaryTYPE)                                             \
  X(fmi3SetClock, fmi3SetClockTYPE)                                               \
  X(fmi3GetNumberOfVariableDependencies, fmi3GetNumberOfVariableDependenciesTYPE) \
  X(fmi3GetVariableDependencies, fmi3GetVariableDependenciesTYPE)                 \
  X(fmi3GetFMUState, fmi3GetFMUStateTYPE)                                         \
  X(fmi3SetFMUState, fmi3SetFMUStateTYPE)                                         \
  X(fmi3FreeFMUState, fmi3FreeFMUStateTYPE)                                       \
  X(fmi3SerializedFMUStateSize, fmi3SerializedFMUStateSizeTYPE)                   \
  X(fmi3SerializeFMUState, fmi3SerializeFMUStateTYPE)                             \
  X(fmi3DeserializeFMUState, fmi3DeserializeFMUStateTYPE)                         \
  X(fmi3GetDirectionalDerivative, fmi3GetDerivativeTYPE)                          \
  X(fmi3GetAdjointDerivative, fmi3GetDerivativeTYPE)                              \
  X(fmi3EnterConfigurationMode, fmi3InstanceOnlyTYPE)                             \
  X(fmi3ExitConfigurationMode, fmi3InstanceOnlyTYPE)                              \
  X(fmi3GetIntervalDecimal, fmi3GetIntervalDecimalTYPE)                           \
  X(fmi3GetIntervalFraction, fmi3GetIntervalFractionTYPE)                         \
  X(fmi3GetShiftDecimal, fmi3GetShiftDecimalTYPE)                                 \
  X(fmi3GetShiftFraction, fmi3GetShiftFractionTYPE)                               \
  X(fmi3SetIntervalDecimal, fmi3SetIntervalDecimalTYPE)                           \
  X(fmi3SetIntervalFraction, fmi3SetIntervalFractionTYPE)                         \
  X(fmi3SetShiftDecimal, fmi3SetShiftDecimalTYPE)                                 \
  X(fmi3SetShiftFraction, fmi3SetShiftFractionTYPE)                               \
  X(fmi3EvaluateDiscreteStates, fmi3InstanceOnlyTYPE)                             \
  X(fmi3UpdateDiscreteStates, fmi3UpdateDiscreteStatesTYPE)                       \
  X(fmi3EnterContinuousTimeMode, fmi3InstanceOnlyTYPE)                            \
  X(fmi3CompletedIntegratorStep, fmi3CompletedIntegratorStepTYPE)                 \
  X(fmi3SetTime, fmi3SetTimeTYPE)                                                 \
  X(fmi3SetContinuousStates, fmi3SetFloat64ArrayTYPE)                             \
  X(fmi3GetContinuousStateDerivatives, fmi3GetFloat64ArrayTYPE)                   \
  X(fmi3GetEventIndicators, fmi3GetFloat64ArrayTYPE)                              \
  X(fmi3GetContinuousStates, fmi3GetFloat64ArrayTYPE)                             \
  X(fmi3GetNominalsOfContinuousStates, fmi3GetFloat64ArrayTYPE)                   \
  X(fmi3GetNumberOfEventIndicators, fmi3GetCountTYPE)                             \
  X(fmi3GetNumberOfContinuousStates, fmi3GetCountTYPE)                            \
  X(fmi3EnterStepMode, fmi3InstanceOnlyTYPE)                                      \
  X(fmi3GetOutputDerivatives, fmi3GetOutputDerivativesTYPE)                       \
  X(fmi3DoStep, fmi3DoStepTYPE)                                                   \
  X(fmi3ActivateModelPartition, fmi3ActivateModelPartitionTYPE)

#define FMU3_FUNCTION_COUNT 75

#define FMU3_FUNCTION_POINTER(name, type) type* name;
typedef struct {
  FMU3_FUNCTIONS(FMU3_FUNCTION_POINTER)
} fmu3_functions;
#undef FMU3_FUNCTION_POINTER

/* ---- the importer's own types, shared by its files */

typedef enum {
  t_float32,
  t_float64,
  t_int8,
  t_uint8,
  t_int16,
  t_uint16,
  t_int32,
  t_uint32,
  t_int64,
  t_uint64,
  t_boolean,
  t_string,
  t_binary,
  t_enumeration, /* read and written as Int64 */
  t_clock,
  t_type_count
} fmu3_type;

typedef enum {
  c_local,
  c_parameter,
  c_calculated_parameter,
  c_input,
  c_output,
  c_independent,
  c_structural_parameter
} fmu3_causality;

typedef enum { v_constant, v_fixed, v_tunable, v_discrete, v_continuous } fmu3_variability;

typedef struct {
  char* name;
  fmu3_type type;
  fmi3ValueReference vr;
  fmu3_causality causality;
  fmu3_variability variability;
  int is_array;
  size_t size;        /* number of elements, 1 for a scalar */
  char* start;        /* the start attribute as written, or NULL */
  char** start_texts; /* String/Binary: the <Start value=...> children */
  size_t start_text_count;
} fmu3_variable;

typedef struct {
  char* token;
  char* model_identifier;
  double start_time;
  double step_size;
  int only_once_per_process;
  int can_get_and_set_fmu_state;
  int can_serialize_fmu_state;
  int provides_directional_derivatives;
  int provides_adjoint_derivatives;
  int has_event_mode;
  int provides_per_element_dependencies;
  int max_output_derivative_order;
  int has_model_exchange;
  fmu3_variable* variables;
  size_t variable_count;
} fmu3_model;

typedef struct {
  fmu3_functions api;
  fmu3_model model;
  const char* resource_path; /* native, with a trailing '/' */
  int steps;
} fmu3_setup;

/* bytes: one step's output values, raw (strings and binaries by content) */
typedef struct {
  unsigned char* data;
  size_t size;
  size_t capacity;
} fmu3_bytes;

/* fmu3_importer.c */
extern int fmu3_log_count; /* messages above fmi3OK received through logMessage */
const char* fmu3_status_name(fmi3Status status);
int fmu3_check(fmi3Status status, const char* call, const char* instance);
fmi3Instance fmu3_instantiate(const fmu3_setup* s, const char* instance);
int fmu3_initialize(const fmu3_setup* s, fmi3Instance c, const char* instance);
int fmu3_step(const fmu3_setup* s, fmi3Instance c, const char* instance, int step,
              fmu3_bytes* outputs);
int fmu3_finish(const fmu3_setup* s, fmi3Instance c, const char* instance);
double fmu3_time_at(const fmu3_setup* s, int step);
void fmu3_log_message(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                      fmi3String message);

/* fmu3_model.c */
int fmu3_read_model(const char* dir, fmu3_model* model);
void fmu3_free_model(fmu3_model* model);
const char* fmu3_type_name(fmu3_type type);

/* fmu3_values.c */
/* Sets the variable to its start value (nValues = its size). */
fmi3Status fmu3_set_start(const fmu3_functions* api, fmi3Instance c, const fmu3_variable* v);
/* Gets the variable's values and appends them to `out`; NaN in a float is an error. */
int fmu3_append_values(const fmu3_functions* api, fmi3Instance c, const char* instance,
                       const fmu3_variable* v, double time, fmu3_bytes* out);
int fmu3_bytes_append(fmu3_bytes* bytes, const void* data, size_t size);

/* fmu3_misuse.c */
int fmu3_check_misuse(const fmu3_setup* s);

#endif
