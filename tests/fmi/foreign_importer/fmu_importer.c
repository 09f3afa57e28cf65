/* fmu_importer: a foreign FMI 2.0 Co-Simulation importer in plain C11.
 *
 * It uses no Stride header on purpose: everything it knows about FMI 2.0 is declared below from
 * the specification, so an FMU that only works with Stride's own declarations fails here.
 * Dependencies: libc, libdl (dlopen/dlsym) and libzip's C API (unzipping only). The unzipping and
 * the string parsing of modelDescription.xml are shared with fmu3_importer (fmu_archive.c).
 *
 * usage: fmu_importer FILE.fmu [--steps N] [--twice] [--no-compare] [--misuse]
 *
 * Unzips the FMU into a fresh mkdtemp directory, reads guid, modelIdentifier, the default
 * experiment and the Real outputs from modelDescription.xml by plain string parsing, loads
 * binaries/linux64/<modelIdentifier>.so, resolves all 34 Co-Simulation functions and runs
 *   GetVersion/GetTypesPlatform -> Instantiate -> SetupExperiment -> Enter/ExitInitializationMode
 *   -> N x (DoStep, GetReal outputs) -> Terminate -> FreeInstance,
 * then checks that Instantiate with a wrong GUID returns NULL with a log message and that
 * functions of undeclared capabilities (FMU state, directional derivatives) return fmi2Error.
 * When the FMU declares canGetAndSetFMUstate and canSerializeFMUstate, the state of the halfway
 * step is serialized, the run goes on, and the deserialized state, set in the same instance and
 * in a fresh one, must repeat the second half bit for bit (unless --no-compare).
 * --twice runs the lifecycle twice in a row (the second time with a trailing '/' on the
 * resource URI, as some importers pass it) and two instances side by side in the same process,
 * comparing all output traces with the first run (--no-compare skips the comparison).
 * --misuse instead calls functions out of order and with bad arguments (see check_misuse).
 * Everything is freed and the temp directory removed, so valgrind sees no leak of ours.
 * Exit status: 0 on success, 1 on a failed check, 2 on a usage error.
 */
#define _XOPEN_SOURCE 700

#include <dlfcn.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fmu_archive.h"

const char* const fmu_program_name = "fmu_importer";

/* ---- FMI 2.0 declarations (fmi2TypesPlatform.h / fmi2FunctionTypes.h, "default" platform) */
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

typedef enum { fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending } fmi2Status;
typedef enum { fmi2ModelExchange, fmi2CoSimulation } fmi2Type;
typedef enum {
  fmi2DoStepStatus,
  fmi2PendingStatus,
  fmi2LastSuccessfulTime,
  fmi2Terminated
} fmi2StatusKind;

typedef void (*fmi2CallbackLogger)(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String,
                                   fmi2String, ...);
typedef void* (*fmi2CallbackAllocateMemory)(size_t, size_t);
typedef void (*fmi2CallbackFreeMemory)(void*);
typedef void (*fmi2StepFinished)(fmi2ComponentEnvironment, fmi2Status);

typedef struct {
  fmi2CallbackLogger logger;
  fmi2CallbackAllocateMemory allocateMemory;
  fmi2CallbackFreeMemory freeMemory;
  fmi2StepFinished stepFinished;
  fmi2ComponentEnvironment componentEnvironment;
} fmi2CallbackFunctions;

/* The 34 functions of a Co-Simulation FMU: 25 common + 9 Co-Simulation. */
typedef struct {
  const char* (*fmi2GetTypesPlatform)(void);
  const char* (*fmi2GetVersion)(void);
  fmi2Status (*fmi2SetDebugLogging)(fmi2Component, fmi2Boolean, size_t, const fmi2String[]);
  fmi2Component (*fmi2Instantiate)(fmi2String, fmi2Type, fmi2String, fmi2String,
                                   const fmi2CallbackFunctions*, fmi2Boolean, fmi2Boolean);
  void (*fmi2FreeInstance)(fmi2Component);
  fmi2Status (*fmi2SetupExperiment)(fmi2Component, fmi2Boolean, fmi2Real, fmi2Real, fmi2Boolean,
                                    fmi2Real);
  fmi2Status (*fmi2EnterInitializationMode)(fmi2Component);
  fmi2Status (*fmi2ExitInitializationMode)(fmi2Component);
  fmi2Status (*fmi2Terminate)(fmi2Component);
  fmi2Status (*fmi2Reset)(fmi2Component);
  fmi2Status (*fmi2GetReal)(fmi2Component, const fmi2ValueReference[], size_t, fmi2Real[]);
  fmi2Status (*fmi2GetInteger)(fmi2Component, const fmi2ValueReference[], size_t, fmi2Integer[]);
  fmi2Status (*fmi2GetBoolean)(fmi2Component, const fmi2ValueReference[], size_t, fmi2Boolean[]);
  fmi2Status (*fmi2GetString)(fmi2Component, const fmi2ValueReference[], size_t, fmi2String[]);
  fmi2Status (*fmi2SetReal)(fmi2Component, const fmi2ValueReference[], size_t, const fmi2Real[]);
  fmi2Status (*fmi2SetInteger)(fmi2Component, const fmi2ValueReference[], size_t,
                               const fmi2Integer[]);
  fmi2Status (*fmi2SetBoolean)(fmi2Component, const fmi2ValueReference[], size_t,
                               const fmi2Boolean[]);
  fmi2Status (*fmi2SetString)(fmi2Component, const fmi2ValueReference[], size_t,
                              const fmi2String[]);
  fmi2Status (*fmi2GetFMUstate)(fmi2Component, fmi2FMUstate*);
  fmi2Status (*fmi2SetFMUstate)(fmi2Component, fmi2FMUstate);
  fmi2Status (*fmi2FreeFMUstate)(fmi2Component, fmi2FMUstate*);
  fmi2Status (*fmi2SerializedFMUstateSize)(fmi2Component, fmi2FMUstate, size_t*);
  fmi2Status (*fmi2SerializeFMUstate)(fmi2Component, fmi2FMUstate, fmi2Byte[], size_t);
  fmi2Status (*fmi2DeSerializeFMUstate)(fmi2Component, const fmi2Byte[], size_t, fmi2FMUstate*);
  fmi2Status (*fmi2GetDirectionalDerivative)(fmi2Component, const fmi2ValueReference[], size_t,
                                             const fmi2ValueReference[], size_t, const fmi2Real[],
                                             fmi2Real[]);
  fmi2Status (*fmi2SetRealInputDerivatives)(fmi2Component, const fmi2ValueReference[], size_t,
                                            const fmi2Integer[], const fmi2Real[]);
  fmi2Status (*fmi2GetRealOutputDerivatives)(fmi2Component, const fmi2ValueReference[], size_t,
                                             const fmi2Integer[], fmi2Real[]);
  fmi2Status (*fmi2DoStep)(fmi2Component, fmi2Real, fmi2Real, fmi2Boolean);
  fmi2Status (*fmi2CancelStep)(fmi2Component);
  fmi2Status (*fmi2GetStatus)(fmi2Component, const fmi2StatusKind, fmi2Status*);
  fmi2Status (*fmi2GetRealStatus)(fmi2Component, const fmi2StatusKind, fmi2Real*);
  fmi2Status (*fmi2GetIntegerStatus)(fmi2Component, const fmi2StatusKind, fmi2Integer*);
  fmi2Status (*fmi2GetBooleanStatus)(fmi2Component, const fmi2StatusKind, fmi2Boolean*);
  fmi2Status (*fmi2GetStringStatus)(fmi2Component, const fmi2StatusKind, fmi2String*);
} fmu_functions;

