/* fmu3_misuse_cases: the cases of fmu3_importer --misuse. Each probe makes one call that FMI 3.0
 * requires to fail with fmi3Error: out of state, of a feature the FMU does not declare, or with
 * an illegal argument; the table says in which states it is made and what the FMU must have for
 * it to apply. */
#define _XOPEN_SOURCE 700

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fmu3_misuse.h"
#include "fmu_archive.h"

#define F (&x->s->api)
#define T0 (x->s->model.start_time)
#define H (x->s->model.step_size)
#define PROBE(name, ...)                                       \
  static fmi3Status probe_##name(context* x, fmi3Instance c) { \
    (void)c;                                                   \
    __VA_ARGS__                                                \
  }
#define B x->buffer
#define FL x->flags

/* ---- calls that only the state makes wrong (no values, so nothing else can be) */
PROBE(enter_initialization, { return F->fmi3EnterInitializationMode(c, 0, 0.0, T0, 0, 0.0); })
PROBE(exit_initialization, { return F->fmi3ExitInitializationMode(c); })
PROBE(terminate, { return F->fmi3Terminate(c); })
PROBE(do_step, { return F->fmi3DoStep(c, T0, H, 0, &FL[0], &FL[1], &FL[2], &B[0]); })
PROBE(get_float64, { return F->fmi3GetFloat64(c, NULL, 0, B, 0); })
PROBE(get_int32, { return F->fmi3GetInt32(c, NULL, 0, (fmi3Int32*)B, 0); })
PROBE(get_boolean, { return F->fmi3GetBoolean(c, NULL, 0, FL, 0); })
PROBE(get_string, { return F->fmi3GetString(c, NULL, 0, (fmi3String*)B, 0); })
PROBE(set_float64, { return F->fmi3SetFloat64(c, NULL, 0, B, 0); })
PROBE(set_int32, { return F->fmi3SetInt32(c, NULL, 0, (const fmi3Int32*)B, 0); })
PROBE(set_boolean, { return F->fmi3SetBoolean(c, NULL, 0, FL, 0); })
PROBE(set_string, { return F->fmi3SetString(c, NULL, 0, (const fmi3String*)B, 0); })

/* ---- functions of features the FMU does not have */
PROBE(enter_event_mode, { return F->fmi3EnterEventMode(c); })
PROBE(enter_step_mode, { return F->fmi3EnterStepMode(c); })
PROBE(update_discrete_states,
      { return F->fmi3UpdateDiscreteStates(c, &FL[0], &FL[1], &FL[2], &FL[3], &FL[0], B); })
PROBE(evaluate_discrete_states, { return F->fmi3EvaluateDiscreteStates(c); })
PROBE(get_clock, { return F->fmi3GetClock(c, &x->output->vr, 1, FL); })
PROBE(set_clock, { return F->fmi3SetClock(c, &x->output->vr, 1, FL); })
PROBE(get_interval_decimal, {
  fmi3IntervalQualifier q[1];
  return F->fmi3GetIntervalDecimal(c, &x->output->vr, 1, B, q);
})
PROBE(get_interval_fraction, {
  fmi3IntervalQualifier q[1];
  return F->fmi3GetIntervalFraction(c, &x->output->vr, 1, (fmi3UInt64*)B, (fmi3UInt64*)B + 1, q);
})
PROBE(get_shift_decimal, { return F->fmi3GetShiftDecimal(c, &x->output->vr, 1, B); })
PROBE(get_shift_fraction,
      { return F->fmi3GetShiftFraction(c, &x->output->vr, 1, (fmi3UInt64*)B, (fmi3UInt64*)B + 1); })
PROBE(set_interval_decimal, { return F->fmi3SetIntervalDecimal(c, &x->output->vr, 1, B); })
PROBE(set_interval_fraction, {
  B[0] = 1.0;
  return F->fmi3SetIntervalFraction(c, &x->output->vr, 1, (fmi3UInt64*)B, (fmi3UInt64*)B);
})
PROBE(set_shift_decimal, { return F->fmi3SetShiftDecimal(c, &x->output->vr, 1, B); })
PROBE(set_shift_fraction, {
  B[0] = 1.0;
  return F->fmi3SetShiftFraction(c, &x->output->vr, 1, (fmi3UInt64*)B, (fmi3UInt64*)B);
})
PROBE(enter_configuration_mode, { return F->fmi3EnterConfigurationMode(c); })
PROBE(exit_configuration_mode, { return F->fmi3ExitConfigurationMode(c); })
PROBE(get_number_of_dependencies,
      { return F->fmi3GetNumberOfVariableDependencies(c, x->output->vr, &x->count); })
