/* fmu3_importer: a foreign FMI 3.0 Co-Simulation importer in plain C11 (declarations in
 * fmu3_importer.h, written from the standard; libc, libdl and libzip only).
 *
 * usage: fmu3_importer FILE.fmu [--steps N] [--twice] [--misuse]
 *
 * Unzips the FMU into a fresh temp directory, reads modelDescription.xml (fmu3_model.c), loads
 * binaries/x86_64-linux/<modelIdentifier>.so, resolves all 75 fmi3 functions (every FMU exports
 * them all, whatever its interface types) and runs
 *   GetVersion -> InstantiateCoSimulation -> Set start values of parameters and inputs (arrays
 *   with nValues = their size) -> EnterInitializationMode -> Get every output ->
 *   ExitInitializationMode -> N x (Set inputs, DoStep, Get every output) -> Terminate -> Free.
 * Then a wrong instantiationToken must give NULL with a log message, and when the FMU declares
 * canGetAndSetFMUState the state of the halfway step is taken, kept and (with
 * canSerializeFMUState) serialized; the run goes on, and the state set again, in the same
 * instance and in a fresh one, must repeat the second half bit for bit.
 * --twice runs the lifecycle again and two instances side by side, comparing every output trace
 * with the first run. --misuse runs the misuse suite instead (fmu3_misuse.c).
 * Exit status: 0 on success, 1 on a failed check, 2 on a usage error.
 */
#define _XOPEN_SOURCE 700

#include "fmu3_importer.h"

#include <dlfcn.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fmu_archive.h"

const char* const fmu_program_name = "fmu3_importer";

int fmu3_log_count = 0;

/* Counts and prints the messages that report a problem; an FMU may log every call at fmi3OK
 * (its own categories), which would drown the rest and says nothing about a rejected call. */
void fmu3_log_message(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                      fmi3String message) {
  (void)env;
  if (status == fmi3OK) return;
  ++fmu3_log_count;
  printf("  [fmu log] %s (%s): %s\n", fmu3_status_name(status), category != NULL ? category : "",
         message != NULL ? message : "(null)");
  fflush(stdout);
}

const char* fmu3_status_name(fmi3Status status) {
  static const char* const names[] = {"fmi3OK", "fmi3Warning", "fmi3Discard", "fmi3Error",
                                      "fmi3Fatal"};
  return (unsigned)status < 5u ? names[status] : "(invalid status)";
}

/* fmi3OK and fmi3Warning let the simulation go on; anything else fails the run. */
int fmu3_check(fmi3Status status, const char* call, const char* instance) {
  if (status == fmi3OK || status == fmi3Warning) return 0;
  return fail("%s(%s) returned %s", call, instance, fmu3_status_name(status));
}