#define FMU_IMPORTER_FUNCTIONS(X) \
  X(fmi2GetTypesPlatform)         \
  X(fmi2GetVersion)               \
  X(fmi2SetDebugLogging)          \
  X(fmi2Instantiate)              \
  X(fmi2FreeInstance)             \
  X(fmi2SetupExperiment)          \
  X(fmi2EnterInitializationMode)  \
  X(fmi2ExitInitializationMode)   \
  X(fmi2Terminate)                \
  X(fmi2Reset)                    \
  X(fmi2GetReal)                  \
  X(fmi2GetInteger)               \
  X(fmi2GetBoolean)               \
  X(fmi2GetString)                \
  X(fmi2SetReal)                  \
  X(fmi2SetInteger)               \
  X(fmi2SetBoolean)               \
  X(fmi2SetString)                \
  X(fmi2GetFMUstate)              \
  X(fmi2SetFMUstate)              \
  X(fmi2FreeFMUstate)             \
  X(fmi2SerializedFMUstateSize)   \
  X(fmi2SerializeFMUstate)        \
  X(fmi2DeSerializeFMUstate)      \
  X(fmi2GetDirectionalDerivative) \
  X(fmi2SetRealInputDerivatives)  \
  X(fmi2GetRealOutputDerivatives) \
  X(fmi2DoStep)                   \
  X(fmi2CancelStep)               \
  X(fmi2GetStatus)                \
  X(fmi2GetRealStatus)            \
  X(fmi2GetIntegerStatus)         \
  X(fmi2GetBooleanStatus)         \
  X(fmi2GetStringStatus)

/* ---- what the importer reads from modelDescription.xml ---- */
typedef struct {
  char* guid;
  char* model_identifier;
  double start_time;
  double step_size;
  int only_once_per_process;
  int can_get_and_set_fmu_state;
  int can_serialize_fmu_state;
  int provides_directional_derivative;
  fmi2ValueReference* outputs; /* valueReferences of Real outputs */
  size_t output_count;
  int has_real_input;
  fmi2ValueReference real_input; /* the first Real input, for --misuse */
} model_info;

static int g_log_count = 0;

static void importer_logger(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                            fmi2String category, fmi2String message, ...) {
  static const char* const names[] = {"OK", "Warning", "Discard", "Error", "Fatal", "Pending"};
  const char* status_name = (unsigned)status < 6u ? names[status] : "?";
  va_list args;
  (void)env;
  ++g_log_count;
  printf("  [fmu log] %s %s (%s): ", instance != NULL ? instance : "(null)", status_name,
         category != NULL ? category : "");
  if (message != NULL) {
    va_start(args, message);
    vprintf(message, args);
    va_end(args);
  }
  printf("\n");
  fflush(stdout);
}

static const char* status_name(fmi2Status s) {
  static const char* const names[] = {"fmi2OK",    "fmi2Warning", "fmi2Discard",
                                      "fmi2Error", "fmi2Fatal",   "fmi2Pending"};
  return (unsigned)s < 6u ? names[s] : "(invalid status)";
}

/* fmi2OK and fmi2Warning let the simulation go on; anything else is a failure here. */
static int check_status(fmi2Status s, const char* call, const char* instance) {
  if (s == fmi2OK || s == fmi2Warning) return 0;
  return fail("%s(%s) returned %s", call, instance, status_name(s));
}

/* ---- modelDescription.xml ---- */

static void free_model_info(model_info* info) {
  free(info->guid);
  free(info->model_identifier);
  free(info->outputs);
  memset(info, 0, sizeof *info);
}

