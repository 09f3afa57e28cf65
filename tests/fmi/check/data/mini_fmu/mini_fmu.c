/* mini_fmu: the smallest honest FMI 2.0 Co-Simulation FMU, a fixture for the FMU checks of
 * tests/fmi. dx/dt = -k x + u, outputs y = x and t = time, x(0) read from
 * resources/initial_state.txt. Each MINI_FMU_* macro builds a variant with one defect, so the
 * tests can show that the importer and the export check catch it.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define STRIDE_FMI2_BUILDING_FMU
#include "stride/fmi2/fmi2_api.h"

#define MINI_FMU_GUID "{5a3c1e7e-2b64-4d0f-9a51-6f0e0c1d2b3a}"

typedef struct {
  fmi2CallbackLogger logger;
  fmi2CallbackFreeMemory free_memory;
  fmi2ComponentEnvironment environment;
  char name[64];
  double x;
  double k;
  double u;
  double time;
} mini_instance;

#if defined(MINI_FMU_SHARED_STATE)
static double g_shared_x; /* the defect: state shared between instances */
#define STATE_X(m) g_shared_x
#else
#define STATE_X(m) ((m)->x)
#endif

static void log_error(const mini_instance* m, const char* message) {
  if (m != NULL && m->logger != NULL) {
    m->logger(m->environment, m->name, fmi2Error, "logStatusError", "%s", message);
  }
}

static fmi2Status unsupported(fmi2Component c, const char* function) {
  char message[128];
  snprintf(message, sizeof message, "%s is not supported by mini_fmu", function);
  log_error((const mini_instance*)c, message);
  return fmi2Error;
}

/* file:///a/b%20c/resources[/] -> /a/b c/resources */
static int resource_path(const char* uri, char* out, size_t size) {
  const char* p;
  size_t n = 0;
  if (uri == NULL || strncmp(uri, "file:", 5) != 0) return -1;
  p = uri + 5;
  if (strncmp(p, "///", 3) == 0) {
    p += 2;
  } else if (strncmp(p, "//localhost/", 12) == 0) {
    p += 11;
  }
  for (; *p != '\0' && n + 1 < size; ++p) {
    if (*p == '%' && p[1] != '\0' && p[2] != '\0') {
      char hex[3] = {p[1], p[2], '\0'};
      out[n++] = (char)strtol(hex, NULL, 16);
      p += 2;
    } else {
      out[n++] = *p;
    }
  }
  while (n > 1 && out[n - 1] == '/') --n;
  out[n] = '\0';
  return 0;
}

const char* fmi2GetTypesPlatform(void) {
  return "default";
}
const char* fmi2GetVersion(void) {
  return "2.0";
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
  (void)c;
  (void)loggingOn;
  (void)nCategories;
  (void)categories;
  return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions* functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn) {
  mini_instance probe;
  mini_instance* m;
  char path[4096];
  FILE* f;
  double x0 = 0.0;
  (void)visible;
  (void)loggingOn;
  if (functions == NULL || functions->logger == NULL) return NULL;
  memset(&probe, 0, sizeof probe);
  probe.logger = functions->logger;
  probe.environment = functions->componentEnvironment;
  snprintf(probe.name, sizeof probe.name, "%s", instanceName != NULL ? instanceName : "");
  if (fmuType != fmi2CoSimulation) {
    log_error(&probe, "mini_fmu is a Co-Simulation FMU only");
    return NULL;
  }
#if !defined(MINI_FMU_IGNORE_GUID)
  if (fmuGUID == NULL || strcmp(fmuGUID, MINI_FMU_GUID) != 0) {
    log_error(&probe, "Wrong GUID.");
    return NULL;
  }
#else
  (void)fmuGUID;
#endif
  if (resource_path(fmuResourceLocation, path, sizeof path - 32) != 0) {
    log_error(&probe, "fmuResourceLocation is not a file: URI");
    return NULL;
  }
  strcat(path, "/initial_state.txt");
  f = fopen(path, "r");
  if (f == NULL || fscanf(f, "%lf", &x0) != 1) {
    if (f != NULL) fclose(f);
    log_error(&probe, "cannot read initial_state.txt from fmuResourceLocation");
    return NULL;
  }
  fclose(f);
  m = functions->allocateMemory != NULL ? functions->allocateMemory(1, sizeof *m)
                                        : calloc(1, sizeof *m);
  if (m == NULL) {
    log_error(&probe, "out of memory");
    return NULL;
  }
  *m = probe;
  m->free_memory = functions->freeMemory != NULL ? functions->freeMemory : free;
  STATE_X(m) = x0;
  m->k = 2.0;
  m->u = 0.0;
  return m;
}

