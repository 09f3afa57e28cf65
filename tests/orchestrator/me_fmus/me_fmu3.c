/* The FMI 3.0 Model Exchange interface around one me_model.h model (test FMUs only), so that the
 * same equations run through both standards. One value-reference space for all types, as 3.0
 * has: Float64 k is vr k, Int32 k is vr 100 + k, Boolean k is vr 200 + k, String k is vr
 * 300 + k, the independent variable time is vr 999. The other types of the standard are refused
 * with fmi3Error; so are the other interfaces (me_fmu3_refusals.c). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "me_model.h"
#include "stride/fmi3/fmi3_api.h"

#define VR_INT32 100
#define VR_BOOLEAN 200
#define VR_STRING 300
#define VR_TIME 999

typedef struct {
  me_data m;
  fmi3InstanceEnvironment env;
  fmi3LogMessageCallback log;
  int logging;
} instance3;

static void say3(const instance3* s, fmi3Status status, const char* category, const char* format,
                 ...) {
  if (!s->logging || s->log == NULL) return;
  char text[256];
  va_list args;
  va_start(args, format);
  vsnprintf(text, sizeof text, format, args);
  va_end(args);
  s->log(s->env, status, category, text);
}

/* k is the index of vr in the type's block starting at base, or -1 */
static int index_of(fmi3ValueReference vr, unsigned base, int limit) {
  if (vr < base || vr >= base + (unsigned)limit) return -1;
  return (int)(vr - base);
}

const char* fmi3GetVersion(void) {
  return "3.0";
}
fmi3Status fmi3SetDebugLogging(fmi3Instance c, fmi3Boolean on, size_t n, const fmi3String cat[]) {
  (void)n;
  (void)cat;
  ((instance3*)c)->logging = on == fmi3True;
  return fmi3OK;
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String name, fmi3String token, fmi3String resources,
                                          fmi3Boolean visible, fmi3Boolean logging,
                                          fmi3InstanceEnvironment env, fmi3LogMessageCallback log) {
  (void)name;
  (void)resources;
  (void)visible;
  if (token == NULL || strcmp(token, me_guid) != 0) return NULL;
  instance3* s = calloc(1, sizeof *s);
  if (s == NULL) return NULL;
  s->env = env;
  s->log = log;
  s->logging = logging == fmi3True;
  s->m.next_event = -1;
  me_start(&s->m);
  say3(s, fmi3OK, "logAll", "instantiated with %d continuous states", me_state_count);
  return s;
}
void fmi3FreeInstance(fmi3Instance c) {
  free(c);
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance c, fmi3Boolean tol_defined, fmi3Float64 tol,
                                       fmi3Float64 start, fmi3Boolean stop_defined,
                                       fmi3Float64 stop) {
  (void)tol_defined;
  (void)tol;
  (void)stop_defined;
  (void)stop;
  ((instance3*)c)->m.time = start;
  return fmi3OK;
}
fmi3Status fmi3ExitInitializationMode(fmi3Instance c) {
  (void)c;
  return fmi3OK;
}
fmi3Status fmi3EnterEventMode(fmi3Instance c) {
  (void)c;
  return fmi3OK;
}
fmi3Status fmi3Terminate(fmi3Instance c) {
  (void)c;
  return fmi3OK;
}
fmi3Status fmi3Reset(fmi3Instance c) {
  instance3* s = c;
  memset(&s->m, 0, sizeof s->m);
  s->m.next_event = -1;
  me_start(&s->m);
  return fmi3OK;
}