static int read_model_description(const char* dir, model_info* info) {
  char* text;
  const char* tag;
  const char* end;
  int result = 0;
  memset(info, 0, sizeof *info);
  info->step_size = 0.01;
  text = read_model_description_text(dir);
  if (text == NULL) return 1;

  tag = find_tag(text, "fmiModelDescription", &end);
  if (tag == NULL) {
    result = fail("modelDescription.xml has no <fmiModelDescription>");
    goto done;
  }
  info->guid = tag_attribute(tag, end, "guid");
  if (info->guid == NULL) {
    result = fail("modelDescription.xml has no guid");
    goto done;
  }
  tag = find_tag(text, "CoSimulation", &end);
  if (tag == NULL) {
    result = fail("modelDescription.xml has no <CoSimulation>");
    goto done;
  }
  info->model_identifier = tag_attribute(tag, end, "modelIdentifier");
  if (info->model_identifier == NULL || info->model_identifier[0] == '\0' ||
      strchr(info->model_identifier, '/') != NULL) {
    result = fail("<CoSimulation> has no usable modelIdentifier");
    goto done;
  }
  info->only_once_per_process = attribute_is_true(tag, end, "canBeInstantiatedOnlyOncePerProcess");
  info->can_get_and_set_fmu_state = attribute_is_true(tag, end, "canGetAndSetFMUstate");
  info->can_serialize_fmu_state = attribute_is_true(tag, end, "canSerializeFMUstate");
  info->provides_directional_derivative =
      attribute_is_true(tag, end, "providesDirectionalDerivative");

  tag = find_tag(text, "DefaultExperiment", &end);
  if (tag != NULL) {
    if (attribute_double(tag, end, "stepSize", &info->step_size) != 0 ||
        attribute_double(tag, end, "startTime", &info->start_time) != 0) {
      result = 1;
      goto done;
    }
    if (!(info->step_size > 0.0)) {
      result = fail("DefaultExperiment stepSize %g is not positive", info->step_size);
      goto done;
    }
  }

  {
    const char* p = text;
    size_t capacity = 0;
    while ((tag = find_tag(p, "ScalarVariable", &end)) != NULL) {
      char* causality = tag_attribute(tag, end, "causality");
      char* vr_text = tag_attribute(tag, end, "valueReference");
      const char* type_end;
      const char* type = find_tag(end, "Real", &type_end);
      const char* next_element = strchr(end + 1, '<');
      int is_real = type != NULL && type == next_element && end[-1] != '/';
      int is_real_output = is_real && causality != NULL && strcmp(causality, "output") == 0;
      if (is_real && causality != NULL && strcmp(causality, "input") == 0 &&
          !info->has_real_input && vr_text != NULL) {
        info->has_real_input = 1;
        info->real_input = (fmi2ValueReference)strtoul(vr_text, NULL, 10);
      }
      if (is_real_output) {
        char* stop = NULL;
        unsigned long vr;
        if (vr_text == NULL || vr_text[0] == '\0') {
          result = fail("an output ScalarVariable has no valueReference");
        } else {
          errno = 0;
          vr = strtoul(vr_text, &stop, 10);
          if (*stop != '\0' || errno != 0 || vr > 0xFFFFFFFFul || vr_text[0] == '-') {
            result = fail("valueReference \"%s\" is not an unsigned int", vr_text);
          } else {
            if (info->output_count == capacity) {
              size_t new_capacity = capacity == 0 ? 8 : capacity * 2;
              fmi2ValueReference* grown =
                  realloc(info->outputs, new_capacity * sizeof *info->outputs);
              if (grown == NULL) {
                result = fail("out of memory");
              } else {
                info->outputs = grown;
                capacity = new_capacity;
              }
            }
            if (result == 0) info->outputs[info->output_count++] = (fmi2ValueReference)vr;
          }
        }
      }
      free(causality);
      free(vr_text);
      if (result != 0) goto done;
      p = end;
    }
  }
done:
  free(text);
  return result;
}

/* ---- loading the binary ---- */

