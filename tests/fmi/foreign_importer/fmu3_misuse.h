/* fmu3_misuse.h: what the misuse runner (fmu3_misuse.c) and its cases (fmu3_misuse_cases.c)
 * share. */
#ifndef STRIDE_TESTS_FMU3_MISUSE_H
#define STRIDE_TESTS_FMU3_MISUSE_H

#include "fmu3_importer.h"

enum state {
  at_instantiated = 1,
  at_initialization = 2,
  at_step = 4,
  at_terminated = 8,
  at_stop_time = 16 /* Step Mode, one step done, with stopTime declared at that step's end */
};

/* What a probe may use: the first variables of some kinds (NULL when the FMU has none). */
typedef struct {
  const fmu3_setup* s;
  const fmu3_variable* output;   /* a Float64 output */
  const fmu3_variable* input;    /* a Float64 input */
  const fmu3_variable* array;    /* an array output or input */
  const fmu3_variable* array_in; /* a Float64 array input */
  const fmu3_variable* fixed;    /* a fixed (not tunable) parameter */
  const fmu3_variable* settable; /* an input, else a fixed parameter */
  const fmu3_variable* time;     /* the independent variable */
  double buffer[64];             /* room for any value array of a probe */
  fmi3Boolean flags[4];
  size_t count;
  fmi3FMUState state;
} context;

typedef fmi3Status (*probe)(context* x, fmi3Instance c);

/* needs: what the FMU must have for a case to apply */
enum {
  n_output = 1,
  n_input = 2,
  n_array = 4,
  n_fixed = 8,
  n_settable = 16,
  n_time = 32,
  n_state = 64,      /* canGetAndSetFMUState */
  n_no_state = 128,  /* not canGetAndSetFMUState */
  n_no_events = 256, /* not hasEventMode */
  n_no_dependencies = 512,
  n_no_directional = 1024,
  n_no_adjoint = 2048,
  n_no_output_derivatives = 4096,
  n_scalar_output = 8192,
  n_array_input = 32768,
  n_no_instance = 16384 /* NULL instance: no logger to reach, so only fmi3Error is required */
};

typedef struct {
  const char* what;
  probe call;
  int states; /* where it is called: the states it is not allowed in, or where it is wrong */
  int needs;
} misuse_case;

extern const misuse_case fmu3_misuse_cases[];
extern const size_t fmu3_misuse_case_count;

#endif