fmi3Status fmi3GetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t n, fmi3Float64 v[],
                          size_t nv) {
  instance3* s = c;
  if (n != nv) return fmi3Error;
  me_equations(&s->m);
  for (size_t k = 0; k < n; ++k) {
    const int i = index_of(vr[k], 0, ME_MAX_REALS);
    if (i < 0 && vr[k] != VR_TIME) return fmi3Error;
    v[k] = i < 0 ? s->m.time : s->m.r[i];
  }
  return fmi3OK;
}
fmi3Status fmi3SetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                          const fmi3Float64 v[], size_t nv) {
  instance3* s = c;
  if (n != nv) return fmi3Error;
  for (size_t k = 0; k < n; ++k) {
    const int i = index_of(vr[k], 0, ME_MAX_REALS);
    if (i < 0) return fmi3Error;
    s->m.r[i] = v[k];
  }
  return fmi3OK;
}
fmi3Status fmi3GetInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t n, fmi3Int32 v[],
                        size_t nv) {
  instance3* s = c;
  if (n != nv) return fmi3Error;
  for (size_t k = 0; k < n; ++k) {
    const int i = index_of(vr[k], VR_INT32, ME_MAX_INTEGERS);
    if (i < 0) return fmi3Error;
    v[k] = s->m.i[i];
  }
  return fmi3OK;
}
fmi3Status fmi3SetInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                        const fmi3Int32 v[], size_t nv) {
  instance3* s = c;
  if (n != nv) return fmi3Error;
  for (size_t k = 0; k < n; ++k) {
    const int i = index_of(vr[k], VR_INT32, ME_MAX_INTEGERS);
    if (i < 0) return fmi3Error;
    s->m.i[i] = v[k];
  }
  return fmi3OK;
}
fmi3Status fmi3GetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t n, fmi3Boolean v[],
                          size_t nv) {
  instance3* s = c;
  if (n != nv) return fmi3Error;
  me_equations(&s->m);
  for (size_t k = 0; k < n; ++k) {
    const int i = index_of(vr[k], VR_BOOLEAN, ME_MAX_BOOLEANS);
    if (i < 0) return fmi3Error;
    v[k] = s->m.b[i] ? fmi3True : fmi3False;
  }
  return fmi3OK;
}
fmi3Status fmi3SetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                          const fmi3Boolean v[], size_t nv) {
  instance3* s = c;
  if (n != nv) return fmi3Error;
  for (size_t k = 0; k < n; ++k) {
    const int i = index_of(vr[k], VR_BOOLEAN, ME_MAX_BOOLEANS);
    if (i < 0) return fmi3Error;
    s->m.b[i] = v[k] != fmi3False;
  }
  return fmi3OK;
}
fmi3Status fmi3GetString(fmi3Instance c, const fmi3ValueReference vr[], size_t n, fmi3String v[],
                         size_t nv) {
  instance3* s = c;
  if (n != nv) return fmi3Error;
  for (size_t k = 0; k < n; ++k) {
    const int i = index_of(vr[k], VR_STRING, ME_MAX_STRINGS);
    if (i < 0) return fmi3Error;
    v[k] = s->m.s[i];
  }
  return fmi3OK;
}
fmi3Status fmi3SetString(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                         const fmi3String v[], size_t nv) {
  instance3* s = c;
  if (n != nv) return fmi3Error;
  for (size_t k = 0; k < n; ++k) {
    const int i = index_of(vr[k], VR_STRING, ME_MAX_STRINGS);
    if (i < 0 || v[k] == NULL || strlen(v[k]) >= ME_STRING_SIZE) return fmi3Error;
    strcpy(s->m.s[i], v[k]);
  }
  return fmi3OK;
}

/* the types no test model has: any call is an error */
#define REFUSED_TYPE(T)                                                                       \
  fmi3Status fmi3Get##T(fmi3Instance c, const fmi3ValueReference vr[], size_t n, fmi3##T v[], \
                        size_t nv) {                                                          \
    (void)c, (void)vr, (void)n, (void)v, (void)nv;                                            \
    return fmi3Error;                                                                         \
  }                                                                                           \
  fmi3Status fmi3Set##T(fmi3Instance c, const fmi3ValueReference vr[], size_t n,              \
                        const fmi3##T v[], size_t nv) {                                       \
    (void)c, (void)vr, (void)n, (void)v, (void)nv;                                            \
    return fmi3Error;                                                                         \
  }
REFUSED_TYPE(Float32)
REFUSED_TYPE(Int8)
REFUSED_TYPE(UInt8)
REFUSED_TYPE(Int16)
REFUSED_TYPE(UInt16)
REFUSED_TYPE(UInt32)
REFUSED_TYPE(Int64)
REFUSED_TYPE(UInt64)
fmi3Status fmi3GetBinary(fmi3Instance c, const fmi3ValueReference vr[], size_t n, size_t sizes[],
                         fmi3Binary v[], size_t nv) {
  (void)c, (void)vr, (void)n, (void)sizes, (void)v, (void)nv;
  return fmi3Error;
}
fmi3Status fmi3SetBinary(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                         const size_t sizes[], const fmi3Binary v[], size_t nv) {
  (void)c, (void)vr, (void)n, (void)sizes, (void)v, (void)nv;
  return fmi3Error;
}
/* FMU state: a copy of the model data; serialized as its bytes */
fmi3Status fmi3GetFMUState(fmi3Instance c, fmi3FMUState* state) {
  if (*state == NULL) *state = malloc(sizeof(me_data));
  if (*state == NULL) return fmi3Error;
  memcpy(*state, &((instance3*)c)->m, sizeof(me_data));
  return fmi3OK;
}
fmi3Status fmi3SetFMUState(fmi3Instance c, fmi3FMUState state) {
  memcpy(&((instance3*)c)->m, state, sizeof(me_data));
  return fmi3OK;
}
fmi3Status fmi3FreeFMUState(fmi3Instance c, fmi3FMUState* state) {
  (void)c;
  free(*state);
  *state = NULL;
  return fmi3OK;
}
fmi3Status fmi3SerializedFMUStateSize(fmi3Instance c, fmi3FMUState state, size_t* size) {
  (void)c;
  (void)state;
  *size = sizeof(me_data);
  return fmi3OK;
}
fmi3Status fmi3SerializeFMUState(fmi3Instance c, fmi3FMUState state, fmi3Byte out[], size_t size) {
  (void)c;
  if (size != sizeof(me_data)) return fmi3Error;
  memcpy(out, state, size);
  return fmi3OK;
}
fmi3Status fmi3DeserializeFMUState(fmi3Instance c, const fmi3Byte in[], size_t size,
                                   fmi3FMUState* state) {
  (void)c;
  if (size != sizeof(me_data)) return fmi3Error;
  *state = malloc(size);
  if (*state == NULL) return fmi3Error;
  memcpy(*state, in, size);
  return fmi3OK;
}