static int load_functions(const char* so_path, const char* shown_name, void** handle,
                          fmu_functions* api) {
  char missing[2048] = "";
  size_t missing_count = 0;
  void* symbol;
  *handle = dlopen(so_path, RTLD_NOW | RTLD_LOCAL);
  if (*handle == NULL) return fail("cannot load %s: %s", so_path, dlerror());
  memset(api, 0, sizeof *api);
  /* POSIX guarantees that a data pointer from dlsym converts to a function pointer. */
#define FMU_IMPORTER_RESOLVE(name)                                                         \
  dlerror();                                                                               \
  symbol = dlsym(*handle, #name);                                                          \
  if (symbol == NULL) {                                                                    \
    if (missing_count++ > 0) strncat(missing, ", ", sizeof missing - strlen(missing) - 1); \
    strncat(missing, #name, sizeof missing - strlen(missing) - 1);                         \
  } else {                                                                                 \
    memcpy(&api->name, &symbol, sizeof symbol);                                            \
  }
  FMU_IMPORTER_FUNCTIONS(FMU_IMPORTER_RESOLVE)
#undef FMU_IMPORTER_RESOLVE
  if (missing_count > 0) {
    dlclose(*handle);
    *handle = NULL;
    return fail("%s does not export %zu of the 34 FMI 2.0 Co-Simulation functions: %s", shown_name,
                missing_count, missing);
  }
  return 0;
}

/* ---- the simulation runs ---- */

typedef struct {
  const fmu_functions* api;
  const model_info* info;
  const fmi2CallbackFunctions* callbacks;
  int steps;
} run_setup;

/* file://<percent-encoded absolute path>/resources[/] */
static char* resource_uri(const char* dir, int trailing_slash) {
  static const char hex[] = "0123456789ABCDEF";
  size_t length = strlen(dir);
  char* uri = malloc(length * 3 + 32);
  char* o = uri;
  size_t i;
  if (uri == NULL) return NULL;
  o += sprintf(o, "file://");
  for (i = 0; i < length; ++i) {
    unsigned char c = (unsigned char)dir[i];
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '/' ||
        c == '-' || c == '_' || c == '.' || c == '~') {
      *o++ = (char)c;
    } else {
      *o++ = '%';
      *o++ = hex[c >> 4];
      *o++ = hex[c & 15];
    }
  }
  sprintf(o, "/resources%s", trailing_slash ? "/" : "");
  return uri;
}

static int read_outputs(const run_setup* s, fmi2Component c, const char* instance, double time,
                        double* values) {
  size_t i;
  if (s->info->output_count == 0) return 0;
  if (check_status(s->api->fmi2GetReal(c, s->info->outputs, s->info->output_count, values),
                   "fmi2GetReal", instance) != 0) {
    return 1;
  }
  for (i = 0; i < s->info->output_count; ++i) {
    if (isnan(values[i])) {
      return fail("%s: output valueReference %u is NaN at t=%g", instance, s->info->outputs[i],
                  time);
    }
  }
  return 0;
}

static fmi2Component instantiate(const run_setup* s, const char* instance, const char* uri) {
  fmi2Component c = s->api->fmi2Instantiate(instance, fmi2CoSimulation, s->info->guid, uri,
                                            s->callbacks, fmi2False, fmi2False);
  if (c == NULL) fail("fmi2Instantiate(%s, \"%s\") returned NULL", instance, uri);
  return c;
}

static int initialize(const run_setup* s, fmi2Component c, const char* instance) {
  return check_status(
             s->api->fmi2SetupExperiment(c, fmi2False, 0.0, s->info->start_time, fmi2False, 0.0),
             "fmi2SetupExperiment", instance) ||
         check_status(s->api->fmi2EnterInitializationMode(c), "fmi2EnterInitializationMode",
                      instance) ||
         check_status(s->api->fmi2ExitInitializationMode(c), "fmi2ExitInitializationMode",
                      instance);
}

static double time_at(const run_setup* s, int step) {
  return s->info->start_time + step * s->info->step_size;
}

static int do_step(const run_setup* s, fmi2Component c, const char* instance, int step,
                   double* values) {
  return check_status(s->api->fmi2DoStep(c, time_at(s, step), s->info->step_size, fmi2True),
                      "fmi2DoStep", instance) ||
         read_outputs(s, c, instance, time_at(s, step + 1), values);
}

static int finish(const run_setup* s, fmi2Component c, const char* instance) {
  int result = check_status(s->api->fmi2Terminate(c), "fmi2Terminate", instance);
  s->api->fmi2FreeInstance(c);
  return result;
}

/* One full lifecycle; `trace` receives (steps + 1) x outputs values. */
static int run_lifecycle(const run_setup* s, const char* instance, const char* uri, double* trace) {
  size_t n = s->info->output_count;
  int step;
  fmi2Component c = instantiate(s, instance, uri);
  if (c == NULL) return 1;
  if (initialize(s, c, instance) != 0 || read_outputs(s, c, instance, time_at(s, 0), trace) != 0) {
    s->api->fmi2FreeInstance(c);
    return 1;
  }
  for (step = 0; step < s->steps; ++step) {
    if (do_step(s, c, instance, step, trace + (size_t)(step + 1) * n) != 0) {
      s->api->fmi2FreeInstance(c);
      return 1;
    }
  }
  return finish(s, c, instance);
}

static int compare_traces(const run_setup* s, const double* expected, const double* actual,
                          const char* what) {
  size_t n = s->info->output_count;
  size_t i;
  for (i = 0; i < (size_t)(s->steps + 1) * n; ++i) {
    if (expected[i] != actual[i]) {
      return fail(
          "%s: output valueReference %u at t=%g is %.17g, the first run gave %.17g "
          "(state shared between instances or runs?)",
          what, s->info->outputs[i % n], time_at(s, (int)(i / n)), actual[i], expected[i]);
    }
  }
  return 0;
}

/* Two instances stepped alternately in one process. */
static int run_side_by_side(const run_setup* s, const char* uri, double* trace_a, double* trace_b) {
  size_t n = s->info->output_count;
  int step;
  int result = 0;
  fmi2Component a = instantiate(s, "instance_a", uri);
  fmi2Component b = a != NULL ? instantiate(s, "instance_b", uri) : NULL;
  if (a == NULL || b == NULL) {
    if (a != NULL) s->api->fmi2FreeInstance(a);
    return 1;
  }
  if (a == b) {
    result = fail("fmi2Instantiate returned the same component for two instances");
    s->api->fmi2FreeInstance(a);
    return result;
  }
  result = initialize(s, a, "instance_a") || initialize(s, b, "instance_b") ||
           read_outputs(s, a, "instance_a", time_at(s, 0), trace_a) ||
           read_outputs(s, b, "instance_b", time_at(s, 0), trace_b);
  for (step = 0; step < s->steps && result == 0; ++step) {
    result = do_step(s, a, "instance_a", step, trace_a + (size_t)(step + 1) * n) ||
             do_step(s, b, "instance_b", step, trace_b + (size_t)(step + 1) * n);
  }
  if (result != 0) {
    s->api->fmi2FreeInstance(a);
    s->api->fmi2FreeInstance(b);
    return 1;
  }
  /* b must survive a's end untouched */
  result = finish(s, a, "instance_a");
  if (result == 0 && n > 0) {
    double* again = malloc(n * sizeof *again);
    if (again == NULL) {
      result = fail("out of memory");
    } else {
      result = read_outputs(s, b, "instance_b", time_at(s, s->steps), again);
      if (result == 0 && memcmp(again, trace_b + (size_t)s->steps * n, n * sizeof *again) != 0) {
        result = fail("instance_b's outputs changed when instance_a was freed");
      }
      free(again);
    }
  }
  if (result != 0) {
    s->api->fmi2FreeInstance(b);
    return 1;
  }
  return finish(s, b, "instance_b");
}

static int check_wrong_guid(const run_setup* s, const char* uri) {
  int logs_before = g_log_count;
  fmi2Component c = s->api->fmi2Instantiate("wrong_guid", fmi2CoSimulation,
                                            "{00000000-0000-0000-0000-000000000000}-wrong", uri,
                                            s->callbacks, fmi2False, fmi2False);
  if (c != NULL) {
    s->api->fmi2FreeInstance(c);
    return fail("fmi2Instantiate accepted a wrong GUID (the binary must compare it with \"%s\")",
                s->info->guid);
  }
  if (g_log_count == logs_before) {
    return fail("fmi2Instantiate rejected a wrong GUID without a log message");
  }
  return 0;
}

/* Functions of capabilities the FMU does not declare must exist and return fmi2Error. They are
 * probed after initialization (state stepComplete), where the state machine allows both calls,
 * so the error can only mean "not supported". */
static int check_unsupported(const run_setup* s, const char* uri) {
  const char* instance = "unsupported_probe";
  int result = 0;
  fmi2Component c;
  if (s->info->can_get_and_set_fmu_state && s->info->provides_directional_derivative) return 0;
  c = instantiate(s, instance, uri);
  if (c == NULL) return 1;
  if (initialize(s, c, instance) != 0) {
    s->api->fmi2FreeInstance(c);
    return 1;
  }
  if (!s->info->can_get_and_set_fmu_state) {
    fmi2FMUstate state = NULL;
    int logs_before = g_log_count;
    fmi2Status st = s->api->fmi2GetFMUstate(c, &state);
    if (st != fmi2Error) {
      result = fail(
          "fmi2GetFMUstate returned %s, expected fmi2Error: the FMU does not declare "
          "canGetAndSetFMUstate",
          status_name(st));
    } else if (g_log_count == logs_before) {
      result = fail("fmi2GetFMUstate returned fmi2Error without a log message");
    }
  }
  if (result == 0 && !s->info->provides_directional_derivative) {
    fmi2ValueReference vr = s->info->output_count > 0 ? s->info->outputs[0] : 0;
    fmi2Real in = 1.0;
    fmi2Real out = 0.0;
    int logs_before = g_log_count;
    fmi2Status st = s->api->fmi2GetDirectionalDerivative(c, &vr, 1, &vr, 1, &in, &out);
    if (st != fmi2Error) {
      result = fail(
          "fmi2GetDirectionalDerivative returned %s, expected fmi2Error: the FMU does "
          "not declare providesDirectionalDerivative",
          status_name(st));
    } else if (g_log_count == logs_before) {
      result = fail("fmi2GetDirectionalDerivative returned fmi2Error without a log message");
    }
  }
  s->api->fmi2FreeInstance(c);
  if (result == 0) printf("fmu_importer: undeclared capabilities return fmi2Error\n");
  return result;
}

/* Steps `c` from step `from` to the end, comparing the outputs with `expected` (the first run). */
static int continue_and_compare(const run_setup* s, fmi2Component c, const char* instance, int from,
                                const double* expected, double* values) {
  size_t n = s->info->output_count;
  int step;
  for (step = from; step < s->steps; ++step) {
    if (do_step(s, c, instance, step, values) != 0) return 1;
    if (n > 0 && memcmp(values, expected + (size_t)(step + 1) * n, n * sizeof *values) != 0) {
      return fail(
          "%s: after restoring the state of step %d the outputs at t=%g differ from the "
          "first run",
          instance, from, time_at(s, step + 1));
    }
  }
  return 0;
}

/* A declared FMU state: saved halfway as bytes (fmi2SerializeFMUstate), the run goes on, then the
 * bytes are deserialized and set, in the same instance and in a second, fresh one: both must
 * repeat the second half of the first run bit for bit. */
static int check_state_round_trip(const run_setup* s, const char* uri, const double* expected) {
  const char* instance = "state_probe";
  const char* target = "state_target";
  size_t n = s->info->output_count;
  int half = s->steps / 2;
  int step;
  int result = 0;
  size_t size = 0;
  fmi2Byte* bytes = NULL;
  fmi2FMUstate state = NULL;
  double* values = malloc((n > 0 ? n : 1) * sizeof *values);
  fmi2Component c;
  fmi2Component d = NULL;
  if (!s->info->can_get_and_set_fmu_state || !s->info->can_serialize_fmu_state) {
    free(values);
    return 0;
  }
  if (values == NULL) return fail("out of memory");
  c = instantiate(s, instance, uri);
  if (c == NULL || initialize(s, c, instance) != 0) {
    if (c != NULL) s->api->fmi2FreeInstance(c);
    free(values);
    return 1;
  }
  for (step = 0; step < half && result == 0; ++step) result = do_step(s, c, instance, step, values);
  result = result ||
           check_status(s->api->fmi2GetFMUstate(c, &state), "fmi2GetFMUstate", instance) ||
           check_status(s->api->fmi2SerializedFMUstateSize(c, state, &size),
                        "fmi2SerializedFMUstateSize", instance);
  if (result == 0 && (bytes = malloc(size > 0 ? size : 1)) == NULL) result = fail("out of memory");
  result = result ||
           check_status(s->api->fmi2SerializeFMUstate(c, state, bytes, size),
                        "fmi2SerializeFMUstate", instance) ||
           check_status(s->api->fmi2FreeFMUstate(c, &state), "fmi2FreeFMUstate", instance) ||
           continue_and_compare(s, c, instance, half, expected, values);
  /* back to the saved moment in the same instance */
  state = NULL;
  result = result ||
           check_status(s->api->fmi2DeSerializeFMUstate(c, bytes, size, &state),
                        "fmi2DeSerializeFMUstate", instance) ||
           check_status(s->api->fmi2SetFMUstate(c, state), "fmi2SetFMUstate", instance) ||
           check_status(s->api->fmi2FreeFMUstate(c, &state), "fmi2FreeFMUstate", instance) ||
           continue_and_compare(s, c, instance, half, expected, values);
  /* and in a fresh instance, initialized as the first was */
  if (result == 0) {
    d = instantiate(s, target, uri);
    state = NULL;
    result = d == NULL || initialize(s, d, target) ||
             check_status(s->api->fmi2DeSerializeFMUstate(d, bytes, size, &state),
                          "fmi2DeSerializeFMUstate", target) ||
             check_status(s->api->fmi2SetFMUstate(d, state), "fmi2SetFMUstate", target) ||
             check_status(s->api->fmi2FreeFMUstate(d, &state), "fmi2FreeFMUstate", target) ||
             continue_and_compare(s, d, target, half, expected, values);
  }
  free(bytes);
  free(values);
  if (result != 0) {
    s->api->fmi2FreeInstance(c);
    if (d != NULL) s->api->fmi2FreeInstance(d);
    return 1;
  }
  result = finish(s, c, instance) || finish(s, d, target);
  if (result == 0) {
    printf(
        "fmu_importer: FMU state of step %d serialized (%zu bytes) and restored, in the same "
        "and in a fresh instance\n",
        half, size);
  }
  return result;
}

/* ---- --misuse: calls out of order and bad arguments, one fresh instance per case ----
 * FMI 2.0 (co-simulation state machine, section 4.2.4) allows each function only in some states.
 * Part 1 calls every function in every state it is not allowed in (with zero variables where it
 * takes some, so the state is the only thing wrong). Part 2 calls functions in stepComplete with
 * arguments no FMU can accept: null arrays, unknown value references, wrong types, outputs set,
 * non-finite inputs, h <= 0 or NaN times. Every case must come back as fmi2Error with a log
 * message and no crash; since only fmi2Reset or fmi2FreeInstance may follow an fmi2Error, each
 * case then resets the instance and requires one legal step to work again. */
enum misuse_state {
  at_instantiated = 1,
  at_initialization = 2,
  at_step_complete = 4,
  at_terminated = 8
};

static const char* misuse_state_name(int state) {
  switch (state) {
    case at_instantiated:
      return "instantiated";
    case at_initialization:
      return "initializationMode";
    case at_step_complete:
      return "stepComplete";
    default:
      return "terminated";
  }
}

typedef fmi2Status (*misuse_probe)(const run_setup* s, fmi2Component c);

#define PROBE(name, body)                                                        \
  static fmi2Status probe_##name(const run_setup* s, fmi2Component c) {          \
    const fmu_functions* f = s->api;                                             \
    fmi2ValueReference vr = s->info->output_count > 0 ? s->info->outputs[0] : 0; \
    fmi2Real real = 0.0;                                                         \
    fmi2Integer integer = 0;                                                     \
    fmi2Boolean boolean = fmi2False;                                             \
    fmi2String string = NULL;                                                    \
    fmi2Status status = fmi2OK;                                                  \
    fmi2FMUstate state = NULL;                                                   \
    (void)f, (void)vr, (void)real, (void)integer, (void)boolean, (void)string;   \
    (void)status, (void)state;                                                   \
    body                                                                         \
  }

