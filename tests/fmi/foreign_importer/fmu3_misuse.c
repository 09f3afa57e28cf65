/* fmu3_misuse: fmu3_importer --misuse. FMI 3.0 requires fmi3Error for every call the state
 * machine does not allow and for every illegal argument (docs/fmi3-rules.md §1, §2, §4). Each case
 * gets a fresh instance, brought into the state the case names; the call must return fmi3Error
 * and log why through logMessage, and since only fmi3Reset or fmi3FreeInstance may follow an
 * fmi3Error, the instance is then reset and must initialize and step again. Instantiation cases
 * must return NULL with a message. The count of cases is printed at the end. */
#define _XOPEN_SOURCE 700

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmu3_misuse.h"
#include "fmu_archive.h"

static const char* state_name(int state) {
  switch (state) {
    case at_instantiated:
      return "Instantiated";
    case at_initialization:
      return "Initialization Mode";
    case at_step:
      return "Step Mode";
    case at_stop_time:
      return "Step Mode at the declared stopTime";
    default:
      return "Terminated";
  }
}

static int applies(const context* x, int needs) {
  const fmu3_model* m = &x->s->model;
  return !(((needs & n_output) && x->output == NULL) || ((needs & n_input) && x->input == NULL) ||
           ((needs & n_array) && x->array == NULL) ||
           ((needs & n_array_input) && x->array_in == NULL) ||
           ((needs & n_fixed) && x->fixed == NULL) ||
           ((needs & n_settable) && x->settable == NULL) || ((needs & n_time) && x->time == NULL) ||
           ((needs & n_state) && !m->can_get_and_set_fmu_state) ||
           ((needs & n_no_state) && m->can_get_and_set_fmu_state) ||
           ((needs & n_no_events) && m->has_event_mode) ||
           ((needs & n_no_dependencies) && m->provides_per_element_dependencies) ||
           ((needs & n_no_directional) && m->provides_directional_derivatives) ||
           ((needs & n_no_adjoint) && m->provides_adjoint_derivatives) ||
           ((needs & n_no_output_derivatives) && m->max_output_derivative_order > 0) ||
           ((needs & n_scalar_output) && (x->output == NULL || x->output->is_array)));
}

static int reach(const fmu3_setup* s, fmi3Instance c, int state) {
  const char* instance = "misuse";
  fmu3_bytes outputs = {NULL, 0, 0};
  int result = 0;
  if (state == at_instantiated) return 0;
  if (state == at_initialization) {
    return fmu3_check(s->api.fmi3EnterInitializationMode(c, 0, 0.0, s->model.start_time, 0, 0.0),
                      "fmi3EnterInitializationMode", instance);
  }
  if (state == at_stop_time) {
    double stop = fmu3_time_at(s, 1);
    result =
        fmu3_check(s->api.fmi3EnterInitializationMode(c, 0, 0.0, s->model.start_time, 1, stop),
                   "fmi3EnterInitializationMode", instance) ||
        fmu3_check(s->api.fmi3ExitInitializationMode(c), "fmi3ExitInitializationMode", instance) ||
        fmu3_step(s, c, instance, 0, &outputs);
    free(outputs.data);
    return result;
  }
  /* one step, so "at t = start" is no longer the only time the FMU has seen */
  result = fmu3_initialize(s, c, instance) || fmu3_step(s, c, instance, 0, &outputs);
  free(outputs.data);
  if (result == 0 && state == at_terminated) {
    result = fmu3_check(s->api.fmi3Terminate(c), "fmi3Terminate", instance);
  }
  return result;
}

/* One case: fresh instance, the state, the call (fmi3Error + a message), reset, a legal step. */
static int run_case(context* x, const misuse_case* m, int state) {
  const fmu3_setup* s = x->s;
  fmu3_bytes outputs = {NULL, 0, 0};
  int logs_before;
  int result;
  fmi3Status status;
  fmi3Instance c = fmu3_instantiate(s, "misuse");
  if (c == NULL) return 1;
  if (reach(s, c, state) != 0) {
    s->api.fmi3FreeInstance(c);
    return fail("misuse: could not reach %s for \"%s\"", state_name(state), m->what);
  }
  memset(x->buffer, 0, sizeof x->buffer);
  memset(x->flags, 0, sizeof x->flags);
  x->state = NULL;
  logs_before = fmu3_log_count;
  status = m->call(x, c);
  if (status != fmi3Error || (fmu3_log_count == logs_before && (m->needs & n_no_instance) == 0)) {
    fail("MISUSE CASE FAILED: %s in %s returned %s%s, expected fmi3Error with a log message",
         m->what, state_name(state), fmu3_status_name(status),
         fmu3_log_count == logs_before ? " without a log message" : "");
    if (x->state != NULL) s->api.fmi3FreeFMUState(c, &x->state);
    s->api.fmi3FreeInstance(c);
    return 1;
  }
  result = fmu3_check(s->api.fmi3Reset(c), "fmi3Reset", "misuse");
  /* a state taken by the probe is the importer's to free, in any state */
  if (x->state != NULL) {
    result =
        fmu3_check(s->api.fmi3FreeFMUState(c, &x->state), "fmi3FreeFMUState", "misuse") || result;
  }
  result = result || fmu3_initialize(s, c, "misuse") || fmu3_step(s, c, "misuse", 0, &outputs);
  free(outputs.data);
  if (result != 0) {
    s->api.fmi3FreeInstance(c);
    return fail("after %s in %s the instance did not run again after fmi3Reset", m->what,
                state_name(state));
  }
  return fmu3_finish(s, c, "misuse");
}