void fmi2FreeInstance(fmi2Component c) {
#if !defined(MINI_FMU_LEAK)
  mini_instance* m = (mini_instance*)c;
  if (m != NULL) m->free_memory(m);
#else
  (void)c;
#endif
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
  (void)toleranceDefined;
  (void)tolerance;
  (void)stopTimeDefined;
  (void)stopTime;
  ((mini_instance*)c)->time = startTime;
  return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  return c != NULL ? fmi2OK : fmi2Error;
}
fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  return c != NULL ? fmi2OK : fmi2Error;
}
fmi2Status fmi2Terminate(fmi2Component c) {
  return c != NULL ? fmi2OK : fmi2Error;
}
fmi2Status fmi2Reset(fmi2Component c) {
  return unsupported(c, "fmi2Reset");
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
  mini_instance* m = (mini_instance*)c;
  size_t i;
  for (i = 0; i < nvr; ++i) {
    switch (vr[i]) {
      case 0:
        value[i] = STATE_X(m);
        break;
      case 1:
        value[i] = m->k;
        break;
      case 2:
        value[i] = m->u;
        break;
      case 3:
        value[i] = m->time;
        break;
      default:
        log_error(m, "fmi2GetReal: unknown valueReference");
        return fmi2Error;
    }
  }
  return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
  mini_instance* m = (mini_instance*)c;
  size_t i;
  for (i = 0; i < nvr; ++i) {
    switch (vr[i]) {
      case 1:
        m->k = value[i];
        break;
      case 2:
        m->u = value[i];
        break;
      default:
        log_error(m, "fmi2SetReal: valueReference cannot be set");
        return fmi2Error;
    }
  }
  return fmi2OK;
}

#define MINI_NO_VARIABLES(function, type, qualifier)                              \
  fmi2Status function(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, \
                      qualifier type value[]) {                                   \
    (void)vr;                                                                     \
    (void)value;                                                                  \
    if (nvr == 0) return fmi2OK;                                                  \
    log_error((mini_instance*)c, #function ": mini_fmu has no such variables");   \
    return fmi2Error;                                                             \
  }
MINI_NO_VARIABLES(fmi2GetInteger, fmi2Integer, )
MINI_NO_VARIABLES(fmi2GetBoolean, fmi2Boolean, )
MINI_NO_VARIABLES(fmi2GetString, fmi2String, )
MINI_NO_VARIABLES(fmi2SetInteger, fmi2Integer, const)
MINI_NO_VARIABLES(fmi2SetBoolean, fmi2Boolean, const)
MINI_NO_VARIABLES(fmi2SetString, fmi2String, const)

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* s) {
  (void)s;
  return unsupported(c, "fmi2GetFMUstate");
}
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate s) {
  (void)s;
  return unsupported(c, "fmi2SetFMUstate");
}
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* s) {
  (void)s;
  return unsupported(c, "fmi2FreeFMUstate");
}
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate s, size_t* size) {
  (void)s;
  (void)size;
  return unsupported(c, "fmi2SerializedFMUstateSize");
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate s, fmi2Byte b[], size_t size) {
  (void)s;
  (void)b;
  (void)size;
  return unsupported(c, "fmi2SerializeFMUstate");
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t size,
                                   fmi2FMUstate* s) {
  (void)b;
  (void)size;
  (void)s;
  return unsupported(c, "fmi2DeSerializeFMUstate");
}
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference k[], size_t nk,
                                        const fmi2Real dk[], fmi2Real du[]) {
  (void)u;
  (void)nu;
  (void)k;
  (void)nk;
  (void)dk;
  (void)du;
  return unsupported(c, "fmi2GetDirectionalDerivative");
}
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                       const fmi2Integer order[], const fmi2Real value[]) {
  (void)vr;
  (void)n;
  (void)order;
  (void)value;
  return unsupported(c, "fmi2SetRealInputDerivatives");
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                        const fmi2Integer order[], fmi2Real value[]) {
  (void)vr;
  (void)n;
  (void)order;
  (void)value;
  return unsupported(c, "fmi2GetRealOutputDerivatives");
}

#if !defined(MINI_FMU_OMIT_DO_STEP)
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
  mini_instance* m = (mini_instance*)c;
  const int substeps = 10;
  const double h = communicationStepSize / substeps;
  int i;
  (void)noSetFMUStatePriorToCurrentPoint;
  if (fabs(currentCommunicationPoint - m->time) > 1e-9 * (1.0 + fabs(m->time))) {
    log_error(m, "fmi2DoStep: currentCommunicationPoint is not the current time");
    return fmi2Error;
  }
  for (i = 0; i < substeps; ++i) STATE_X(m) += h * (-m->k * STATE_X(m) + m->u);
  m->time = currentCommunicationPoint + communicationStepSize;
#if defined(MINI_FMU_NAN)
  if (m->time > 0.05) STATE_X(m) = NAN;
#endif
  return fmi2OK;
}
#endif

fmi2Status fmi2CancelStep(fmi2Component c) {
  return unsupported(c, "fmi2CancelStep");
}
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status* value) {
  (void)s;
  (void)value;
  return unsupported(c, "fmi2GetStatus");
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* value) {
  (void)s;
  (void)value;
  return unsupported(c, "fmi2GetRealStatus");
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer* value) {
  (void)s;
  (void)value;
  return unsupported(c, "fmi2GetIntegerStatus");
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* value) {
  (void)s;
  (void)value;
  return unsupported(c, "fmi2GetBooleanStatus");
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String* value) {
  (void)s;
  (void)value;
  return unsupported(c, "fmi2GetStringStatus");
}

#if defined(MINI_FMU_EXTRA_EXPORT)
/* the defect: a helper that leaks out of the shared library */
__attribute__((visibility("default"))) int mini_fmu_helper(void) {
  return 42;
}
#endif

#if defined(MINI_FMU_EXTRA_NEEDED)
/* the defect: a dependency on a library the importer's machine may not have */
extern const char* zlibVersion(void);
__attribute__((constructor)) static void mini_fmu_touch_zlib(void) {
  (void)zlibVersion();
}
#endif