/* part 1: the functions that depend on the state (all but those allowed everywhere) */
PROBE(setup_experiment,
      { return f->fmi2SetupExperiment(c, fmi2False, 0.0, s->info->start_time, fmi2False, 0.0); })
PROBE(enter_initialization, { return f->fmi2EnterInitializationMode(c); })
PROBE(exit_initialization, { return f->fmi2ExitInitializationMode(c); })
PROBE(terminate, { return f->fmi2Terminate(c); })
PROBE(get_real, { return f->fmi2GetReal(c, &vr, 0, &real); })
PROBE(get_integer, { return f->fmi2GetInteger(c, &vr, 0, &integer); })
PROBE(get_boolean, { return f->fmi2GetBoolean(c, &vr, 0, &boolean); })
PROBE(get_string, { return f->fmi2GetString(c, &vr, 0, &string); })
PROBE(set_real, { return f->fmi2SetReal(c, &vr, 0, &real); })
PROBE(set_integer, { return f->fmi2SetInteger(c, &vr, 0, &integer); })
PROBE(set_boolean, { return f->fmi2SetBoolean(c, &vr, 0, &boolean); })
PROBE(set_string, { return f->fmi2SetString(c, &vr, 0, &string); })
PROBE(get_directional_derivative,
      { return f->fmi2GetDirectionalDerivative(c, &vr, 0, &vr, 0, &real, &real); })