PROBE(get_dependencies, {
  size_t index[1];
  fmi3ValueReference independent[1];
  fmi3DependencyKind kind[1];
  return F->fmi3GetVariableDependencies(c, x->output->vr, index, independent, index, kind, 1);
})
PROBE(get_directional_derivative, {
  const fmi3ValueReference* out = &x->output->vr;
  B[0] = 1.0;
  return F->fmi3GetDirectionalDerivative(c, out, 1, out, 1, B, 1, B + 1, 1);
})
PROBE(get_adjoint_derivative, {
  const fmi3ValueReference* out = &x->output->vr;
  B[0] = 1.0;
  return F->fmi3GetAdjointDerivative(c, out, 1, out, 1, B, 1, B + 1, 1);
})
PROBE(get_output_derivatives, {
  fmi3Int32 order = 1;
  return F->fmi3GetOutputDerivatives(c, &x->output->vr, 1, &order, B, 1);
})
PROBE(get_fmu_state, { return F->fmi3GetFMUState(c, &x->state); })
PROBE(enter_continuous_time_mode, { return F->fmi3EnterContinuousTimeMode(c); })
PROBE(completed_integrator_step, { return F->fmi3CompletedIntegratorStep(c, 0, &FL[0], &FL[1]); })
PROBE(set_time, { return F->fmi3SetTime(c, T0); })
PROBE(set_continuous_states, { return F->fmi3SetContinuousStates(c, B, 1); })
PROBE(get_continuous_state_derivatives, { return F->fmi3GetContinuousStateDerivatives(c, B, 1); })
PROBE(get_event_indicators, { return F->fmi3GetEventIndicators(c, B, 1); })
PROBE(get_continuous_states, { return F->fmi3GetContinuousStates(c, B, 1); })
PROBE(get_nominals, { return F->fmi3GetNominalsOfContinuousStates(c, B, 1); })
PROBE(get_number_of_event_indicators, { return F->fmi3GetNumberOfEventIndicators(c, &x->count); })
PROBE(get_number_of_states, { return F->fmi3GetNumberOfContinuousStates(c, &x->count); })
PROBE(activate_model_partition, { return F->fmi3ActivateModelPartition(c, x->output->vr, T0); })

/* ---- bad arguments */
PROBE(null_instance_do_step,
      { return F->fmi3DoStep(NULL, T0, H, 0, &FL[0], &FL[1], &FL[2], &B[0]); })
