/* gait_host: drives gait.fmu from plain C through the FMI 2.0 C API, as any co-simulation tool
 * does: read the GUID and value references from modelDescription.xml, dlopen the binary,
 * instantiate, step. Prints the right and left hip pitch (servo IDs 11, 12) every 0.25 s.
 *
 *   cmake -E make_directory gait && cmake -E chdir gait cmake -E tar xf ../gait.fmu
 *   cc -I"$PREFIX/include" -o gait_host gait_host.c -ldl
 *   ./gait_host gait 2
 */
#define _DEFAULT_SOURCE /* realpath */
#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stride/fmi2/fmi2_api.h"

typedef fmi2Component (*instantiate_fn)(fmi2String, fmi2Type, fmi2String, fmi2String,
                                        const fmi2CallbackFunctions*, fmi2Boolean, fmi2Boolean);
typedef fmi2Status (*setup_fn)(fmi2Component, fmi2Boolean, fmi2Real, fmi2Real, fmi2Boolean,
                               fmi2Real);
typedef fmi2Status (*mode_fn)(fmi2Component);
typedef fmi2Status (*set_real_fn)(fmi2Component, const fmi2ValueReference[], size_t,
                                  const fmi2Real[]);
typedef fmi2Status (*set_boolean_fn)(fmi2Component, const fmi2ValueReference[], size_t,
                                     const fmi2Boolean[]);
typedef fmi2Status (*get_real_fn)(fmi2Component, const fmi2ValueReference[], size_t, fmi2Real[]);
typedef fmi2Status (*do_step_fn)(fmi2Component, fmi2Real, fmi2Real, fmi2Boolean);
typedef void (*free_fn)(fmi2Component);

static void print_message(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                          fmi2String category, fmi2String message, ...) {
  (void)env;
  fprintf(stderr, "[%s] %s (status %d): %s\n", category, instance, (int)status, message);
}

static void fail(const char* what) {
  fprintf(stderr, "gait_host: %s\n", what);
  exit(1);
}

/* The text of `attribute` in the first element of `xml` that carries `name="<name>"`. */
static void attribute_of(const char* xml, const char* name, const char* attribute, char* out,
                         size_t size) {
  char key[128];
  snprintf(key, sizeof key, "name=\"%s\"", name);
  const char* element = strstr(xml, key);
  if (element == NULL) fail("variable not in modelDescription.xml");
  snprintf(key, sizeof key, "%s=\"", attribute);
  const char* value = strstr(element, key);
  if (value == NULL) fail("attribute not in modelDescription.xml");
  value += strlen(key);
  size_t n = (size_t)(strchr(value, '"') - value);
  if (n >= size) fail("attribute too long");
  memcpy(out, value, n);
  out[n] = '\0';
}

static fmi2ValueReference value_reference(const char* xml, const char* name) {
  char text[32];
  attribute_of(xml, name, "valueReference", text, sizeof text);
  return (fmi2ValueReference)strtoul(text, NULL, 10);
}

static void* symbol(void* library, const char* name) {
  void* f = dlsym(library, name);
  if (f == NULL) fail(name);
  return f;
}

int main(int argc, char** argv) {
  if (argc != 3) fail("usage: gait_host UNPACKED_FMU_DIR SECONDS");
  /* the resource location must be an absolute file:// URI */
  char dir[PATH_MAX];
  if (realpath(argv[1], dir) == NULL) fail("no such folder");
  char* end = NULL;
  const double seconds = strtod(argv[2], &end);
  if (end == argv[2] || *end != '\0' || !(seconds > 0 && seconds < 1e6))
    fail("SECONDS must be a number of seconds, more than 0");
  char path[PATH_MAX + 64];

  snprintf(path, sizeof path, "%s/modelDescription.xml", dir);
  FILE* file = fopen(path, "rb");
  if (file == NULL) fail("cannot open modelDescription.xml");
  static char xml[1 << 20];
  xml[fread(xml, 1, sizeof xml - 1, file)] = '\0';
  fclose(file);
  char guid[64];
  const char* root = strstr(xml, "<fmiModelDescription");
  if (root == NULL) fail("not a model description");
  const char* g = strstr(root, "guid=\"");
  if (g == NULL || sscanf(g, "guid=\"%63[^\"]\"", guid) != 1) fail("no GUID");
  const fmi2ValueReference x_move = value_reference(xml, "x_move");
  const fmi2ValueReference walking = value_reference(xml, "walking");
  const fmi2ValueReference hips[2] = {value_reference(xml, "joint_angle[11]"),
                                      value_reference(xml, "joint_angle[12]")};

  snprintf(path, sizeof path, "%s/binaries/linux64/gait.so", dir);
  void* library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
  if (library == NULL) fail(dlerror());
  instantiate_fn instantiate = (instantiate_fn)symbol(library, "fmi2Instantiate");
  setup_fn setup = (setup_fn)symbol(library, "fmi2SetupExperiment");
  mode_fn enter_init = (mode_fn)symbol(library, "fmi2EnterInitializationMode");
  mode_fn exit_init = (mode_fn)symbol(library, "fmi2ExitInitializationMode");
  mode_fn terminate = (mode_fn)symbol(library, "fmi2Terminate");
  set_real_fn set_real = (set_real_fn)symbol(library, "fmi2SetReal");
  set_boolean_fn set_boolean = (set_boolean_fn)symbol(library, "fmi2SetBoolean");
  get_real_fn get_real = (get_real_fn)symbol(library, "fmi2GetReal");
  do_step_fn do_step = (do_step_fn)symbol(library, "fmi2DoStep");
  free_fn free_instance = (free_fn)symbol(library, "fmi2FreeInstance");

  char resources[PATH_MAX + 64];
  snprintf(resources, sizeof resources, "file://%s/resources", dir);
  const fmi2CallbackFunctions callbacks = {print_message, calloc, free, NULL, NULL};
  fmi2Component c =
      instantiate("gait", fmi2CoSimulation, guid, resources, &callbacks, fmi2False, fmi2False);
  if (c == NULL) fail("fmi2Instantiate failed");
  const fmi2Real forward = 20.0; /* mm */
  const fmi2Boolean on = fmi2True;
  if (setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
      set_real(c, &x_move, 1, &forward) != fmi2OK || set_boolean(c, &walking, 1, &on) != fmi2OK ||
      enter_init(c) != fmi2OK || exit_init(c) != fmi2OK) {
    fail("initialization failed");
  }
  const double h = 0.008;
  const long steps = (long)(seconds / h + 0.5);
  printf("t_s,hip_pitch_r_rad,hip_pitch_l_rad\n");
  for (long k = 0; k <= steps; ++k) {
    if (k % 31 == 0 || k == steps) { /* 31 steps of 8 ms: every 0.248 s, and the last */
      fmi2Real angle[2];
      if (get_real(c, hips, 2, angle) != fmi2OK) fail("fmi2GetReal failed");
      printf("%.3f,%.6f,%.6f\n", k * h, angle[0], angle[1]);
    }
    if (k < steps && do_step(c, k * h, h, fmi2True) != fmi2OK) fail("fmi2DoStep failed");
  }
  terminate(c);
  free_instance(c);
  dlclose(library);
  return 0;
}