PROBE(set_real_input_derivatives,
      { return f->fmi2SetRealInputDerivatives(c, &vr, 0, &integer, &real); })
PROBE(get_real_output_derivatives,
      { return f->fmi2GetRealOutputDerivatives(c, &vr, 0, &integer, &real); })
PROBE(do_step, { return f->fmi2DoStep(c, s->info->start_time, s->info->step_size, fmi2True); })
PROBE(cancel_step, { return f->fmi2CancelStep(c); })
PROBE(get_status, { return f->fmi2GetStatus(c, fmi2DoStepStatus, &status); })
PROBE(get_real_status, { return f->fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &real); })
PROBE(get_integer_status, { return f->fmi2GetIntegerStatus(c, fmi2DoStepStatus, &integer); })
PROBE(get_boolean_status, { return f->fmi2GetBooleanStatus(c, fmi2Terminated, &boolean); })
PROBE(get_string_status, { return f->fmi2GetStringStatus(c, fmi2PendingStatus, &string); })

/* part 2: bad arguments in stepComplete */
PROBE(get_real_null_references, { return f->fmi2GetReal(c, NULL, 1, &real); })
PROBE(get_real_null_values, { return f->fmi2GetReal(c, &vr, 1, NULL); })
PROBE(set_real_null_values, {
  fmi2ValueReference in = s->info->real_input;
  return f->fmi2SetReal(c, &in, 1, NULL);
})
PROBE(get_real_unknown_reference, {
  fmi2ValueReference unknown = 0x7fffffffu;
  return f->fmi2GetReal(c, &unknown, 1, &real);
})
PROBE(set_real_unknown_reference, {
  fmi2ValueReference unknown = 0x7fffffffu;
  return f->fmi2SetReal(c, &unknown, 1, &real);
})
PROBE(get_integer_of_a_real, { return f->fmi2GetInteger(c, &vr, 1, &integer); })
PROBE(get_boolean_of_a_real, { return f->fmi2GetBoolean(c, &vr, 1, &boolean); })
PROBE(get_string_of_a_real, { return f->fmi2GetString(c, &vr, 1, &string); })
PROBE(set_real_on_an_output, { return f->fmi2SetReal(c, &vr, 1, &real); })
PROBE(set_real_nan_input, {
  fmi2ValueReference in = s->info->real_input;
  real = NAN;
  return f->fmi2SetReal(c, &in, 1, &real);
})
PROBE(set_real_infinite_input, {
  fmi2ValueReference in = s->info->real_input;
  real = INFINITY;
  return f->fmi2SetReal(c, &in, 1, &real);
})
PROBE(do_step_zero_step, { return f->fmi2DoStep(c, s->info->start_time, 0.0, fmi2True); })
PROBE(do_step_negative_step,
      { return f->fmi2DoStep(c, s->info->start_time, -s->info->step_size, fmi2True); })
PROBE(do_step_nan_step, { return f->fmi2DoStep(c, s->info->start_time, NAN, fmi2True); })
PROBE(do_step_nan_time, { return f->fmi2DoStep(c, NAN, s->info->step_size, fmi2True); })
PROBE(get_fmu_state_null, { return f->fmi2GetFMUstate(c, NULL); })
PROBE(set_fmu_state_unknown, {
  state = &real; /* not a state this FMU handed out */
  return f->fmi2SetFMUstate(c, state);
})
PROBE(get_status_null, { return f->fmi2GetRealStatus(c, fmi2LastSuccessfulTime, NULL); })

typedef struct {
  const char* what;
  misuse_probe probe;
  int allowed; /* states the function may be called in (part 1); 0 for part 2 */
  int needs;   /* 1: a Real output, 2: a Real input, 4: FMU state support */
} misuse_case;

