/* fmi3_kinds: an FMI 3.0 Co-Simulation test FMU with every variable kind Stride imports.
 *
 * Each step (and the end of initialization) computes, from the inputs:
 *   <kind>_out = <kind>_in + 1           for the ten numeric kinds, except
 *   f64_out    = gain * f64_in + steps   (steps: completed steps, the state worth saving)
 *   <kind>_aout[i] = <kind>_ain[i] + i + 1   (arrays of 3, i from 0)
 *   series_out[i]  = series_in[0] + ... + series_in[i]  (size from the structural parameter n)
 *   b_out = !b_in,  s_out = s_in + "!",  bin_out = bin_in reversed
 * big (Int64) is always 5000000000, which does not fit a 32-bit integer. stop=true makes the
 * next step ask for termination. The whole instance is plain data, so its FMU state is a copy. */
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "stride/fmi3/fmi3_api.h"

#define TOKEN "{fmi3-kinds-7d1c}"
#define TEXT_MAX 256
#define BYTES_MAX 64
#define SERIES 4

/* kind, field prefix, C type, first value reference */
#define NUMERIC_KINDS(X)           \
  X(Float32, f32, fmi3Float32, 10) \
  X(Float64, f64, fmi3Float64, 20) \
  X(Int8, i8, fmi3Int8, 30)        \
  X(UInt8, u8, fmi3UInt8, 40)      \
  X(Int16, i16, fmi3Int16, 50)     \
  X(UInt16, u16, fmi3UInt16, 60)   \
  X(Int32, i32, fmi3Int32, 70)     \
  X(UInt32, u32, fmi3UInt32, 80)   \
  X(Int64, i64, fmi3Int64, 90)     \
  X(UInt64, u64, fmi3UInt64, 100)

enum { VR_GAIN = 1, VR_STEPS = 2, VR_BIG = 3, VR_STOP = 4, VR_N = 5 };
enum { VR_B_IN = 110, VR_B_OUT, VR_S_IN = 120, VR_S_OUT, VR_BIN_IN = 130, VR_BIN_OUT };
enum { VR_SERIES_IN = 140, VR_SERIES_OUT };

typedef enum { instantiated, initialization, stepping, terminated } phase;

typedef struct {
#define FIELDS(K, p, T, vr) T p##_in, p##_out, p##_ain[3], p##_aout[3];
  NUMERIC_KINDS(FIELDS)
#undef FIELDS
  fmi3Float64 time, gain, series_in[SERIES], series_out[SERIES];
  fmi3Int32 steps;
  fmi3Int64 big;
  fmi3UInt64 n;
  fmi3Boolean b_in, b_out, stop;
  char s_in[TEXT_MAX], s_out[TEXT_MAX + 1];
  fmi3Byte bin_in[BYTES_MAX], bin_out[BYTES_MAX];
  size_t bin_in_size, bin_out_size;
  phase state;
} data;

typedef struct {
  data d;
  fmi3InstanceEnvironment env;
  fmi3LogMessageCallback log;
  bool logging;
} instance;

static void say(instance* m, fmi3Status s, const char* message) {
  if (m->logging && m->log) m->log(m->env, s, "logStatusError", message);
}

static fmi3Status fail(instance* m, const char* message) {
  say(m, fmi3Error, message);
  return fmi3Error;
}

static void compute(data* d) {
#define ADD_ONE(K, p, T, vr)       \
  d->p##_out = (T)(d->p##_in + 1); \
  for (int i = 0; i < 3; ++i) d->p##_aout[i] = (T)(d->p##_ain[i] + i + 1);
  NUMERIC_KINDS(ADD_ONE)
#undef ADD_ONE
  d->f64_out = d->gain * d->f64_in + d->steps;
  double sum = 0;
  for (int i = 0; i < SERIES; ++i) d->series_out[i] = (sum += d->series_in[i]);
  d->b_out = !d->b_in;
  strcpy(d->s_out, d->s_in);
  strcat(d->s_out, "!");
  d->bin_out_size = d->bin_in_size;
  for (size_t i = 0; i < d->bin_in_size; ++i) d->bin_out[i] = d->bin_in[d->bin_in_size - 1 - i];
}

static void defaults(data* d) {
  memset(d, 0, sizeof *d);
#define START(K, p, T, vr) \
  d->p##_in = (T)2;        \
  for (int i = 0; i < 3; ++i) d->p##_ain[i] = (T)(10 * (i + 1));
  NUMERIC_KINDS(START)
#undef START
  d->f64_in = 1.5;
  d->gain = 2.0;
  d->big = 5000000000LL;
  d->n = SERIES;
  for (int i = 0; i < SERIES; ++i) d->series_in[i] = i + 1;
  strcpy(d->s_in, "stride");
  d->bin_in_size = 2;
  d->bin_in[0] = 0xca;
  d->bin_in[1] = 0xfe;
  compute(d);
}

