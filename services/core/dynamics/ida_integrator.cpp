// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/ida_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <ida/ida_impl.h>
#include <sundials/sundials_config.h>

// next_step() reads IDA's private memory (ida_impl.h) and repeats its coefficient update and
// prediction: both are those of SUNDIALS 6.4 (Debian's package). Another version must be checked
// against its own ida.c before this builds.
static_assert(SUNDIALS_VERSION_MAJOR == 6 && SUNDIALS_VERSION_MINOR == 4,
              "IdaIntegrator::next_step() replicates SUNDIALS 6.4's IDA: check it against this version's ida.c");

#include "core/dynamics/sundials_support.hpp"

namespace wrc {

struct IdaIntegrator::Impl {
  explicit Impl(DaeSystem& s) : system(s) {}
  void set_up(const IdaSegment& settings);

  DaeSystem& system;
  SundialsContext ctx;
  std::unique_ptr<SerialVector> y, yp, id, atol;
  std::unique_ptr<SerialVector> output_state;  // the state interpolated at an output time
  IdaSolver ida;
  double t = 0;  // time of y [s]
  double newton_matrix_cj_change = 0;  // IdaSegment::newton_matrix_cj_change [-]
  // cj of the last Newton matrix of this segment (IDA's cjold) [1/s]; NaN before the first.
  double newton_matrix_cj = std::numeric_limits<double>::quiet_NaN();
};

namespace {

IdaIntegrator::Impl& impl_of(void* user) { return *static_cast<IdaIntegrator::Impl*>(user); }
DaeSystem* system_of(void* user) { return &impl_of(user).system; }

int ida_residual(sunrealtype t, N_Vector y, N_Vector yp, N_Vector r, void* user) {
  return system_of(user)->residual(t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), N_VGetArrayPointer(r));
}

int ida_jacobian(sunrealtype t, sunrealtype cj, N_Vector y, N_Vector yp, N_Vector r, SUNMatrix jac, void* user,
                 N_Vector, N_Vector, N_Vector) {
  const DenseMatrixView view{SM_DATA_D(jac), static_cast<long>(SM_ROWS_D(jac))};
  impl_of(user).newton_matrix_cj = cj;
  return system_of(user)->jacobian(t, cj, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), N_VGetArrayPointer(r),
                                   view);
}

void ida_message(int, const char*, const char* function, char* text, void* user) {
  system_of(user)->message(function, text);
}

int ida_roots(sunrealtype t, N_Vector y, N_Vector, sunrealtype* g, void* user) {
  return system_of(user)->roots(t, N_VGetArrayPointer(y), g);
}

}  // namespace

IdaIntegrator::IdaIntegrator(DaeSystem& system) : impl_(std::make_unique<Impl>(system)) {}

IdaIntegrator::~IdaIntegrator() = default;

bool IdaIntegrator::started() const { return static_cast<bool>(impl_->ida); }

void IdaIntegrator::begin(double t, const std::vector<double>& y, const std::vector<double>& yp,
                          const IdaSegment& settings) {
  Impl& m = *impl_;
  const long n = static_cast<long>(y.size());
  const bool same_size = m.y && m.y->size() == n;
  if (!same_size) {
    m.y = std::make_unique<SerialVector>(n, m.ctx.get());
    m.yp = std::make_unique<SerialVector>(n, m.ctx.get());
    m.id = std::make_unique<SerialVector>(n, m.ctx.get());
    m.atol = std::make_unique<SerialVector>(n, m.ctx.get());
    m.output_state = std::make_unique<SerialVector>(n, m.ctx.get());
  }
  std::copy(y.begin(), y.end(), m.y->data());
  std::copy(yp.begin(), yp.end(), m.yp->data());
  std::copy(settings.differential.begin(), settings.differential.end(), m.id->data());
  std::copy(settings.absolute_tolerance.begin(), settings.absolute_tolerance.end(), m.atol->data());
  m.t = t;
  m.newton_matrix_cj = std::numeric_limits<double>::quiet_NaN();  // a new segment starts with a new matrix
  if (same_size && m.ida) {
    check_sundials(IDAReInit(m.ida.mem(), t, m.y->get(), m.yp->get()), "IDAReInit");
  } else {
    m.ida.create(m.ctx.get(), ida_residual, t, m.y->get(), m.yp->get());
    m.set_up(settings);
  }
}