static const misuse_case k_misuse_cases[] = {
    /* part 1: allowed states from the FMI 2.0 co-simulation state table */
    {"fmi2SetupExperiment", probe_setup_experiment, at_instantiated, 0},
    {"fmi2EnterInitializationMode", probe_enter_initialization, at_instantiated, 0},
    {"fmi2ExitInitializationMode", probe_exit_initialization, at_initialization, 0},
    {"fmi2Terminate", probe_terminate, at_step_complete, 0},
    {"fmi2GetReal", probe_get_real, at_initialization | at_step_complete | at_terminated, 0},
    {"fmi2GetInteger", probe_get_integer, at_initialization | at_step_complete | at_terminated, 0},
    {"fmi2GetBoolean", probe_get_boolean, at_initialization | at_step_complete | at_terminated, 0},
    {"fmi2GetString", probe_get_string, at_initialization | at_step_complete | at_terminated, 0},
    {"fmi2SetReal", probe_set_real, at_instantiated | at_initialization | at_step_complete, 0},
    {"fmi2SetInteger", probe_set_integer, at_instantiated | at_initialization | at_step_complete,
     0},
    {"fmi2SetBoolean", probe_set_boolean, at_instantiated | at_initialization | at_step_complete,
     0},
    {"fmi2SetString", probe_set_string, at_instantiated | at_initialization | at_step_complete, 0},
    {"fmi2GetDirectionalDerivative", probe_get_directional_derivative,
     at_initialization | at_step_complete | at_terminated, 0},
    {"fmi2SetRealInputDerivatives", probe_set_real_input_derivatives,
     at_instantiated | at_initialization | at_step_complete, 0},
    {"fmi2GetRealOutputDerivatives", probe_get_real_output_derivatives,
     at_step_complete | at_terminated, 0},
    {"fmi2DoStep", probe_do_step, at_step_complete, 0},
    {"fmi2CancelStep", probe_cancel_step, 0 /* stepInProgress only */, 0},
    {"fmi2GetStatus", probe_get_status, at_step_complete | at_terminated, 0},
    {"fmi2GetRealStatus", probe_get_real_status, at_step_complete | at_terminated, 0},
    {"fmi2GetIntegerStatus", probe_get_integer_status, at_step_complete | at_terminated, 0},
    {"fmi2GetBooleanStatus", probe_get_boolean_status, at_step_complete | at_terminated, 0},
    {"fmi2GetStringStatus", probe_get_string_status, at_step_complete | at_terminated, 0},
};

static const misuse_case k_bad_argument_cases[] = {
    {"fmi2GetReal with null value references", probe_get_real_null_references, 0, 1},
    {"fmi2GetReal with a null value array", probe_get_real_null_values, 0, 1},
    {"fmi2SetReal with a null value array", probe_set_real_null_values, 0, 2},
    {"fmi2GetReal of an unknown value reference", probe_get_real_unknown_reference, 0, 0},
    {"fmi2SetReal of an unknown value reference", probe_set_real_unknown_reference, 0, 0},
    {"fmi2GetInteger of a Real variable", probe_get_integer_of_a_real, 0, 1},
    {"fmi2GetBoolean of a Real variable", probe_get_boolean_of_a_real, 0, 1},
    {"fmi2GetString of a Real variable", probe_get_string_of_a_real, 0, 1},
    {"fmi2SetReal on an output", probe_set_real_on_an_output, 0, 1},
    {"fmi2SetReal of NaN on an input", probe_set_real_nan_input, 0, 2},
    {"fmi2SetReal of infinity on an input", probe_set_real_infinite_input, 0, 2},
    {"fmi2DoStep with h = 0", probe_do_step_zero_step, 0, 0},
    {"fmi2DoStep with h < 0", probe_do_step_negative_step, 0, 0},
    {"fmi2DoStep with h = NaN", probe_do_step_nan_step, 0, 0},
    {"fmi2DoStep at t = NaN", probe_do_step_nan_time, 0, 0},
    {"fmi2GetFMUstate into a null pointer", probe_get_fmu_state_null, 0, 4},
    {"fmi2SetFMUstate of a state it never made", probe_set_fmu_state_unknown, 0, 4},
    {"fmi2GetRealStatus into a null pointer", probe_get_status_null, 0, 0},
};

static int reach(const run_setup* s, fmi2Component c, int state) {
  const char* instance = "misuse";
  if (state == at_instantiated) return 0;
  if (state == at_initialization) {
    return check_status(
               s->api->fmi2SetupExperiment(c, fmi2False, 0.0, s->info->start_time, fmi2False, 0.0),
               "fmi2SetupExperiment", instance) ||
           check_status(s->api->fmi2EnterInitializationMode(c), "fmi2EnterInitializationMode",
                        instance);
  }
  if (initialize(s, c, instance) != 0) return 1;
  if (state == at_terminated) {
    return check_status(s->api->fmi2Terminate(c), "fmi2Terminate", instance);
  }
  return 0;
}

/* One case: fresh instance, the state, the call (fmi2Error + a message), reset, a legal step. */
static int misuse_once(const run_setup* s, const char* uri, const misuse_case* m, int state,
                       double* outputs) {
  int logs_before;
  fmi2Status st;
  fmi2Component c = instantiate(s, "misuse", uri);
  if (c == NULL) return 1;
  if (reach(s, c, state) != 0) {
    s->api->fmi2FreeInstance(c);
    return fail("misuse: could not reach %s for \"%s\"", misuse_state_name(state), m->what);
  }
  logs_before = g_log_count;
  st = m->probe(s, c);
  if (st != fmi2Error || g_log_count == logs_before) {
    s->api->fmi2FreeInstance(c);
    return fail("%s in %s returned %s%s, expected fmi2Error with a message", m->what,
                misuse_state_name(state), status_name(st),
                g_log_count == logs_before ? " without a message" : "");
  }
  if (check_status(s->api->fmi2Reset(c), "fmi2Reset", "misuse") != 0 ||
      initialize(s, c, "misuse") != 0 || do_step(s, c, "misuse", 0, outputs) != 0 ||
      finish(s, c, "misuse") != 0) {
    return fail("after %s in %s the instance did not run again after fmi2Reset", m->what,
                misuse_state_name(state));
  }
  return 0;
}

static int check_misuse(const run_setup* s, const char* uri) {
  static const int states[] = {at_instantiated, at_initialization, at_step_complete, at_terminated};
  size_t i;
  size_t k;
  int calls = 0;
  int result = 0;
  double* outputs = calloc(s->info->output_count > 0 ? s->info->output_count : 1, sizeof(double));
  if (outputs == NULL) return fail("out of memory");
  for (i = 0; i < sizeof k_misuse_cases / sizeof k_misuse_cases[0] && result == 0; ++i) {
    for (k = 0; k < sizeof states / sizeof states[0] && result == 0; ++k) {
      if ((k_misuse_cases[i].allowed & states[k]) != 0) continue;
      result = misuse_once(s, uri, &k_misuse_cases[i], states[k], outputs);
      ++calls;
    }
  }
  for (i = 0; i < sizeof k_bad_argument_cases / sizeof k_bad_argument_cases[0] && result == 0;
       ++i) {
    const misuse_case* m = &k_bad_argument_cases[i];
    if (((m->needs & 1) && s->info->output_count == 0) ||
        ((m->needs & 2) && !s->info->has_real_input) ||
        ((m->needs & 4) && !s->info->can_get_and_set_fmu_state)) {
      printf("fmu_importer: not applicable to this FMU: %s\n", m->what);
      continue;
    }
    result = misuse_once(s, uri, m, at_step_complete, outputs);
    ++calls;
  }
  free(outputs);
  if (result == 0) {
    printf("fmu_importer: %d calls out of order or with bad arguments returned fmi2Error\n", calls);
  }
  return result;
}

