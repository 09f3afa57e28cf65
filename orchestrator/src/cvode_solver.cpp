#include "cvode_solver.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>

namespace stride::cosim::detail {

struct cvode_solver::handles {
  SUNContext context = nullptr;
  void* mem = nullptr;
  N_Vector y = nullptr;
  N_Vector atol = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver linear = nullptr;
  SUNNonlinearSolver nonlinear = nullptr;
  ode_system* system = nullptr;
  std::exception_ptr* pending = nullptr;  // thrown by the system inside CVODE's callbacks

  ~handles() {
    if (mem != nullptr) CVodeFree(&mem);
    if (nonlinear != nullptr) SUNNonlinSolFree(nonlinear);
    if (linear != nullptr) SUNLinSolFree(linear);
    if (matrix != nullptr) SUNMatDestroy(matrix);
    if (atol != nullptr) N_VDestroy(atol);
    if (y != nullptr) N_VDestroy(y);
    if (context != nullptr) SUNContext_Free(&context);
  }
};

namespace {

// CVODE needs at least one state: a system with none (only time events or indicators) gets a
// constant dummy.
std::size_t solver_size(const ode_system& s) {
  return std::max<std::size_t>(s.state_count(), 1);
}

// The callbacks run inside C code: an exception is parked, reported to CVODE as an
// unrecoverable failure and rethrown by fail().
int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  auto* h = static_cast<cvode_solver::handles*>(data);
  try {
    const std::size_t n = h->system->state_count();
    double* dx = N_VGetArrayPointer(ydot);
    if (n == 0) {
      dx[0] = 0;
      return 0;
    }
    h->system->derivatives(t, {N_VGetArrayPointer(y), n}, {dx, n});
    return 0;
  } catch (...) {
    *h->pending = std::current_exception();
    return -1;
  }
}

int roots(sunrealtype t, N_Vector y, sunrealtype* g, void* data) {
  auto* h = static_cast<cvode_solver::handles*>(data);
  try {
    h->system->indicators(t, {N_VGetArrayPointer(y), h->system->state_count()},
                          {g, h->system->indicator_count()});
    return 0;
  } catch (...) {
    *h->pending = std::current_exception();
    return -1;
  }
}

void error_handler(int /*code*/, const char* /*module*/, const char* /*function*/, char* message,
                   void* data) {
  *static_cast<std::string*>(data) = message ? message : "";
}

}  // namespace

cvode_solver::cvode_solver(ode_system& system, const cvode_settings& settings)
    : system_(system), settings_(settings), h_(new handles) {
  h_->system = &system_;
  h_->pending = &pending_;
  const auto n = static_cast<sunindextype>(solver_size(system));
  bool ok = SUNContext_Create(nullptr, &h_->context) == 0;
  if (ok) {
    h_->y = N_VNew_Serial(n, h_->context);
    h_->atol = N_VNew_Serial(n, h_->context);
    const bool bdf = settings.method == model_exchange_options::method_kind::bdf;
    h_->mem = CVodeCreate(bdf ? CV_BDF : CV_ADAMS, h_->context);
    ok = h_->y != nullptr && h_->atol != nullptr && h_->mem != nullptr;
  }
  if (!ok) {
    delete h_;
    h_ = nullptr;
    throw solver_failure("cannot allocate CVODE's memory");
  }
  CVodeSetErrHandlerFn(h_->mem, error_handler, &message_);
  double* atol = N_VGetArrayPointer(h_->atol);
  for (sunindextype i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    atol[i] = k < settings.atol.size() ? settings.atol[k] : settings.rtol;
  }
}

cvode_solver::~cvode_solver() {
  delete h_;
}

void cvode_solver::reset(double t, std::span<const double> x) {
  double* y = N_VGetArrayPointer(h_->y);
  std::fill(y, y + solver_size(system_), 0.0);
  std::copy(x.begin(), x.end(), y);
  pending_ = nullptr;
  if (initialised_) {
    if (const int flag = CVodeReInit(h_->mem, t, h_->y); flag != CV_SUCCESS) {
      fail(flag, "CVodeReInit");
    }
    return;
  }
  int flag = CVodeInit(h_->mem, rhs, t, h_->y);
  if (flag != CV_SUCCESS) fail(flag, "CVodeInit");
  CVodeSetUserData(h_->mem, h_);
  flag = CVodeSVtolerances(h_->mem, settings_.rtol, h_->atol);
  if (flag != CV_SUCCESS) fail(flag, "CVodeSVtolerances");
  if (settings_.max_step) CVodeSetMaxStep(h_->mem, *settings_.max_step);
  if (settings_.method == model_exchange_options::method_kind::bdf) {
    h_->matrix = SUNDenseMatrix(static_cast<sunindextype>(solver_size(system_)),
                                static_cast<sunindextype>(solver_size(system_)), h_->context);
    h_->linear = SUNLinSol_Dense(h_->y, h_->matrix, h_->context);
    flag = CVodeSetLinearSolver(h_->mem, h_->linear, h_->matrix);
    if (flag != CV_SUCCESS) fail(flag, "CVodeSetLinearSolver");
  } else {
    // Adams is for non-stiff systems: functional (fixed-point) iteration needs no Jacobian
    h_->nonlinear = SUNNonlinSol_FixedPoint(h_->y, 0, h_->context);
    flag = CVodeSetNonlinearSolver(h_->mem, h_->nonlinear);
    if (flag != CV_SUCCESS) fail(flag, "CVodeSetNonlinearSolver");
  }
  if (system_.indicator_count() > 0) {
    flag = CVodeRootInit(h_->mem, static_cast<int>(system_.indicator_count()), roots);
    if (flag != CV_SUCCESS) fail(flag, "CVodeRootInit");
  }
  initialised_ = true;
}

ode_step cvode_solver::step(double t_stop, std::span<double> x) {
  CVodeSetStopTime(h_->mem, t_stop);
  double t = 0;
  const int flag = CVode(h_->mem, t_stop, h_->y, &t, CV_ONE_STEP);
  if (flag < 0) fail(flag, "CVode");
  const double* y = N_VGetArrayPointer(h_->y);
  std::copy(y, y + x.size(), x.begin());
  return {flag == CV_TSTOP_RETURN ? t_stop : t, flag == CV_ROOT_RETURN};
}

void cvode_solver::fail(int flag, const char* function) {
  if (pending_) {
    auto e = pending_;
    pending_ = nullptr;
    std::rethrow_exception(e);
  }
  std::string reason = CVodeGetReturnFlagName(flag);
  switch (flag) {
    case CV_TOO_MUCH_WORK:
      reason += " (too much work: too many internal steps)";
      break;
    case CV_TOO_MUCH_ACC:
      reason += " (the tolerances cannot be reached)";
      break;
    case CV_ERR_FAILURE:
      reason += " (repeated error test failures)";
      break;
    case CV_CONV_FAILURE:
      reason += " (repeated convergence failures)";
      break;
    default:
      break;
  }
  if (!message_.empty()) reason += ": " + message_;
  throw solver_failure(std::string(function) + " failed with " + reason);
}

}  // namespace stride::cosim::detail
