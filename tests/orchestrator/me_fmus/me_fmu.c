/* The FMI 2.0 Model Exchange interface around one me_model.h model (test FMUs only); me_cs.c
 * adds the Co-Simulation functions. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "me_instance.h"

void say(const instance* s, fmi2Status status, const char* category, const char* format, ...) {
  if (!s->logging || s->cb == NULL || s->cb->logger == NULL) return;
  char text[256];
  va_list args;
  va_start(args, format);
  vsnprintf(text, sizeof text, format, args);
  va_end(args);
  s->cb->logger(s->cb->componentEnvironment, s->name, status, category, "%s", text);
}

static fmi2Status vr_ok(const fmi2ValueReference vr[], size_t n, size_t limit) {
  for (size_t k = 0; k < n; ++k) {
    if (vr[k] >= limit) return fmi2Error;
  }
  return fmi2OK;
}

const char* fmi2GetTypesPlatform(void) {
  return "default";
}
const char* fmi2GetVersion(void) {
  return "2.0";
}
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String cat[]) {
  (void)c;
  (void)on;
  (void)n;
  (void)cat;
  return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String uri,
                              const fmi2CallbackFunctions* cb, fmi2Boolean visible,
                              fmi2Boolean logging) {
  (void)uri;
  (void)visible;
  if (guid == NULL || strcmp(guid, me_guid) != 0) return NULL;
  instance* s = calloc(1, sizeof *s);
  if (s == NULL) return NULL;
  s->cb = cb;
  s->type = type;
  s->logging = logging == fmi2True;
  strncpy(s->name, name ? name : "", sizeof s->name - 1);
  s->m.next_event = -1;
  me_start(&s->m);
  say(s, fmi2OK, "logAll", "instantiated with %d continuous states", me_state_count);
  return s;
}
void fmi2FreeInstance(fmi2Component c) {
  free(c);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tol_defined, fmi2Real tol,
                               fmi2Real start, fmi2Boolean stop_defined, fmi2Real stop) {
  (void)tol_defined;
  (void)tol;
  (void)stop_defined;
  (void)stop;
  ((instance*)c)->m.time = start;
  return fmi2OK;
}
fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  (void)c;
  return fmi2OK;
}
fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  (void)c;
  return fmi2OK;
}
fmi2Status fmi2Terminate(fmi2Component c) {
  (void)c;
  return fmi2OK;
}
fmi2Status fmi2Reset(fmi2Component c) {
  instance* s = c;
  memset(&s->m, 0, sizeof s->m);
  s->m.next_event = -1;
  me_start(&s->m);
  return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[]) {
  instance* s = c;
  if (vr_ok(vr, n, ME_MAX_REALS) != fmi2OK) return fmi2Error;
  me_equations(&s->m);
  for (size_t k = 0; k < n; ++k) v[k] = s->m.r[vr[k]];
  return fmi2OK;
}
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                       const fmi2Real v[]) {
  instance* s = c;
  if (vr_ok(vr, n, ME_MAX_REALS) != fmi2OK) return fmi2Error;
  for (size_t k = 0; k < n; ++k) s->m.r[vr[k]] = v[k];
  return fmi2OK;
}
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                          fmi2Integer v[]) {
  instance* s = c;
  if (vr_ok(vr, n, ME_MAX_INTEGERS) != fmi2OK) return fmi2Error;
  for (size_t k = 0; k < n; ++k) v[k] = s->m.i[vr[k]];
  return fmi2OK;
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                          const fmi2Integer v[]) {
  instance* s = c;
  if (vr_ok(vr, n, ME_MAX_INTEGERS) != fmi2OK) return fmi2Error;
  for (size_t k = 0; k < n; ++k) s->m.i[vr[k]] = v[k];
  return fmi2OK;
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                          fmi2Boolean v[]) {
  instance* s = c;
  if (vr_ok(vr, n, ME_MAX_BOOLEANS) != fmi2OK) return fmi2Error;
  me_equations(&s->m);
  for (size_t k = 0; k < n; ++k) v[k] = s->m.b[vr[k]] ? fmi2True : fmi2False;
  return fmi2OK;
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                          const fmi2Boolean v[]) {
  instance* s = c;
  if (vr_ok(vr, n, ME_MAX_BOOLEANS) != fmi2OK) return fmi2Error;
  for (size_t k = 0; k < n; ++k) s->m.b[vr[k]] = v[k] != fmi2False;
  return fmi2OK;
}
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[]) {
  instance* s = c;
  if (vr_ok(vr, n, ME_MAX_STRINGS) != fmi2OK) return fmi2Error;
  me_equations(&s->m);
  for (size_t k = 0; k < n; ++k) v[k] = s->m.s[vr[k]];
  return fmi2OK;
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                         const fmi2String v[]) {
  instance* s = c;
  if (vr_ok(vr, n, ME_MAX_STRINGS) != fmi2OK) return fmi2Error;
  for (size_t k = 0; k < n; ++k) {
    if (v[k] == NULL || strlen(v[k]) >= ME_STRING_SIZE) return fmi2Error;
    strcpy(s->m.s[vr[k]], v[k]);
  }
  return fmi2OK;
}

/* FMU state: a copy of the model data; serialized as its bytes */
fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* state) {
  if (*state == NULL) *state = malloc(sizeof(me_data));
  if (*state == NULL) return fmi2Error;
  memcpy(*state, &((instance*)c)->m, sizeof(me_data));
  return fmi2OK;
}
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state) {
  memcpy(&((instance*)c)->m, state, sizeof(me_data));
  return fmi2OK;
}
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* state) {
  (void)c;
  free(*state);
  *state = NULL;
  return fmi2OK;
}
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t* size) {
  (void)c;
  (void)state;
  *size = sizeof(me_data);
  return fmi2OK;
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte out[], size_t size) {
  (void)c;
  if (size != sizeof(me_data)) return fmi2Error;
  memcpy(out, state, size);
  return fmi2OK;
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte in[], size_t size,
                                   fmi2FMUstate* state) {
  (void)c;
  if (size != sizeof(me_data)) return fmi2Error;
  *state = malloc(size);
  if (*state == NULL) return fmi2Error;
  memcpy(*state, in, size);
  return fmi2OK;
}
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference k[], size_t nk,
                                        const fmi2Real dk[], fmi2Real du[]) {
  (void)c;
  (void)u;
  (void)nu;
  (void)k;
  (void)nk;
  (void)dk;
  (void)du;
  return fmi2Error;
}