/* ---- variable lookup: where the values of a value reference live ---- */

typedef enum {
#define TAG(K, p, T, vr) k_##K,
  NUMERIC_KINDS(TAG)
#undef TAG
      k_Boolean,
  k_String,
  k_Binary
} kind;

typedef struct {
  void* at;
  size_t count;
  kind k;
  bool settable;  /* input or parameter */
  bool parameter; /* settable only before initialization ends */
} slot;

static bool find(data* d, fmi3ValueReference vr, slot* s) {
  s->settable = false;
  s->parameter = false;
#define FIND(K, p, T, base)                                           \
  if (vr >= base && vr < base + 4) {                                  \
    void* at[4] = {&d->p##_in, &d->p##_out, d->p##_ain, d->p##_aout}; \
    s->at = at[vr - base];                                            \
    s->count = vr - base < 2 ? 1 : 3;                                 \
    s->k = k_##K;                                                     \
    s->settable = (vr - base) % 2 == 0;                               \
    return true;                                                      \
  }
  NUMERIC_KINDS(FIND)
#undef FIND
  switch (vr) {
    case 0:
      *s = (slot){&d->time, 1, k_Float64, false, false};
      return true;
    case VR_GAIN:
      *s = (slot){&d->gain, 1, k_Float64, true, true};
      return true;
    case VR_STEPS:
      *s = (slot){&d->steps, 1, k_Int32, false, false};
      return true;
    case VR_BIG:
      *s = (slot){&d->big, 1, k_Int64, false, false};
      return true;
    case VR_STOP:
      *s = (slot){&d->stop, 1, k_Boolean, true, false};
      return true;
    case VR_N:
      *s = (slot){&d->n, 1, k_UInt64, false, false};
      return true;
    case VR_B_IN:
      *s = (slot){&d->b_in, 1, k_Boolean, true, false};
      return true;
    case VR_B_OUT:
      *s = (slot){&d->b_out, 1, k_Boolean, false, false};
      return true;
    case VR_S_IN:
      *s = (slot){d->s_in, 1, k_String, true, false};
      return true;
    case VR_S_OUT:
      *s = (slot){d->s_out, 1, k_String, false, false};
      return true;
    case VR_BIN_IN:
      *s = (slot){d->bin_in, 1, k_Binary, true, false};
      return true;
    case VR_BIN_OUT:
      *s = (slot){d->bin_out, 1, k_Binary, false, false};
      return true;
    case VR_SERIES_IN:
      *s = (slot){d->series_in, SERIES, k_Float64, true, false};
      return true;
    case VR_SERIES_OUT:
      *s = (slot){d->series_out, SERIES, k_Float64, false, false};
      return true;
    default:
      return false;
  }
}

/* Checks one get or set call: known references of kind `k`, nValues matching, state allowing. */
static fmi3Status check_call(instance* m, const fmi3ValueReference vr[], size_t nvr, kind k,
                             size_t n_values, bool setting) {
  if (m == NULL || (nvr > 0 && vr == NULL)) return fmi3Error;
  if (m->d.state == terminated && setting) return fail(m, "set after fmi3Terminate");
  size_t total = 0;
  for (size_t i = 0; i < nvr; ++i) {
    slot s;
    if (!find(&m->d, vr[i], &s) || s.k != k) return fail(m, "unknown value reference for type");
    if (setting && !s.settable) return fail(m, "variable cannot be set");
    if (setting && s.parameter && m->d.state == stepping) return fail(m, "fixed parameter");
    total += s.count;
  }
  if (total != n_values) return fail(m, "nValues does not match the array sizes");
  return fmi3OK;
}

#define GET_SET(K, p, T, base)                                                                    \
  fmi3Status fmi3Get##K(fmi3Instance inst, const fmi3ValueReference vr[], size_t nvr, T values[], \
                        size_t n) {                                                               \
    instance* m = inst;                                                                           \
    const fmi3Status s = check_call(m, vr, nvr, k_##K, n, false);                                 \
    if (s != fmi3OK) return s;                                                                    \
    for (size_t i = 0, at = 0; i < nvr; ++i) {                                                    \
      slot sl;                                                                                    \
      find(&m->d, vr[i], &sl);                                                                    \
      memcpy(values + at, sl.at, sl.count * sizeof(T));                                           \
      at += sl.count;                                                                             \
    }                                                                                             \
    return fmi3OK;                                                                                \
  }                                                                                               \
  fmi3Status fmi3Set##K(fmi3Instance inst, const fmi3ValueReference vr[], size_t nvr,             \
                        const T values[], size_t n) {                                             \
    instance* m = inst;                                                                           \
    const fmi3Status s = check_call(m, vr, nvr, k_##K, n, true);                                  \
    if (s != fmi3OK) return s;                                                                    \
    for (size_t i = 0, at = 0; i < nvr; ++i) {                                                    \
      slot sl;                                                                                    \
      find(&m->d, vr[i], &sl);                                                                    \
      memcpy(sl.at, values + at, sl.count * sizeof(T));                                           \
      at += sl.count;                                                                             \
    }                                                                                             \
    return fmi3OK;                                                                                \
  }
NUMERIC_KINDS(GET_SET)
GET_SET(Boolean, b, fmi3Boolean, 0)
#undef GET_SET

fmi3Status fmi3GetString(fmi3Instance inst, const fmi3ValueReference vr[], size_t nvr,
                         fmi3String values[], size_t n) {
  instance* m = inst;
  const fmi3Status s = check_call(m, vr, nvr, k_String, n, false);
  if (s != fmi3OK) return s;
  for (size_t i = 0; i < nvr; ++i) {
    slot sl;
    find(&m->d, vr[i], &sl);
    values[i] = sl.at;
  }
  return fmi3OK;
}

fmi3Status fmi3SetString(fmi3Instance inst, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3String values[], size_t n) {
  instance* m = inst;
  const fmi3Status s = check_call(m, vr, nvr, k_String, n, true);
  if (s != fmi3OK) return s;
  for (size_t i = 0; i < nvr; ++i) {
    if (values[i] == NULL || strlen(values[i]) >= TEXT_MAX) return fail(m, "string too long");
  }
  for (size_t i = 0; i < nvr; ++i) {
    slot sl;
    find(&m->d, vr[i], &sl);
    strcpy(sl.at, values[i]);
  }
  return fmi3OK;
}

fmi3Status fmi3GetBinary(fmi3Instance inst, const fmi3ValueReference vr[], size_t nvr,
                         size_t sizes[], fmi3Binary values[], size_t n) {
  instance* m = inst;
  const fmi3Status s = check_call(m, vr, nvr, k_Binary, n, false);
  if (s != fmi3OK) return s;
  for (size_t i = 0; i < nvr; ++i) {
    const bool in = vr[i] == VR_BIN_IN;
    values[i] = in ? m->d.bin_in : m->d.bin_out;
    sizes[i] = in ? m->d.bin_in_size : m->d.bin_out_size;
  }
  return fmi3OK;
}

fmi3Status fmi3SetBinary(fmi3Instance inst, const fmi3ValueReference vr[], size_t nvr,
                         const size_t sizes[], const fmi3Binary values[], size_t n) {
  instance* m = inst;
  const fmi3Status s = check_call(m, vr, nvr, k_Binary, n, true);
  if (s != fmi3OK) return s;
  for (size_t i = 0; i < nvr; ++i) {
    if (sizes[i] > BYTES_MAX || (sizes[i] > 0 && values[i] == NULL)) return fail(m, "too long");
  }
  for (size_t i = 0; i < nvr; ++i) {
    if (sizes[i] > 0) memcpy(m->d.bin_in, values[i], sizes[i]);
    m->d.bin_in_size = sizes[i];
  }
  return fmi3OK;
}

/* ---- life cycle ---- */

const char* fmi3GetVersion(void) {
  return fmi3Version;
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String name, fmi3String token, fmi3String resources,
                                         fmi3Boolean visible, fmi3Boolean logging,
                                         fmi3Boolean event_mode, fmi3Boolean early_return,
                                         const fmi3ValueReference required[], size_t n_required,
                                         fmi3InstanceEnvironment env, fmi3LogMessageCallback log,
                                         fmi3IntermediateUpdateCallback update) {
  (void)name, (void)resources, (void)visible, (void)required, (void)update;
  instance probe = {.env = env, .log = log, .logging = logging};
  if (token == NULL || strcmp(token, TOKEN) != 0) {
    say(&probe, fmi3Error, "wrong instantiationToken");
    return NULL;
  }
  if (event_mode || early_return || n_required > 0) {
    say(&probe, fmi3Error, "event mode, early return and intermediate update are not offered");
    return NULL;
  }
  instance* m = calloc(1, sizeof *m);
  if (m == NULL) return NULL;
  *m = probe;
  defaults(&m->d);
  say(m, fmi3OK, "fmi3_kinds instantiated");
  return m;
}

void fmi3FreeInstance(fmi3Instance inst) {
  free(inst);
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance inst, fmi3Boolean tol_defined, fmi3Float64 tol,
                                       fmi3Float64 start, fmi3Boolean stop_defined,
                                       fmi3Float64 stop) {
  (void)tol_defined, (void)tol, (void)stop_defined, (void)stop;
  instance* m = inst;
  if (m == NULL || m->d.state != instantiated) return fmi3Error;
  m->d.time = start;
  m->d.state = initialization;
  return fmi3OK;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance inst) {
  instance* m = inst;
  if (m == NULL || m->d.state != initialization) return fmi3Error;
  compute(&m->d);
  m->d.state = stepping;
  return fmi3OK;
}

fmi3Status fmi3DoStep(fmi3Instance inst, fmi3Float64 t, fmi3Float64 h, fmi3Boolean no_set_prior,
                      fmi3Boolean* event, fmi3Boolean* terminate, fmi3Boolean* early,
                      fmi3Float64* last) {
  (void)no_set_prior;
  instance* m = inst;
  if (m == NULL || !event || !terminate || !early || !last) return fmi3Error;
  if (m->d.state != stepping) return fail(m, "fmi3DoStep outside step mode");
  if (!(h > 0)) return fail(m, "step size must be positive");
  *event = fmi3False;
  *early = fmi3False;
  *terminate = m->d.stop;
  if (m->d.stop) {
    *last = t;
    return fmi3Discard;
  }
  m->d.steps += 1;
  m->d.time = t + h;
  compute(&m->d);
  *last = m->d.time;
  return fmi3OK;
}

fmi3Status fmi3Terminate(fmi3Instance inst) {
  instance* m = inst;
  if (m == NULL || m->d.state != stepping) return fmi3Error;
  m->d.state = terminated;
  return fmi3OK;
}

fmi3Status fmi3Reset(fmi3Instance inst) {
  instance* m = inst;
  if (m == NULL) return fmi3Error;
  defaults(&m->d);
  return fmi3OK;
}

fmi3Status fmi3SetDebugLogging(fmi3Instance inst, fmi3Boolean on, size_t n,
                               const fmi3String categories[]) {
  (void)n, (void)categories;
  instance* m = inst;
  if (m == NULL) return fmi3Error;
  m->logging = on;
  return fmi3OK;
}

/* ---- FMU state: a copy of the data ---- */

fmi3Status fmi3GetFMUState(fmi3Instance inst, fmi3FMUState* state) {
  instance* m = inst;
  if (m == NULL || state == NULL) return fmi3Error;
  data* copy = *state ? *state : malloc(sizeof *copy);
  if (copy == NULL) return fmi3Error;
  *copy = m->d;
  *state = copy;
  return fmi3OK;
}

fmi3Status fmi3SetFMUState(fmi3Instance inst, fmi3FMUState state) {
  instance* m = inst;
  if (m == NULL || state == NULL) return fmi3Error;
  m->d = *(const data*)state;
  return fmi3OK;
}

fmi3Status fmi3FreeFMUState(fmi3Instance inst, fmi3FMUState* state) {
  if (inst == NULL || state == NULL) return fmi3Error;
  free(*state);
  *state = NULL;
  return fmi3OK;
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance inst, fmi3FMUState state, size_t* size) {
  if (inst == NULL || state == NULL || size == NULL) return fmi3Error;
  *size = sizeof(data);
  return fmi3OK;
}

fmi3Status fmi3SerializeFMUState(fmi3Instance inst, fmi3FMUState state, fmi3Byte bytes[],
                                 size_t size) {
  if (inst == NULL || state == NULL || bytes == NULL) return fmi3Error;
  if (size != sizeof(data)) return fail(inst, "wrong size of the state buffer");
  memcpy(bytes, state, sizeof(data));
  return fmi3OK;
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance inst, const fmi3Byte bytes[], size_t size,
                                   fmi3FMUState* state) {
  if (inst == NULL || bytes == NULL || state == NULL) return fmi3Error;
  if (size != sizeof(data)) return fail(inst, "serialized state of the wrong size");
  data* copy = malloc(sizeof *copy);
  if (copy == NULL) return fmi3Error;
  memcpy(copy, bytes, sizeof *copy);
  if (copy->state > terminated || copy->bin_in_size > BYTES_MAX ||
      memchr(copy->s_in, 0, TEXT_MAX) == NULL) {
    free(copy);
    return fail(inst, "damaged serialized state");
  }
  *state = copy;
  return fmi3OK;
}
