/* A ball dropped from h0 bouncing with restitution e: a state event when the height reaches
 * zero while falling. Outputs the count of bounces and the time of the last one. */
#include "me_model.h"

const char* const me_guid = "{stride-me-ball}";
const int me_state_count = 2;
const int me_indicator_count = 1;
const fmi2ValueReference me_states[] = {0, 2};      /* h, v */
const fmi2ValueReference me_derivatives[] = {1, 3}; /* der(h), der(v) */

void me_start(me_data* m) {
  m->r[0] = 1.0;  /* h */
  m->r[4] = 9.81; /* g */
  m->r[5] = 0.7;  /* e */
  m->r[6] = -1;   /* last bounce: none yet */
}
void me_equations(me_data* m) {
  m->r[1] = m->r[2];
  m->r[3] = -m->r[4];
}
void me_indicators(const me_data* m, double z[]) {
  z[0] = m->r[0];
}
int me_event(me_data* m) {
  if (m->r[0] > 0 || m->r[2] >= 0) return 0;
  m->r[0] = 0;
  m->r[2] = -m->r[5] * m->r[2];
  m->r[6] = m->time;
  m->i[0] += 1;
  /* max_bounces > 0: the simulation ends at that bounce */
  if (m->i[1] > 0 && m->i[0] >= m->i[1]) m->terminate = 1;
  return 1;
}
int me_step_event(me_data* m) {
  (void)m;
  return 0;
}
