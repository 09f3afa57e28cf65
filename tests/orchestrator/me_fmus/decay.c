/* x' = -k x, x(0) = x0: closed form x0 exp(-k t). With a large k it is stiff. */
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
  m->r[1] = -m->r[2] * m->r[0];
}
void me_indicators(const me_data* m, double z[]) {
  (void)m;
  (void)z;
}
int me_event(me_data* m) {
  (void)m;
  return 0;
}