PROBE(null_instance_get, { return F->fmi3GetFloat64(NULL, &x->output->vr, 1, B, 1); })
PROBE(null_instance_terminate, { return F->fmi3Terminate(NULL); })
PROBE(null_value_references, { return F->fmi3GetFloat64(c, NULL, 1, B, x->output->size); })
PROBE(get_null_values, { return F->fmi3GetFloat64(c, &x->output->vr, 1, NULL, x->output->size); })
PROBE(set_null_values, { return F->fmi3SetFloat64(c, &x->input->vr, 1, NULL, x->input->size); })
PROBE(do_step_null_event, { return F->fmi3DoStep(c, T0, H, 0, NULL, &FL[1], &FL[2], &B[0]); })
PROBE(do_step_null_terminate, { return F->fmi3DoStep(c, T0, H, 0, &FL[0], NULL, &FL[2], &B[0]); })
PROBE(do_step_null_early, { return F->fmi3DoStep(c, T0, H, 0, &FL[0], &FL[1], NULL, &B[0]); })
PROBE(do_step_null_time, { return F->fmi3DoStep(c, T0, H, 0, &FL[0], &FL[1], &FL[2], NULL); })
PROBE(get_fmu_state_null, { return F->fmi3GetFMUState(c, NULL); })
PROBE(set_fmu_state_null, { return F->fmi3SetFMUState(c, NULL); })
PROBE(set_fmu_state_foreign, { return F->fmi3SetFMUState(c, (fmi3FMUState)B); })
PROBE(state_size_null, { return F->fmi3SerializedFMUStateSize(c, NULL, &x->count); })
PROBE(deserialize_null, {
  memset(B, 0, 16);
  return F->fmi3DeserializeFMUState(c, (const fmi3Byte*)B, 16, NULL);
})
PROBE(deserialize_garbage, {
  memset(B, 0x5a, 16);
  x->state = NULL;
  return F->fmi3DeserializeFMUState(c, (const fmi3Byte*)B, 7, &x->state);
})
/* nValues must be the sum of the sizes of the variables: one more, one less */
static fmi3Status get_array(context* x, fmi3Instance c, size_t n) {
  const fmu3_variable* v = x->array;
  if (v->type == t_float64) return F->fmi3GetFloat64(c, &v->vr, 1, B, n);
  if (v->type == t_int32) return F->fmi3GetInt32(c, &v->vr, 1, (fmi3Int32*)B, n);
  if (v->type == t_boolean) return F->fmi3GetBoolean(c, &v->vr, 1, (fmi3Boolean*)B, n);
  return F->fmi3GetString(c, &v->vr, 1, (fmi3String*)B, n);
}
PROBE(array_n_plus_one, { return get_array(x, c, x->array->size + 1); })
PROBE(array_n_minus_one, { return get_array(x, c, x->array->size - 1); })
PROBE(array_n_zero, { return get_array(x, c, 0); })
PROBE(scalar_n_two, { return F->fmi3GetFloat64(c, &x->output->vr, 1, B, 2); })
PROBE(set_input_n_plus_one,
      { return F->fmi3SetFloat64(c, &x->input->vr, 1, B, x->input->size + 1); })
PROBE(set_array_n_minus_one,
      { return F->fmi3SetFloat64(c, &x->array_in->vr, 1, B, x->array_in->size - 1); })
PROBE(set_array_n_plus_one,
      { return F->fmi3SetFloat64(c, &x->array_in->vr, 1, B, x->array_in->size + 1); })
PROBE(get_unknown_reference, {
  fmi3ValueReference unknown = 0x7fffffffu;
  return F->fmi3GetFloat64(c, &unknown, 1, B, 1);
})
PROBE(set_unknown_reference, {
  fmi3ValueReference unknown = 0x7fffffffu;
  return F->fmi3SetFloat64(c, &unknown, 1, B, 1);
})
PROBE(get_int32_of_float64, { return F->fmi3GetInt32(c, &x->output->vr, 1, (fmi3Int32*)B, 1); })
PROBE(get_boolean_of_float64, { return F->fmi3GetBoolean(c, &x->output->vr, 1, FL, 1); })
PROBE(get_string_of_float64, { return F->fmi3GetString(c, &x->output->vr, 1, (fmi3String*)B, 1); })
PROBE(set_output, { return F->fmi3SetFloat64(c, &x->output->vr, 1, B, x->output->size); })
PROBE(set_independent, {
  B[0] = T0;
  return F->fmi3SetFloat64(c, &x->time->vr, 1, B, 1);
})
static fmi3Status set_settable(context* x, fmi3Instance c, const fmu3_variable* v) {
  /* its own start value, so only the state or the variability can make it wrong */
  fmi3Status status = fmu3_set_start(F, c, v);
  return status == fmi3Fatal ? fmi3OK : status; /* unreadable start: reported, fail the case */
}
PROBE(set_fixed_in_step_mode, { return set_settable(x, c, x->fixed); })
PROBE(set_after_terminate, { return set_settable(x, c, x->settable); })
static fmi3Status set_input_value(context* x, fmi3Instance c, double value) {
  size_t i;
  for (i = 0; i < x->input->size && i < 64; ++i) B[i] = value;
  return F->fmi3SetFloat64(c, &x->input->vr, 1, B, x->input->size);
}
PROBE(set_nan, { return set_input_value(x, c, NAN); })
PROBE(set_plus_infinity, { return set_input_value(x, c, INFINITY); })
PROBE(set_minus_infinity, { return set_input_value(x, c, -INFINITY); })
PROBE(do_step_zero, { return F->fmi3DoStep(c, T0, 0.0, 0, &FL[0], &FL[1], &FL[2], &B[0]); })
PROBE(do_step_negative, { return F->fmi3DoStep(c, T0, -H, 0, &FL[0], &FL[1], &FL[2], &B[0]); })
PROBE(do_step_nan, { return F->fmi3DoStep(c, T0, NAN, 0, &FL[0], &FL[1], &FL[2], &B[0]); })
PROBE(do_step_nan_time, { return F->fmi3DoStep(c, NAN, H, 0, &FL[0], &FL[1], &FL[2], &B[0]); })

