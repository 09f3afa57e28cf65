/* A chain of ten first-order lags, x0' = -x0 and xi' = x(i-1) - xi, from x0(0) = 1: a linear
 * 10-state system with the closed form xi(t) = t^i e^-t / i!. Value references: reals 0..9
 * the states, 10..19 their derivatives. */
#include "me_model.h"

const char* const me_guid = "{stride-me-chain}";
const int me_state_count = 10;
const int me_indicator_count = 0;
const fmi2ValueReference me_states[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
const fmi2ValueReference me_derivatives[] = {10, 11, 12, 13, 14, 15, 16, 17, 18, 19};

void me_start(me_data* m) {
  m->r[0] = 1.0;
}
void me_equations(me_data* m) {
  m->r[10] = -m->r[0];
  for (int i = 1; i < 10; ++i) m->r[10 + i] = m->r[i - 1] - m->r[i];
}
void me_indicators(const me_data* m, double z[]) {
  (void)m;
  (void)z;
}
int me_event(me_data* m) {
  (void)m;
  return 0;
}
int me_step_event(me_data* m) {
  (void)m;
  return 0;
}
