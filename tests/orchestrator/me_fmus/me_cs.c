/* The FMI 2.0 Co-Simulation functions of the test FMUs: the same equations advanced by the FMU
 * itself with classical Runge-Kutta (RK4) at a fixed internal step, events detected at the end
 * of each internal step. It makes the Co-Simulation twin of each Model Exchange model, the
 * reference the Model Exchange runner's cost is measured against (bench/orchestrator). */
#include <math.h>
#include <string.h>

#include "me_instance.h"

/* the states' derivatives at (t, x), through the model's equations */
static void rates(instance* s, double t, const double x[], double dx[]) {
  s->m.time = t;
  for (int k = 0; k < me_state_count; ++k) s->m.r[me_states[k]] = x[k];
  me_equations(&s->m);
  for (int k = 0; k < me_state_count; ++k) dx[k] = s->m.r[me_derivatives[k]];
}

static void rk4_step(instance* s, double t, double dt) {
  double x[ME_MAX_REALS], y[ME_MAX_REALS], k1[ME_MAX_REALS], k2[ME_MAX_REALS], k3[ME_MAX_REALS],
      k4[ME_MAX_REALS];
  const int n = me_state_count;
  for (int k = 0; k < n; ++k) x[k] = s->m.r[me_states[k]];
  rates(s, t, x, k1);
  for (int k = 0; k < n; ++k) y[k] = x[k] + 0.5 * dt * k1[k];
  rates(s, t + 0.5 * dt, y, k2);
  for (int k = 0; k < n; ++k) y[k] = x[k] + 0.5 * dt * k2[k];
  rates(s, t + 0.5 * dt, y, k3);
  for (int k = 0; k < n; ++k) y[k] = x[k] + dt * k3[k];
  rates(s, t + dt, y, k4);
  for (int k = 0; k < n; ++k) y[k] = x[k] + dt / 6.0 * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
  s->m.time = t + dt;
  for (int k = 0; k < n; ++k) s->m.r[me_states[k]] = y[k];
  me_equations(&s->m);
}

/* an event indicator changed sign over the internal step */
static int crossed(const double before[], const double after[]) {
  for (int k = 0; k < me_indicator_count; ++k) {
    if ((before[k] > 0) != (after[k] > 0)) return 1;
  }
  return 0;
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean no_set_prior) {
  (void)no_set_prior;
  instance* s = c;
  if (s == NULL || s->type != fmi2CoSimulation || !(h > 0)) return fmi2Error;
  if (s->m.terminate) return fmi2Discard;
  if (!s->m.cs_started) { /* the initial event pass, which a Model Exchange importer makes */
    s->m.cs_started = 1;
    s->m.time = t;
    me_event(&s->m);
  }
  const double max_step = s->m.r[ME_CS_STEP] > 0 ? s->m.r[ME_CS_STEP] : 1e-3;
  const int n = (int)ceil(h / max_step - 1e-9);
  const double dt = h / (n < 1 ? 1 : n);
  double before[ME_MAX_REALS], after[ME_MAX_REALS];
  for (int i = 0; i < n; ++i) {
    me_indicators(&s->m, before);
    rk4_step(s, t + i * dt, dt);
    s->m.time = t + (i + 1) * dt; /* no drift from adding dt n times */
    me_indicators(&s->m, after);
    const int timed = s->m.next_event >= 0 && s->m.time >= s->m.next_event;
    if (crossed(before, after) || timed || me_step_event(&s->m)) me_event(&s->m);
    if (s->m.terminate) return fmi2Discard;
  }
  return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c) {
  (void)c;
  return fmi2Error;
}
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
  (void)c;
  (void)vr;
  (void)order;
  (void)value;
  return nvr == 0 ? fmi2OK : fmi2Error;
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
  (void)c;
  (void)vr;
  (void)order;
  (void)value;
  return nvr == 0 ? fmi2OK : fmi2Error;
}
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind k, fmi2Status* value) {
  (void)c;
  (void)k;
  (void)value;
  return fmi2Discard;
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind k, fmi2Real* value) {
  (void)k;
  if (value == NULL) return fmi2Error;
  *value = ((instance*)c)->m.time; /* fmi2LastSuccessfulTime */
  return fmi2OK;
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind k, fmi2Integer* value) {
  (void)c;
  (void)k;
  (void)value;
  return fmi2Discard;
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k, fmi2Boolean* value) {
  if (value == NULL || k != fmi2Terminated) return fmi2Discard;
  *value = ((instance*)c)->m.terminate ? fmi2True : fmi2False;
  return fmi2OK;
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind k, fmi2String* value) {
  (void)c;
  (void)k;
  (void)value;
  return fmi2Discard;
}