/* ---- Model Exchange ---- */
fmi3Status fmi3UpdateDiscreteStates(fmi3Instance c, fmi3Boolean* again, fmi3Boolean* terminate,
                                    fmi3Boolean* nominals_changed, fmi3Boolean* values_changed,
                                    fmi3Boolean* next_defined, fmi3Float64* next) {
  instance3* s = c;
  const int changed = me_event(&s->m);
  *again = s->m.r[ME_CHATTER] > 0 ? fmi3True : fmi3False;
  *terminate = s->m.terminate ? fmi3True : fmi3False;
  *nominals_changed = fmi3False;
  *values_changed = changed ? fmi3True : fmi3False;
  *next_defined = s->m.next_event >= 0 ? fmi3True : fmi3False;
  *next = s->m.next_event;
  return fmi3OK;
}
fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance c) {
  (void)c;
  return fmi3OK;
}
fmi3Status fmi3CompletedIntegratorStep(fmi3Instance c, fmi3Boolean no_set, fmi3Boolean* enter,
                                       fmi3Boolean* terminate) {
  (void)no_set;
  *enter = me_step_event(&((instance3*)c)->m) ? fmi3True : fmi3False;
  *terminate = ((instance3*)c)->m.terminate ? fmi3True : fmi3False;
  return fmi3OK;
}
fmi3Status fmi3SetTime(fmi3Instance c, fmi3Float64 t) {
  ((instance3*)c)->m.time = t;
  return fmi3OK;
}
fmi3Status fmi3SetContinuousStates(fmi3Instance c, const fmi3Float64 x[], size_t n) {
  instance3* s = c;
  if ((int)n != me_state_count) return fmi3Error;
  for (size_t k = 0; k < n; ++k) s->m.r[me_states[k]] = x[k];
  return fmi3OK;
}
fmi3Status fmi3GetContinuousStates(fmi3Instance c, fmi3Float64 x[], size_t n) {
  instance3* s = c;
  if ((int)n != me_state_count) return fmi3Error;
  for (size_t k = 0; k < n; ++k) x[k] = s->m.r[me_states[k]];
  return fmi3OK;
}
fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance c, fmi3Float64 dx[], size_t n) {
  instance3* s = c;
  if ((int)n != me_state_count) return fmi3Error;
  if (s->m.r[ME_FAIL_AFTER] > 0 && s->m.time > s->m.r[ME_FAIL_AFTER]) {
    say3(s, fmi3Discard, "logStatusDiscard", "equations refused at t = %g", s->m.time);
    return fmi3Discard;
  }
  me_equations(&s->m);
  for (size_t k = 0; k < n; ++k) dx[k] = s->m.r[me_derivatives[k]];
  return fmi3OK;
}
fmi3Status fmi3GetEventIndicators(fmi3Instance c, fmi3Float64 z[], size_t n) {
  if ((int)n != me_indicator_count) return fmi3Error;
  me_indicators(&((instance3*)c)->m, z);
  return fmi3OK;
}
fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance c, fmi3Float64 x[], size_t n) {
  (void)c;
  for (size_t k = 0; k < n; ++k) x[k] = 1.0;
  return fmi3OK;
}
fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance c, size_t* n) {
  (void)c;
  *n = (size_t)me_indicator_count;
  return fmi3OK;
}
fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance c, size_t* n) {
  (void)c;
  *n = (size_t)me_state_count;
  return fmi3OK;
}