PROBE(do_step_past_stop_time,
      { return F->fmi3DoStep(c, T0 + H, H, 0, &FL[0], &FL[1], &FL[2], &B[0]); })
PROBE(enter_initialization_stop_before_start,
      { return F->fmi3EnterInitializationMode(c, 0, 0.0, T0, 1, T0 - H); })
PROBE(enter_initialization_nan_start,
      { return F->fmi3EnterInitializationMode(c, 0, 0.0, NAN, 0, 0.0); })
PROBE(debug_logging_unknown_category, {
  fmi3String category = "noSuchLogCategory";
  return F->fmi3SetDebugLogging(c, fmi3True, 1, &category);
})
PROBE(debug_logging_null_categories, { return F->fmi3SetDebugLogging(c, fmi3True, 1, NULL); })
PROBE(free_fmu_state_null, { return F->fmi3FreeFMUState(c, NULL); })
PROBE(serialize_too_small, {
  size_t size = 0;
  fmi3Byte* bytes;
  fmi3Status status = F->fmi3GetFMUState(c, &x->state);
  if (status != fmi3OK || F->fmi3SerializedFMUStateSize(c, x->state, &size) != fmi3OK || size < 2 ||
      (bytes = malloc(size - 1)) == NULL) {
    fail("misuse: could not get an FMU state and its size to serialize");
    return fmi3OK; /* not the call under test: fails the case */
  }
  status = F->fmi3SerializeFMUState(c, x->state, bytes, size - 1);
  free(bytes);
  return status;
})

#define NOT_IN(allowed) \
  ((at_instantiated | at_initialization | at_step | at_terminated) & ~(allowed))
#define GET_STATES (at_initialization | at_step | at_terminated)
#define SET_STATES (at_instantiated | at_initialization | at_step)