void IdaIntegrator::Impl::set_up(const IdaSegment& s) {
  void* mem = ida.mem();
  newton_matrix_cj_change = s.newton_matrix_cj_change;
  check_sundials(IDASetUserData(mem, this), "IDASetUserData");
  check_sundials(IDASetErrHandlerFn(mem, ida_message, this), "IDASetErrHandlerFn");
  check_sundials(IDASVtolerances(mem, s.relative_tolerance, atol->get()), "IDASVtolerances");
  check_sundials(IDASetId(mem, id->get()), "IDASetId");
  check_sundials(IDASetJacFn(mem, ida_jacobian), "IDASetJacFn");
  check_sundials(IDASetMaxStep(mem, s.max_step), "IDASetMaxStep");
  check_sundials(IDASetDeltaCjLSetup(mem, s.newton_matrix_cj_change), "IDASetDeltaCjLSetup");
  if (!s.index2) return;
  check_sundials(IDASetSuppressAlg(mem, SUNTRUE), "IDASetSuppressAlg");
  check_sundials(IDASetMaxNonlinIters(mem, s.max_newton_iterations), "IDASetMaxNonlinIters");
  if (s.root_direction.empty()) return;  // no event functions (elastic contact)
  std::vector<int> direction = s.root_direction;
  check_sundials(IDARootInit(mem, static_cast<int>(direction.size()), ida_roots), "IDARootInit");
  check_sundials(IDASetRootDirection(mem, direction.data()), "IDASetRootDirection");
  check_sundials(IDASetNoInactiveRootWarn(mem), "IDASetNoInactiveRootWarn");
}

IdaStep IdaIntegrator::step(double t_stop) {
  Impl& m = *impl_;
  check_sundials(IDASetStopTime(m.ida.mem(), t_stop), "IDASetStopTime");
  IdaStep s;
  s.t = m.t;
  s.flag = IDASolve(m.ida.mem(), t_stop, &s.t, m.y->get(), m.yp->get(), IDA_ONE_STEP);
  s.root = s.flag == IDA_ROOT_RETURN;
  s.stop_time = s.flag == IDA_TSTOP_RETURN;
  s.convergence_failure = s.flag == IDA_CONV_FAIL;
  if (s.flag >= 0) m.t = s.t;
  return s;
}

bool IdaIntegrator::newton_matrix_expected() const {
  const Impl& m = *impl_;
  if (!m.ida || std::isnan(m.newton_matrix_cj)) return true;
  double cj = 0;
  check_sundials(IDAGetCurrentCj(m.ida.mem(), &cj), "IDAGetCurrentCj");
  return newton_matrix_expected(cj);
}

bool IdaIntegrator::newton_matrix_expected(double cj) const {
  const Impl& m = *impl_;
  if (std::isnan(m.newton_matrix_cj)) return true;
  // IDA's rule (its nonlinear solver's set-up decision): a new matrix when cj / cjold leaves
  // [(1 - dcj) / (1 + dcj), (1 + dcj) / (1 - dcj)].
  const double ratio = cj / m.newton_matrix_cj;
  const double low = (1.0 - m.newton_matrix_cj_change) / (1.0 + m.newton_matrix_cj_change);
  return ratio < low || ratio > 1.0 / low;
}

double IdaIntegrator::current_time() const {
  double t = 0;
  check_sundials(IDAGetCurrentTime(impl_->ida.mem(), &t), "IDAGetCurrentTime");
  return t;
}

