/* The equations of one Model Exchange test FMU; me_fmu.c wraps them in the FMI 2.0 Model
 * Exchange interface. Variables of each type are addressed by value reference. The wrapper
 * reads three reals of every model: the last (ME_MAX_REALS - 1), when positive, is a time after
 * which the equations return fmi2Discard; the one before it, when positive, makes every event
 * iteration ask for another pass; the one before that is the internal step of the
 * Co-Simulation interface (me_cs.c), 1 ms when not positive. */
#ifndef STRIDE_TESTS_ME_MODEL_H
#define STRIDE_TESTS_ME_MODEL_H

#include "stride/fmi2/fmi2_me_api.h"

#define ME_MAX_REALS 32
#define ME_MAX_INTEGERS 4
#define ME_MAX_BOOLEANS 4
#define ME_MAX_STRINGS 2
#define ME_STRING_SIZE 64

typedef struct {
  double time;
  double r[ME_MAX_REALS];
  int i[ME_MAX_INTEGERS];
  int b[ME_MAX_BOOLEANS];
  char s[ME_MAX_STRINGS][ME_STRING_SIZE];
  double next_event; /* < 0: none */
  int terminate;
  int cs_started; /* Co-Simulation: the initial event pass is done */
} me_data;

extern const char* const me_guid;
extern const int me_state_count;
extern const int me_indicator_count;
extern const fmi2ValueReference me_states[];      /* value references of the states */
extern const fmi2ValueReference me_derivatives[]; /* and of their derivatives */

#define ME_CS_STEP (ME_MAX_REALS - 3)
#define ME_CHATTER (ME_MAX_REALS - 2)
#define ME_FAIL_AFTER (ME_MAX_REALS - 1)

void me_start(me_data* m);     /* start values */
void me_equations(me_data* m); /* derivatives (and outputs) from the states */
void me_indicators(const me_data* m, double z[]);
/* One pass of event iteration at m->time; returns whether the continuous states changed. */
int me_event(me_data* m);
/* After an integrator step: whether the model asks for a step event. */
int me_step_event(me_data* m);

#endif /* STRIDE_TESTS_ME_MODEL_H */
