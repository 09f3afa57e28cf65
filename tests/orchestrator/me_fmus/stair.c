/* A stair: the integer level rises by one at every multiple of the period (time events), and
 * x integrates the level. Outputs the time of the last switch. */
#include "me_model.h"

const char* const me_guid = "{stride-me-stair}";
const int me_state_count = 1;
const int me_indicator_count = 0;
const fmi2ValueReference me_states[] = {0};
const fmi2ValueReference me_derivatives[] = {1};

void me_start(me_data* m) {
  m->r[2] = -1;  /* last switch: none yet */
  m->r[3] = 0.3; /* period */
}
void me_equations(me_data* m) {
  m->r[1] = m->i[0];
}
void me_indicators(const me_data* m, double z[]) {
  (void)m;
  (void)z;
}
int me_event(me_data* m) {
  if (m->next_event < 0) {
    m->next_event = m->r[3];
    return 0;
  }
  if (m->time < m->next_event) return 0;
  m->i[0] += 1;
  m->r[2] = m->time;
  m->next_event = (m->i[0] + 1) * m->r[3];
  return 0;
}
int me_step_event(me_data* m) {
  (void)m;
  return 0;
}