/* Instantiations the FMU must refuse: NULL and a message. */
static int check_instantiations(const fmu3_setup* s, int* cases) {
  static const char* const whats[] = {
      "fmi3InstantiateCoSimulation with a wrong instantiationToken",
      "fmi3InstantiateCoSimulation with a NULL instantiationToken",
      "fmi3InstantiateCoSimulation with eventModeUsed = true (no hasEventMode)",
      "fmi3InstantiateModelExchange (no <ModelExchange>)",
      "fmi3InstantiateScheduledExecution (no <ScheduledExecution>)"};
  const fmu3_functions* f = &s->api;
  const char* path = s->resource_path;
  int failures = 0;
  int k;
  for (k = 0; k < 5; ++k) {
    int logs_before = fmu3_log_count;
    fmi3Instance c = NULL;
    if ((k == 2 && s->model.has_event_mode) || (k == 3 && s->model.has_model_exchange)) continue;
    switch (k) {
      case 0:
        c = f->fmi3InstantiateCoSimulation("misuse", "{wrong}", path, 0, 1, 0, 0, NULL, 0, NULL,
                                           fmu3_log_message, NULL);
        break;
      case 1:
        c = f->fmi3InstantiateCoSimulation("misuse", NULL, path, 0, 1, 0, 0, NULL, 0, NULL,
                                           fmu3_log_message, NULL);
        break;
      case 2:
        c = f->fmi3InstantiateCoSimulation("misuse", s->model.token, path, 0, 1, 1, 0, NULL, 0,
                                           NULL, fmu3_log_message, NULL);
        break;
      case 3:
        c = f->fmi3InstantiateModelExchange("misuse", s->model.token, path, 0, 1, NULL,
                                            fmu3_log_message);
        break;
      default:
        c = f->fmi3InstantiateScheduledExecution("misuse", s->model.token, path, 0, 1, NULL,
                                                 fmu3_log_message, NULL, NULL, NULL);
        break;
    }
    ++*cases;
    if (c != NULL || fmu3_log_count == logs_before) {
      fail("MISUSE CASE FAILED: %s returned %s%s, expected NULL with a log message", whats[k],
           c != NULL ? "an instance" : "NULL",
           fmu3_log_count == logs_before ? " and no message" : "");
      if (c != NULL) f->fmi3FreeInstance(c);
      ++failures;
    }
  }
  return failures;
}

int fmu3_check_misuse(const fmu3_setup* s) {
  static const int states[] = {at_instantiated, at_initialization, at_step, at_terminated,
                               at_stop_time};
  context x;
  size_t i;
  size_t k;
  int cases = 0;
  int failures = 0;
  memset(&x, 0, sizeof x);
  x.s = s;
  for (i = 0; i < s->model.variable_count; ++i) {
    const fmu3_variable* v = &s->model.variables[i];
    int small = v->size <= 32; /* the probes' buffer holds 64 doubles, 2 x 32 */
    /* a scalar when there is one, so the scalar-only cases apply too */
    if (v->causality == c_output && v->type == t_float64 && small &&
        (x.output == NULL || (x.output->is_array && !v->is_array))) {
      x.output = v;
    }
    if (v->causality == c_input && v->type == t_float64 && small &&
        (x.input == NULL || (x.input->is_array && !v->is_array))) {
      x.input = v;
    }
    if ((v->causality == c_output || v->causality == c_input) && v->is_array && x.array == NULL &&
        small && v->type != t_binary && v->type != t_clock) {
      x.array = v;
    }
    if (v->causality == c_input && v->type == t_float64 && v->is_array && small &&
        x.array_in == NULL) {
      x.array_in = v;
    }
    if (v->causality == c_parameter && v->variability == v_fixed && x.fixed == NULL) x.fixed = v;
    if (v->causality == c_independent) x.time = v;
  }
  x.settable = x.input != NULL ? x.input : x.fixed;
  failures = check_instantiations(s, &cases);
  for (i = 0; i < fmu3_misuse_case_count; ++i) {
    const misuse_case* m = &fmu3_misuse_cases[i];
    if (!applies(&x, m->needs)) {
      printf("fmu3_importer: not applicable to this FMU: %s\n", m->what);
      continue;
    }
    for (k = 0; k < sizeof states / sizeof states[0]; ++k) {
      if ((m->states & states[k]) == 0) continue;
      ++cases;
      failures += run_case(&x, m, states[k]);
    }
  }
  printf("fmu3_importer: misuse: %d cases, %d passed, %d failed\n", cases, cases - failures,
         failures);
  return failures > 0;
}