static int usage(void) {
  fprintf(stderr, "usage: fmu_importer FILE.fmu [--steps N] [--twice] [--no-compare] [--misuse]\n");
  return 2;
}

int main(int argc, char** argv) {
  const char* fmu = NULL;
  int steps = 100;
  int twice = 0;
  int compare = 1;
  int misuse = 0;
  int i;
  int result = 1;
  char dir[PATH_MAX] = "";
  char so_path[PATH_MAX];
  char shown_name[PATH_MAX];
  model_info info;
  void* handle = NULL;
  fmu_functions api;
  char* uri = NULL;
  char* uri_slash = NULL;
  double* traces[4] = {NULL, NULL, NULL, NULL};
  fmi2CallbackFunctions callbacks;
  run_setup setup;
  size_t trace_size;

  memset(&info, 0, sizeof info);
  for (i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--twice") == 0) {
      twice = 1;
    } else if (strcmp(argv[i], "--no-compare") == 0) {
      compare = 0;
    } else if (strcmp(argv[i], "--misuse") == 0) {
      misuse = 1;
    } else if (strcmp(argv[i], "--steps") == 0 && i + 1 < argc) {
      char* stop = NULL;
      long n = strtol(argv[++i], &stop, 10);
      if (*stop != '\0' || n < 0 || n > 10000000) return usage();
      steps = (int)n;
    } else if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
      usage();
      return 0;
    } else if (argv[i][0] == '-' || fmu != NULL) {
      return usage();
    } else {
      fmu = argv[i];
    }
  }
  if (fmu == NULL) return usage();

  if (make_temp_dir(dir, sizeof dir, "fmu_importer_") != 0) return 1;

  if (unzip_fmu(fmu, dir) != 0 || read_model_description(dir, &info) != 0) goto cleanup;
  printf("fmu_importer: %s: guid %s, modelIdentifier %s, %zu Real outputs, step %g\n", fmu,
         info.guid, info.model_identifier, info.output_count, info.step_size);

  if ((size_t)snprintf(so_path, sizeof so_path, "%s/binaries/linux64/%s.so", dir,
                       info.model_identifier) >= sizeof so_path) {
    fail("path of the binary is too long");
    goto cleanup;
  }
  if (access(so_path, R_OK) != 0) {
    fail("the FMU has no binaries/linux64/%s.so", info.model_identifier);
    goto cleanup;
  }
  snprintf(shown_name, sizeof shown_name, "binaries/linux64/%s.so", info.model_identifier);
  if (load_functions(so_path, shown_name, &handle, &api) != 0) goto cleanup;

  if (api.fmi2GetVersion() == NULL || strcmp(api.fmi2GetVersion(), "2.0") != 0) {
    fail("fmi2GetVersion() returned \"%s\", expected \"2.0\"",
         api.fmi2GetVersion() != NULL ? api.fmi2GetVersion() : "(null)");
    goto cleanup;
  }
  if (api.fmi2GetTypesPlatform() == NULL || strcmp(api.fmi2GetTypesPlatform(), "default") != 0) {
    fail("fmi2GetTypesPlatform() returned \"%s\", expected \"default\"",
         api.fmi2GetTypesPlatform() != NULL ? api.fmi2GetTypesPlatform() : "(null)");
    goto cleanup;
  }

  uri = resource_uri(dir, 0);
  uri_slash = resource_uri(dir, 1);
  trace_size = (size_t)(steps + 1) * (info.output_count > 0 ? info.output_count : 1);
  for (i = 0; i < 4; ++i) traces[i] = calloc(trace_size, sizeof(double));
  if (uri == NULL || uri_slash == NULL || traces[0] == NULL || traces[1] == NULL ||
      traces[2] == NULL || traces[3] == NULL) {
    fail("out of memory");
    goto cleanup;
  }
  callbacks.logger = importer_logger;
  callbacks.allocateMemory = calloc;
  callbacks.freeMemory = free;
  callbacks.stepFinished = NULL;
  callbacks.componentEnvironment = NULL;
  setup.api = &api;
  setup.info = &info;
  setup.callbacks = &callbacks;
  setup.steps = steps;

  if (misuse) {
    if (check_misuse(&setup, uri) == 0) {
      result = 0;
      printf("fmu_importer: OK %s\n", fmu);
    }
    goto cleanup;
  }
  if (run_lifecycle(&setup, "run_1", uri, traces[0]) != 0) goto cleanup;
  printf("fmu_importer: lifecycle 1 passed (%d steps)\n", steps);
  if (check_wrong_guid(&setup, uri) != 0) goto cleanup;
  printf("fmu_importer: wrong GUID rejected\n");
  if (check_unsupported(&setup, uri) != 0) goto cleanup;
  if (compare && check_state_round_trip(&setup, uri, traces[0]) != 0) goto cleanup;
  if (twice) {
    if (run_lifecycle(&setup, "run_2", uri_slash, traces[1]) != 0) goto cleanup;
    if (compare && compare_traces(&setup, traces[0], traces[1], "run_2") != 0) goto cleanup;
    printf("fmu_importer: lifecycle 2 passed (resource URI with trailing '/')\n");
    if (info.only_once_per_process) {
      printf("fmu_importer: canBeInstantiatedOnlyOncePerProcess: side-by-side run skipped\n");
    } else {
      if (run_side_by_side(&setup, uri, traces[2], traces[3]) != 0) goto cleanup;
      if (compare && (compare_traces(&setup, traces[0], traces[2], "instance_a") != 0 ||
                      compare_traces(&setup, traces[0], traces[3], "instance_b") != 0)) {
        goto cleanup;
      }
      printf("fmu_importer: two instances side by side passed\n");
    }
  }
  result = 0;
  printf("fmu_importer: OK %s\n", fmu);

cleanup:
  for (i = 0; i < 4; ++i) free(traces[i]);
  free(uri);
  free(uri_slash);
  if (handle != NULL && dlclose(handle) != 0) {
    result = fail("dlclose: %s", dlerror());
  }
  free_model_info(&info);
  remove_tree(dir);
  return result;
}
