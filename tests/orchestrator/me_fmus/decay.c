/* x' = -k x + u, x(0) = 1: with u = 0 the closed form is exp(-k t); with a large k it is
 * stiff. The input u changes only at communication points; while the Boolean input `frozen` is
 * true, x stands still. Value references: reals 0 x, 1 der(x), 2 k, 3 u, 4 threshold,
 * 5 crossed_at; integer 0 crossed; Booleans 0 frozen, 1 was_frozen (its echo); strings 0 tag,
 * 1 tag_seen (its echo). */
#include <string.h>

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
  m->r[1] = m->b[0] ? 0.0 : -m->r[2] * m->r[0] + m->r[3]; /* u: r[3] */
  m->b[1] = m->b[0];
  memcpy(m->s[1], m->s[0], sizeof m->s[0]);
}
void me_indicators(const me_data* m, double z[]) {
  (void)m;
  (void)z;
}
/* With threshold > 0: a step event after the first integrator step that ends below it, which
 * records its time and sets the integer `crossed`. */
int me_step_event(me_data* m) {
  return m->r[4] > 0 && m->i[0] == 0 && m->r[0] < m->r[4];
}
int me_event(me_data* m) {
  if (me_step_event(m)) {
    m->i[0] = 1;
    m->r[5] = m->time;
  }
  return 0;
}