std::optional<IdaIntegrator::NextStep> IdaIntegrator::next_step() const {
  const Impl& m = *impl_;
  if (!m.ida) return std::nullopt;
  // IDA's own data (ida_impl.h) and its order of operations (IDASetCoeffs, IDAPredict, the
  // nonlinear solver's first residual at the predictor plus a zero correction), so that the
  // forecast is the residual's state to the last bit.
  const IDAMem ida = static_cast<IDAMem>(m.ida.mem());
  if (ida->ida_nst == 0) return std::nullopt;
  double hh = ida->ida_hh;
  const double tn = ida->ida_tn;
  if (ida->ida_tstopset) {
    const double troundoff = 100.0 * ida->ida_uround * (std::abs(tn) + std::abs(hh));
    if (std::abs(tn - ida->ida_tstop) <= troundoff) return std::nullopt;
    if ((tn + hh - ida->ida_tstop) * hh > 0.0) hh = (ida->ida_tstop - tn) * (1.0 - 4.0 * ida->ida_uround);
  }
  const int kk = ida->ida_kk;
  int ns = (hh != ida->ida_hused || kk != ida->ida_kused) ? 0 : ida->ida_ns;
  ns = std::min(ns + 1, ida->ida_kused + 2);
  double beta[MXORDP1];
  double psi[MXORDP1];
  std::copy(ida->ida_beta, ida->ida_beta + MXORDP1, beta);
  std::copy(ida->ida_psi, ida->ida_psi + MXORDP1, psi);
  if (kk + 1 >= ns) {
    beta[0] = 1.0;
    double temp1 = hh;
    for (int i = 1; i <= kk; ++i) {
      const double temp2 = psi[i - 1];
      psi[i - 1] = temp1;
      beta[i] = beta[i - 1] * psi[i - 1] / temp2;
      temp1 = temp2 + hh;
    }
  }
  NextStep next;
  double alphas = 0.0;
  for (int i = 0; i < kk; ++i) alphas = alphas - 1.0 / (i + 1);
  next.cj = -alphas / hh;
  next.t = tn + hh;
  if (ida->ida_tstopset && (next.t - ida->ida_tstop) * hh > 0.0) next.t = ida->ida_tstop;
  const long n = m.y->size();
  next.y.assign(static_cast<size_t>(n), 0.0);
  for (long i = 0; i < n; ++i) {
    double z = N_VGetArrayPointer(ida->ida_phi[0])[i];
    for (int j = 1; j <= kk; ++j) {
      const double phi = N_VGetArrayPointer(ida->ida_phi[j])[i];
      z = (j >= ns ? beta[j] * phi : phi) + z;
    }
    next.y[static_cast<size_t>(i)] = z + 0.0;
  }
  return next;
}

std::vector<int> IdaIntegrator::root_info(int root_count) const {
  std::vector<int> info(static_cast<size_t>(root_count), 0);
  check_sundials(IDAGetRootInfo(impl_->ida.mem(), info.data()), "IDAGetRootInfo");
  return info;
}

RunCounters IdaIntegrator::counters() const {
  RunCounters c;
  if (!impl_->ida) return c;
  void* mem = impl_->ida.mem();
  long v = 0;
  check_sundials(IDAGetNumSteps(mem, &v), "IDAGetNumSteps");
  c.steps = v;
  check_sundials(IDAGetNumResEvals(mem, &v), "IDAGetNumResEvals");
  c.residual_evals = v;
  check_sundials(IDAGetNumLinSolvSetups(mem, &v), "IDAGetNumLinSolvSetups");
  c.lin_setups = v;
  check_sundials(IDAGetNumErrTestFails(mem, &v), "IDAGetNumErrTestFails");
  c.err_test_fails = v;
  check_sundials(IDAGetNumNonlinSolvIters(mem, &v), "IDAGetNumNonlinSolvIters");
  c.nonlin_iters = v;
  check_sundials(IDAGetNumNonlinSolvConvFails(mem, &v), "IDAGetNumNonlinSolvConvFails");
  c.nonlin_conv_fails = v;
  // 0 for a segment without event functions.
  if (IDAGetNumGEvals(mem, &v) == IDA_SUCCESS) c.root_evals = v;
  int order = 0;
  check_sundials(IDAGetLastOrder(mem, &order), "IDAGetLastOrder");
  c.last_order = order;
  double h = 0;
  check_sundials(IDAGetLastStep(mem, &h), "IDAGetLastStep");
  c.last_step = h;
  return c;
}

std::vector<double> IdaIntegrator::state() const {
  const SerialVector& y = *impl_->y;
  return std::vector<double>(y.data(), y.data() + y.size());
}

const double* IdaIntegrator::state_data() const { return impl_->y->data(); }

const double* IdaIntegrator::derivative_data() const { return impl_->yp->data(); }

std::vector<double> IdaIntegrator::state_at(double t) {
  Impl& m = *impl_;
  SerialVector& tmp = *m.output_state;
  check_sundials(IDAGetDky(m.ida.mem(), t, 0, tmp.get()), "IDAGetDky");
  if (t == m.t) N_VScale(1.0, m.y->get(), tmp.get());  // exactly the step's state
  return std::vector<double>(tmp.data(), tmp.data() + tmp.size());
}

}  // namespace wrc