static int load_functions(const char* so_path, void** handle, fmu3_functions* api) {
  char missing[4096] = "";
  size_t missing_count = 0;
  void* symbol;
  *handle = dlopen(so_path, RTLD_NOW | RTLD_LOCAL);
  if (*handle == NULL) return fail("cannot load %s: %s", so_path, dlerror());
  memset(api, 0, sizeof *api);
  /* POSIX guarantees that a data pointer from dlsym converts to a function pointer. */
#define FMU3_RESOLVE(name, type)                                                           \
  symbol = dlsym(*handle, #name);                                                          \
  if (symbol == NULL) {                                                                    \
    if (missing_count++ > 0) strncat(missing, ", ", sizeof missing - strlen(missing) - 1); \
    strncat(missing, #name, sizeof missing - strlen(missing) - 1);                         \
  } else {                                                                                 \
    memcpy(&api->name, &symbol, sizeof symbol);                                            \
  }
  FMU3_FUNCTIONS(FMU3_RESOLVE)
#undef FMU3_RESOLVE
  if (missing_count > 0) {
    dlclose(*handle);
    *handle = NULL;
    return fail("the FMU does not export %zu of the %d FMI 3.0 functions: %s", missing_count,
                FMU3_FUNCTION_COUNT, missing);
  }
  return 0;
}

/* ---- one run */

fmi3Instance fmu3_instantiate(const fmu3_setup* s, const char* instance) {
  fmi3Instance c = s->api.fmi3InstantiateCoSimulation(instance, s->model.token, s->resource_path,
                                                      fmi3False, fmi3True, fmi3False, fmi3False,
                                                      NULL, 0, NULL, fmu3_log_message, NULL);
  if (c == NULL) fail("fmi3InstantiateCoSimulation(%s) returned NULL", instance);
  return c;
}

double fmu3_time_at(const fmu3_setup* s, int step) {
  return s->model.start_time + step * s->model.step_size;
}

/* Sets every input (inputs) and every parameter (parameters) to its start value. */
static int set_starts(const fmu3_setup* s, fmi3Instance c, const char* instance, int inputs,
                      int parameters) {
  size_t i;
  for (i = 0; i < s->model.variable_count; ++i) {
    const fmu3_variable* v = &s->model.variables[i];
    fmi3Status status;
    if (!((inputs && v->causality == c_input) || (parameters && v->causality == c_parameter))) {
      continue;
    }
    status = fmu3_set_start(&s->api, c, v);
    if (status == fmi3Fatal) return 1; /* start values unreadable, already reported */
    if (status != fmi3OK && status != fmi3Warning) {
      return fail("fmi3Set%s(%s) of %s (valueReference %u, %zu values) returned %s",
                  fmu3_type_name(v->type), instance, v->name, v->vr, v->size,
                  fmu3_status_name(status));
    }
  }
  return 0;
}

/* Appends every output of `c` to `outputs`. */
static int read_outputs(const fmu3_setup* s, fmi3Instance c, const char* instance, double time,
                        fmu3_bytes* outputs) {
  size_t i;
  for (i = 0; i < s->model.variable_count; ++i) {
    const fmu3_variable* v = &s->model.variables[i];
    if (v->causality != c_output || v->type == t_clock) continue;
    if (fmu3_append_values(&s->api, c, instance, v, time, outputs) != 0) return 1;
  }
  return 0;
}

int fmu3_initialize(const fmu3_setup* s, fmi3Instance c, const char* instance) {
  return set_starts(s, c, instance, 1, 1) ||
         fmu3_check(s->api.fmi3EnterInitializationMode(c, fmi3False, 0.0, s->model.start_time,
                                                       fmi3False, 0.0),
                    "fmi3EnterInitializationMode", instance) ||
         fmu3_check(s->api.fmi3ExitInitializationMode(c), "fmi3ExitInitializationMode", instance);
}

int fmu3_step(const fmu3_setup* s, fmi3Instance c, const char* instance, int step,
              fmu3_bytes* outputs) {
  fmi3Boolean event = fmi3True;
  fmi3Boolean terminate = fmi3True;
  fmi3Boolean early = fmi3True;
  fmi3Float64 reached = -1.0;
  double t = fmu3_time_at(s, step);
  if (set_starts(s, c, instance, 1, 0) != 0 ||
      fmu3_check(s->api.fmi3DoStep(c, t, s->model.step_size, fmi3False, &event, &terminate, &early,
                                   &reached),
                 "fmi3DoStep", instance) != 0) {
    return 1;
  }
  /* no event mode, no early return allowed: a full step, and nothing to handle. The FMU may
   * keep its own time as a running sum of the steps, which drifts from t + h by rounding only */
  if (event || terminate || early ||
      !(fabs(reached - (t + s->model.step_size)) <= 1e-9 * s->model.step_size)) {
    return fail(
        "fmi3DoStep(%s) at t=%g: eventHandlingNeeded=%d terminateSimulation=%d earlyReturn=%d "
        "lastSuccessfulTime=%.17g, expected 0 0 0 %.17g",
        instance, t, event, terminate, early, reached, t + s->model.step_size);
  }
  outputs->size = 0;
  return read_outputs(s, c, instance, fmu3_time_at(s, step + 1), outputs);
}

int fmu3_finish(const fmu3_setup* s, fmi3Instance c, const char* instance) {
  int result = fmu3_check(s->api.fmi3Terminate(c), "fmi3Terminate", instance);
  s->api.fmi3FreeInstance(c);
  return result;
}

/* A trace: the outputs after initialization and after each step. */
typedef struct {
  fmu3_bytes* at; /* steps + 1 */
  int count;
} trace;

static int trace_init(trace* t, int steps) {
  t->count = steps + 1;
  t->at = calloc((size_t)t->count, sizeof *t->at);
  return t->at == NULL ? fail("out of memory") : 0;
}

static void trace_free(trace* t) {
  int i;
  for (i = 0; t->at != NULL && i < t->count; ++i) free(t->at[i].data);
  free(t->at);
  t->at = NULL;
}

static int same_outputs(const fmu3_bytes* a, const fmu3_bytes* b) {
  return a->size == b->size && (a->size == 0 || memcmp(a->data, b->data, a->size) == 0);
}

static int compare_traces(const fmu3_setup* s, const trace* expected, const trace* actual,
                          const char* what) {
  int i;
  for (i = 0; i < expected->count; ++i) {
    if (!same_outputs(&expected->at[i], &actual->at[i])) {
      return fail("%s: the outputs at t=%g differ from the first run (state shared?)", what,
                  fmu3_time_at(s, i));
    }
  }
  return 0;
}

/* Instantiated, start values set, initialized with the outputs of Initialization Mode read. */
static fmi3Instance start_run(const fmu3_setup* s, const char* instance, fmu3_bytes* outputs) {
  fmi3Instance c = fmu3_instantiate(s, instance);
  if (c == NULL) return NULL;
  outputs->size = 0;
  /* nCategories == 0: every category on (fmu3_log_message shows only the problems) */
  if (fmu3_check(s->api.fmi3SetDebugLogging(c, fmi3True, 0, NULL), "fmi3SetDebugLogging",
                 instance) != 0 ||
      set_starts(s, c, instance, 1, 1) != 0 ||
      fmu3_check(s->api.fmi3EnterInitializationMode(c, fmi3False, 0.0, s->model.start_time,
                                                    fmi3False, 0.0),
                 "fmi3EnterInitializationMode", instance) != 0 ||
      read_outputs(s, c, instance, s->model.start_time, outputs) != 0 ||
      fmu3_check(s->api.fmi3ExitInitializationMode(c), "fmi3ExitInitializationMode", instance)) {
    s->api.fmi3FreeInstance(c);
    return NULL;
  }
  return c;
}

/* A whole run; Terminated still answers fmi3Get with the final values, those of the last step. */
static int run_lifecycle(const fmu3_setup* s, const char* instance, trace* t) {
  int step;
  int result = 0;
  fmu3_bytes final = {NULL, 0, 0};
  fmi3Instance c = start_run(s, instance, &t->at[0]);
  if (c == NULL) return 1;
  for (step = 0; step < s->steps && result == 0; ++step) {
    result = fmu3_step(s, c, instance, step, &t->at[step + 1]);
  }
  result = result || fmu3_check(s->api.fmi3Terminate(c), "fmi3Terminate", instance) ||
           read_outputs(s, c, instance, fmu3_time_at(s, s->steps), &final);
  if (result == 0 && !same_outputs(&final, &t->at[s->steps])) {
    result = fail("%s: the outputs read after fmi3Terminate differ from those of the last step",
                  instance);
  }
  free(final.data);
  s->api.fmi3FreeInstance(c);
  return result;
}

/* Two instances stepped alternately in one process; b must outlive a untouched. */
static int run_side_by_side(const fmu3_setup* s, trace* a_trace, trace* b_trace) {
  int step;
  int result = 0;
  fmu3_bytes again = {NULL, 0, 0};
  fmi3Instance a = start_run(s, "instance_a", &a_trace->at[0]);
  fmi3Instance b = a != NULL ? start_run(s, "instance_b", &b_trace->at[0]) : NULL;
  if (b == NULL) {
    if (a != NULL) s->api.fmi3FreeInstance(a);
    return 1;
  }
  if (a == b) result = fail("two instantiations returned the same instance");
  for (step = 0; step < s->steps && result == 0; ++step) {
    result = fmu3_step(s, a, "instance_a", step, &a_trace->at[step + 1]) ||
             fmu3_step(s, b, "instance_b", step, &b_trace->at[step + 1]);
  }
  if (result == 0) {
    result = fmu3_finish(s, a, "instance_a");
    a = NULL;
  }
  if (result == 0) {
    result = read_outputs(s, b, "instance_b", fmu3_time_at(s, s->steps), &again);
    if (result == 0 && !same_outputs(&again, &b_trace->at[s->steps])) {
      result = fail("instance_b's outputs changed when instance_a was freed");
    }
  }
  free(again.data);
  if (result != 0) {
    if (a != NULL) s->api.fmi3FreeInstance(a);
    s->api.fmi3FreeInstance(b);
    return 1;
  }
  return fmu3_finish(s, b, "instance_b");
}

static int check_wrong_token(const fmu3_setup* s) {
  int logs_before = fmu3_log_count;
  fmi3Instance c = s->api.fmi3InstantiateCoSimulation(
      "wrong_token", "{00000000-0000-0000-0000-000000000000}", s->resource_path, fmi3False,
      fmi3True, fmi3False, fmi3False, NULL, 0, NULL, fmu3_log_message, NULL);
  if (c != NULL) {
    s->api.fmi3FreeInstance(c);
    return fail("fmi3InstantiateCoSimulation accepted a wrong instantiationToken (not \"%s\")",
                s->model.token);
  }
  if (fmu3_log_count == logs_before) {
    return fail("fmi3InstantiateCoSimulation refused a wrong instantiationToken without a message");
  }
  printf("fmu3_importer: wrong instantiationToken refused\n");
  return 0;
}

/* Steps `c` from step `from` to the end; every output must equal the first run's. */
static int continue_and_compare(const fmu3_setup* s, fmi3Instance c, const char* instance, int from,
                                const trace* expected) {
  int step;
  int result = 0;
  fmu3_bytes values = {NULL, 0, 0};
  for (step = from; step < s->steps && result == 0; ++step) {
    result = fmu3_step(s, c, instance, step, &values);
    if (result == 0 && !same_outputs(&values, &expected->at[step + 1])) {
      result = fail(
          "%s: after restoring the state of step %d the outputs at t=%g differ from "
          "the first run",
          instance, from, fmu3_time_at(s, step + 1));
    }
  }
  free(values.data);
  return result;
}

/* The halfway state, kept as fmi3FMUState and as bytes, rewinds the run: in the same instance
 * (both forms) and in a fresh one (the bytes), the second half must repeat the first run. */
static int check_state_round_trip(const fmu3_setup* s, const trace* expected) {
  const char* instance = "state_probe";
  const char* target = "state_target";
  const fmi3Instance none = NULL;
  int half = s->steps / 2;
  int step;
  int result = 0;
  size_t size = 0;
  fmi3Byte* bytes = NULL;
  fmi3FMUState kept = NULL;
  fmi3FMUState state = NULL;
  fmu3_bytes scratch = {NULL, 0, 0};
  fmi3Instance c;
  fmi3Instance d = none;
  if (!s->model.can_get_and_set_fmu_state) return 0;
  c = start_run(s, instance, &scratch);
  if (c == NULL) return 1;
  for (step = 0; step < half && result == 0; ++step) {
    result = fmu3_step(s, c, instance, step, &scratch);
  }
  free(scratch.data);
  result = result || fmu3_check(s->api.fmi3GetFMUState(c, &kept), "fmi3GetFMUState", instance);
  if (result == 0 && s->model.can_serialize_fmu_state) {
    result = fmu3_check(s->api.fmi3SerializedFMUStateSize(c, kept, &size),
                        "fmi3SerializedFMUStateSize", instance);
    if (result == 0 && (bytes = malloc(size > 0 ? size : 1)) == NULL) result = fail("no memory");
    result = result || fmu3_check(s->api.fmi3SerializeFMUState(c, kept, bytes, size),
                                  "fmi3SerializeFMUState", instance);
  }
  result = result || continue_and_compare(s, c, instance, half, expected) ||
           fmu3_check(s->api.fmi3SetFMUState(c, kept), "fmi3SetFMUState", instance) ||
           continue_and_compare(s, c, instance, half, expected);
  if (kept != NULL) {
    result = fmu3_check(s->api.fmi3FreeFMUState(c, &kept), "fmi3FreeFMUState", instance) || result;
    if (kept != NULL) result = fail("fmi3FreeFMUState did not set the state pointer to NULL");
  }
  if (result == 0 && bytes != NULL) {
    result = fmu3_check(s->api.fmi3DeserializeFMUState(c, bytes, size, &state),
                        "fmi3DeserializeFMUState", instance) ||
             fmu3_check(s->api.fmi3SetFMUState(c, state), "fmi3SetFMUState", instance) ||
             fmu3_check(s->api.fmi3FreeFMUState(c, &state), "fmi3FreeFMUState", instance) ||
             continue_and_compare(s, c, instance, half, expected);
    scratch.data = NULL;
    scratch.size = scratch.capacity = 0;
    d = result == 0 ? start_run(s, target, &scratch) : NULL;
    free(scratch.data);
    state = NULL;
    result = result || d == NULL ||
             fmu3_check(s->api.fmi3DeserializeFMUState(d, bytes, size, &state),
                        "fmi3DeserializeFMUState", target) ||
             fmu3_check(s->api.fmi3SetFMUState(d, state), "fmi3SetFMUState", target) ||
             fmu3_check(s->api.fmi3FreeFMUState(d, &state), "fmi3FreeFMUState", target) ||
             continue_and_compare(s, d, target, half, expected);
  }
  free(bytes);
  if (result != 0) {
    s->api.fmi3FreeInstance(c);
    if (d != NULL) s->api.fmi3FreeInstance(d);
    return 1;
  }
  result = fmu3_finish(s, c, instance) || (d != NULL && fmu3_finish(s, d, target));
  if (result == 0) {
    printf("fmu3_importer: FMU state of step %d restored in the same instance%s\n", half,
           d != NULL ? ", and serialized and restored in a fresh one" : "");
  }
  return result;
}

static int usage(void) {
  fprintf(stderr, "usage: fmu3_importer FILE.fmu [--steps N] [--twice] [--misuse]\n");
  return 2;
}

static int run_all(fmu3_setup* s, int twice, int misuse) {
  trace traces[3] = {{NULL, 0}, {NULL, 0}, {NULL, 0}};
  int result = 1;
  int i;
  const char* version = s->api.fmi3GetVersion();
  if (version == NULL || strcmp(version, "3.0") != 0) {
    return fail("fmi3GetVersion() returned \"%s\", expected \"3.0\"",
                version != NULL ? version : "(null)");
  }
  if (misuse) return fmu3_check_misuse(s);
  for (i = 0; i < 3; ++i) {
    if (trace_init(&traces[i], s->steps) != 0) goto done;
  }
  if (run_lifecycle(s, "run_1", &traces[0]) != 0) goto done;
  printf("fmu3_importer: lifecycle 1 passed (%d steps)\n", s->steps);
  if (check_wrong_token(s) != 0 || check_state_round_trip(s, &traces[0]) != 0) goto done;
  if (twice) {
    if (run_lifecycle(s, "run_2", &traces[1]) != 0 ||
        compare_traces(s, &traces[0], &traces[1], "run_2") != 0) {
      goto done;
    }
    printf("fmu3_importer: lifecycle 2 passed, outputs equal to the first\n");
    if (s->model.only_once_per_process) {
      printf("fmu3_importer: canBeInstantiatedOnlyOncePerProcess: no side-by-side run\n");
    } else {
      if (run_side_by_side(s, &traces[1], &traces[2]) != 0 ||
          compare_traces(s, &traces[0], &traces[1], "instance_a") != 0 ||
          compare_traces(s, &traces[0], &traces[2], "instance_b") != 0) {
        goto done;
      }
      printf("fmu3_importer: two instances side by side passed\n");
    }
  }
  result = 0;
done:
  for (i = 0; i < 3; ++i) trace_free(&traces[i]);
  return result;
}

int main(int argc, char** argv) {
  const char* fmu = NULL;
  int twice = 0;
  int misuse = 0;
  int i;
  int result = 1;
  char dir[PATH_MAX] = "";
  char path[PATH_MAX];
  char resources[PATH_MAX];
  void* handle = NULL;
  fmu3_setup setup;

  memset(&setup, 0, sizeof setup);
  setup.steps = 100;
  for (i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--twice") == 0) {
      twice = 1;
    } else if (strcmp(argv[i], "--misuse") == 0) {
      misuse = 1;
    } else if (strcmp(argv[i], "--steps") == 0 && i + 1 < argc) {
      char* stop = NULL;
      long n = strtol(argv[++i], &stop, 10);
      if (*stop != '\0' || n < 2 || n > 10000000) return usage();
      setup.steps = (int)n;
    } else if (argv[i][0] == '-' || fmu != NULL) {
      return usage();
    } else {
      fmu = argv[i];
    }
  }
  if (fmu == NULL) return usage();
  if (make_temp_dir(dir, sizeof dir, "fmu3_importer_") != 0) return 1;
  if (unzip_fmu(fmu, dir) != 0 || fmu3_read_model(dir, &setup.model) != 0) goto cleanup;
  printf("fmu3_importer: %s: instantiationToken %s, modelIdentifier %s, %zu variables, step %g\n",
         fmu, setup.model.token, setup.model.model_identifier, setup.model.variable_count,
         setup.model.step_size);
  if ((size_t)snprintf(path, sizeof path, "%s/binaries/x86_64-linux/%s.so", dir,
                       setup.model.model_identifier) >= sizeof path ||
      (size_t)snprintf(resources, sizeof resources, "%s/resources/", dir) >= sizeof resources) {
    fail("path of the binary is too long");
    goto cleanup;
  }
  if (access(path, R_OK) != 0) {
    fail("the FMU has no binaries/x86_64-linux/%s.so", setup.model.model_identifier);
    goto cleanup;
  }
  /* resourcePath is NULL when the FMU has no resources/ folder (docs/fmi3-rules.md §3) */
  setup.resource_path = access(resources, F_OK) == 0 ? resources : NULL;
  if (load_functions(path, &handle, &setup.api) != 0) goto cleanup;
  result = run_all(&setup, twice, misuse);
  if (result == 0) printf("fmu3_importer: OK %s\n", fmu);

cleanup:
  if (handle != NULL && dlclose(handle) != 0) result = fail("dlclose: %s", dlerror());
  fmu3_free_model(&setup.model);
  remove_tree(dir);
  return result;
}
