/* One instance of a test FMU, shared by its Model Exchange (me_fmu.c) and Co-Simulation
 * (me_cs.c) functions. */
#ifndef STRIDE_TESTS_ME_INSTANCE_H
#define STRIDE_TESTS_ME_INSTANCE_H

#include "me_model.h"

typedef struct {
  me_data m;
  const fmi2CallbackFunctions* cb; /* FMI 2.0: the importer keeps it alive */
  fmi2Type type;
  int logging;
  char name[ME_STRING_SIZE];
} instance;

/* A message through the importer's logger when logging is on (printf-style). */
void say(const instance* s, fmi2Status status, const char* category, const char* format, ...);

#endif /* STRIDE_TESTS_ME_INSTANCE_H */