const misuse_case fmu3_misuse_cases[] = {
    /* out of state (the FMI 3.0 Co-Simulation state machine) */
    {"fmi3EnterInitializationMode", probe_enter_initialization, NOT_IN(at_instantiated), 0},
    {"fmi3ExitInitializationMode", probe_exit_initialization, NOT_IN(at_initialization), 0},
    {"fmi3Terminate", probe_terminate, NOT_IN(at_step), 0},
    {"fmi3DoStep", probe_do_step, NOT_IN(at_step), 0},
    {"fmi3GetFloat64 (no values)", probe_get_float64, NOT_IN(GET_STATES), 0},
    {"fmi3GetInt32 (no values)", probe_get_int32, NOT_IN(GET_STATES), 0},
    {"fmi3GetBoolean (no values)", probe_get_boolean, NOT_IN(GET_STATES), 0},
    {"fmi3GetString (no values)", probe_get_string, NOT_IN(GET_STATES), 0},
    {"fmi3SetFloat64 (no values)", probe_set_float64, NOT_IN(SET_STATES), 0},
    {"fmi3SetInt32 (no values)", probe_set_int32, NOT_IN(SET_STATES), 0},
    {"fmi3SetBoolean (no values)", probe_set_boolean, NOT_IN(SET_STATES), 0},
    {"fmi3SetString (no values)", probe_set_string, NOT_IN(SET_STATES), 0},
    {"fmi3Set of an input or fixed parameter after fmi3Terminate", probe_set_after_terminate,
     at_terminated, n_settable},
    /* features the FMU does not declare, called where they would otherwise be allowed */
    {"fmi3EnterEventMode without event mode", probe_enter_event_mode, at_step, n_no_events},
    {"fmi3EnterStepMode without event mode", probe_enter_step_mode, at_step, n_no_events},
    {"fmi3UpdateDiscreteStates without event mode", probe_update_discrete_states, at_step,
     n_no_events},
    {"fmi3EvaluateDiscreteStates without event mode", probe_evaluate_discrete_states, at_step,
     n_no_events},
    {"fmi3GetClock of a Float64", probe_get_clock, at_step, n_output},
    {"fmi3SetClock of a Float64", probe_set_clock, at_step, n_output},
    {"fmi3GetIntervalDecimal of a Float64", probe_get_interval_decimal, at_step, n_output},
    {"fmi3GetIntervalFraction of a Float64", probe_get_interval_fraction, at_step, n_output},
    {"fmi3GetShiftDecimal of a Float64", probe_get_shift_decimal, at_step, n_output},
    {"fmi3GetShiftFraction of a Float64", probe_get_shift_fraction, at_step, n_output},
    {"fmi3SetIntervalDecimal of a Float64", probe_set_interval_decimal, at_step, n_output},
    {"fmi3SetIntervalFraction of a Float64", probe_set_interval_fraction, at_step, n_output},
    {"fmi3SetShiftDecimal of a Float64", probe_set_shift_decimal, at_step, n_output},
    {"fmi3SetShiftFraction of a Float64", probe_set_shift_fraction, at_step, n_output},
    {"fmi3EnterConfigurationMode without structural parameters", probe_enter_configuration_mode,
     at_instantiated | at_step, 0},
    {"fmi3ExitConfigurationMode", probe_exit_configuration_mode, at_instantiated | at_step, 0},
    {"fmi3GetNumberOfVariableDependencies", probe_get_number_of_dependencies, at_step,
     n_output | n_no_dependencies},
    {"fmi3GetVariableDependencies", probe_get_dependencies, at_step, n_output | n_no_dependencies},
    {"fmi3GetDirectionalDerivative", probe_get_directional_derivative,
     at_initialization | at_terminated, n_scalar_output | n_no_directional},
    {"fmi3GetAdjointDerivative", probe_get_adjoint_derivative, at_initialization | at_terminated,
     n_scalar_output | n_no_adjoint},
    {"fmi3GetOutputDerivatives", probe_get_output_derivatives, at_step,
     n_scalar_output | n_no_output_derivatives},
    {"fmi3GetFMUState without canGetAndSetFMUState", probe_get_fmu_state, at_step, n_no_state},
    {"fmi3EnterContinuousTimeMode (Model Exchange)", probe_enter_continuous_time_mode, at_step, 0},
    {"fmi3CompletedIntegratorStep (Model Exchange)", probe_completed_integrator_step, at_step, 0},
    {"fmi3SetTime (Model Exchange)", probe_set_time, at_step, 0},
    {"fmi3SetContinuousStates (Model Exchange)", probe_set_continuous_states, at_step, 0},
    {"fmi3GetContinuousStateDerivatives (Model Exchange)", probe_get_continuous_state_derivatives,
     at_step, 0},
    {"fmi3GetEventIndicators (Model Exchange)", probe_get_event_indicators, at_step, 0},
    {"fmi3GetContinuousStates (Model Exchange)", probe_get_continuous_states, at_step, 0},
    {"fmi3GetNominalsOfContinuousStates (Model Exchange)", probe_get_nominals, at_step, 0},
    {"fmi3GetNumberOfEventIndicators (Model Exchange)", probe_get_number_of_event_indicators,
     at_step, 0},
    {"fmi3GetNumberOfContinuousStates (Model Exchange)", probe_get_number_of_states, at_step, 0},
    {"fmi3ActivateModelPartition (Scheduled Execution)", probe_activate_model_partition, at_step,
     n_output},
    /* null pointers */
    {"fmi3DoStep of a NULL instance", probe_null_instance_do_step, at_step, n_no_instance},
    {"fmi3GetFloat64 of a NULL instance", probe_null_instance_get, at_step,
     n_output | n_no_instance},
    {"fmi3Terminate of a NULL instance", probe_null_instance_terminate, at_step, n_no_instance},
    {"fmi3GetFloat64 with NULL valueReferences", probe_null_value_references, at_step, n_output},
    {"fmi3GetFloat64 with NULL values", probe_get_null_values, at_step, n_output},
    {"fmi3SetFloat64 with NULL values", probe_set_null_values, at_step, n_input},
    {"fmi3DoStep with NULL eventHandlingNeeded", probe_do_step_null_event, at_step, 0},
    {"fmi3DoStep with NULL terminateSimulation", probe_do_step_null_terminate, at_step, 0},
    {"fmi3DoStep with NULL earlyReturn", probe_do_step_null_early, at_step, 0},
    {"fmi3DoStep with NULL lastSuccessfulTime", probe_do_step_null_time, at_step, 0},
    {"fmi3GetFMUState into NULL", probe_get_fmu_state_null, at_step, n_state},
    {"fmi3SetFMUState of NULL", probe_set_fmu_state_null, at_step, n_state},
    {"fmi3SetFMUState of a state it never made", probe_set_fmu_state_foreign, at_step, n_state},
    {"fmi3SerializedFMUStateSize of NULL", probe_state_size_null, at_step, n_state},
    {"fmi3DeserializeFMUState into NULL", probe_deserialize_null, at_step, n_state},
    {"fmi3DeserializeFMUState of 7 garbage bytes", probe_deserialize_garbage, at_step, n_state},
    /* value arrays of the wrong size */
    {"fmi3Get of an array with nValues = size + 1", probe_array_n_plus_one, at_step, n_array},
    {"fmi3Get of an array with nValues = size - 1", probe_array_n_minus_one, at_step, n_array},
    {"fmi3Get of an array with nValues = 0", probe_array_n_zero, at_step, n_array},
    {"fmi3GetFloat64 of a scalar with nValues = 2", probe_scalar_n_two, at_step, n_scalar_output},
    {"fmi3SetFloat64 of an input with nValues = size + 1", probe_set_input_n_plus_one, at_step,
     n_input},
    {"fmi3SetFloat64 of an array input with nValues = size - 1", probe_set_array_n_minus_one,
     at_step, n_array_input},
    {"fmi3SetFloat64 of an array input with nValues = size + 1", probe_set_array_n_plus_one,
     at_step, n_array_input},
    /* wrong variables */
    {"fmi3GetFloat64 of an unknown value reference", probe_get_unknown_reference, at_step, 0},
    {"fmi3SetFloat64 of an unknown value reference", probe_set_unknown_reference, at_step, 0},
    {"fmi3GetInt32 of a Float64", probe_get_int32_of_float64, at_step, n_scalar_output},
    {"fmi3GetBoolean of a Float64", probe_get_boolean_of_float64, at_step, n_scalar_output},
    {"fmi3GetString of a Float64", probe_get_string_of_float64, at_step, n_scalar_output},
    {"fmi3SetFloat64 of an output", probe_set_output, SET_STATES, n_output},
    {"fmi3SetFloat64 of the independent variable", probe_set_independent, SET_STATES, n_time},
    {"fmi3Set of a fixed parameter in Step Mode", probe_set_fixed_in_step_mode, at_step, n_fixed},
    /* values no input can take */
    {"fmi3SetFloat64 of NaN into an input", probe_set_nan, at_step, n_input},
    {"fmi3SetFloat64 of +inf into an input", probe_set_plus_infinity, at_step, n_input},
    {"fmi3SetFloat64 of -inf into an input", probe_set_minus_infinity, at_step, n_input},
    {"fmi3DoStep with h = 0", probe_do_step_zero, at_step, 0},
    {"fmi3DoStep with h < 0", probe_do_step_negative, at_step, 0},
    {"fmi3DoStep with h = NaN", probe_do_step_nan, at_step, 0},
    {"fmi3DoStep at t = NaN", probe_do_step_nan_time, at_step, 0},
    {"fmi3DoStep past the declared stopTime", probe_do_step_past_stop_time, at_stop_time, 0},
    {"fmi3EnterInitializationMode with stopTime < startTime",
     probe_enter_initialization_stop_before_start, at_instantiated, 0},
    {"fmi3EnterInitializationMode with startTime = NaN", probe_enter_initialization_nan_start,
     at_instantiated, 0},
    /* other arguments */
    {"fmi3SetDebugLogging of an unknown category", probe_debug_logging_unknown_category, at_step,
     0},
    {"fmi3SetDebugLogging with NULL categories", probe_debug_logging_null_categories, at_step, 0},
    {"fmi3FreeFMUState of a NULL pointer", probe_free_fmu_state_null, at_step, n_state},
    {"fmi3SerializeFMUState into a buffer one byte short", probe_serialize_too_small, at_step,
     n_state},
};

const size_t fmu3_misuse_case_count = sizeof fmu3_misuse_cases / sizeof fmu3_misuse_cases[0];