/* ---- Model Exchange ---- */
fmi2Status fmi2EnterEventMode(fmi2Component c) {
  (void)c;
  return fmi2OK;
}
fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo* info) {
  instance* s = c;
  const int changed = me_event(&s->m);
  info->newDiscreteStatesNeeded = s->m.r[ME_CHATTER] > 0 ? fmi2True : fmi2False;
  info->terminateSimulation = s->m.terminate ? fmi2True : fmi2False;
  info->nominalsOfContinuousStatesChanged = fmi2False;
  info->valuesOfContinuousStatesChanged = changed ? fmi2True : fmi2False;
  info->nextEventTimeDefined = s->m.next_event >= 0 ? fmi2True : fmi2False;
  info->nextEventTime = s->m.next_event;
  return fmi2OK;
}
fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {
  (void)c;
  return fmi2OK;
}
fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean no_set, fmi2Boolean* enter,
                                       fmi2Boolean* terminate) {
  (void)no_set;
  *enter = me_step_event(&((instance*)c)->m) ? fmi2True : fmi2False;
  *terminate = ((instance*)c)->m.terminate ? fmi2True : fmi2False;
  return fmi2OK;
}
fmi2Status fmi2SetTime(fmi2Component c, fmi2Real t) {
  ((instance*)c)->m.time = t;
  return fmi2OK;
}
fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t n) {
  instance* s = c;
  if ((int)n != me_state_count) return fmi2Error;
  for (size_t k = 0; k < n; ++k) s->m.r[me_states[k]] = x[k];
  return fmi2OK;
}
fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t n) {
  instance* s = c;
  if ((int)n != me_state_count) return fmi2Error;
  for (size_t k = 0; k < n; ++k) x[k] = s->m.r[me_states[k]];
  return fmi2OK;
}
fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real dx[], size_t n) {
  instance* s = c;
  if ((int)n != me_state_count) return fmi2Error;
  if (s->m.r[ME_FAIL_AFTER] > 0 && s->m.time > s->m.r[ME_FAIL_AFTER]) {
    say(s, fmi2Discard, "logStatusDiscard", "equations refused at t = %g", s->m.time);
    return fmi2Discard;
  }
  me_equations(&s->m);
  for (size_t k = 0; k < n; ++k) dx[k] = s->m.r[me_derivatives[k]];
  return fmi2OK;
}
fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real z[], size_t n) {
  if ((int)n != me_indicator_count) return fmi2Error;
  me_indicators(&((instance*)c)->m, z);
  return fmi2OK;
}
fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x[], size_t n) {
  (void)c;
  for (size_t k = 0; k < n; ++k) x[k] = 1.0;
  return fmi2OK;
}
