/* x' = -k x + u, x(0) = 1: with u = 0 the closed form is exp(-k t); with a large k it is
 * stiff. The input u changes only at communication points. */
#include "me_model.h"

const char* const me_guid = "{stride-me-decay}";
const int me_state_count = 1;
const int me_indicator_count = 0;
const fmi2ValueReference me_states[] = {0};
const fmi2ValueReference me_derivatives[] = {1};

void me_start(me_data* m) {
  m->r[0] = 1.0; /* x */
  m->r[2] = 1.0; /* k */
}
void me_equations(me_data* m) {
  m->r[1] = -m->r[2] * m->r[0] + m->r[3]; /* u: r[3] */
}
void me_indicators(const me_data* m, double z[]) {
  (void)m;
  (void)z;
}
int me_event(me_data* m) {
  (void)m;
  return 0;
}
