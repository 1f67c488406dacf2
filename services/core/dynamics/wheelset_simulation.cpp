#include "core/dynamics/wheelset_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>

#include "core/models/contact_model_factory.hpp"

namespace wrc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr size_t kCacheSize = 8;
constexpr int kRootCount = 4;  // switch L, switch R, normal force L, normal force R
constexpr double kGapTolerance = 1e-13;  // [m] position projection onto gap = 0

WheelsetSimulation* self(void* user) { return static_cast<WheelsetSimulation*>(user); }

int ida_residual(sunrealtype, N_Vector y, N_Vector yp, N_Vector r, void* user) {
  return self(user)->residual_callback(N_VGetArrayPointer(y), N_VGetArrayPointer(yp), N_VGetArrayPointer(r));
}

int ida_jacobian(sunrealtype, sunrealtype cj, N_Vector y, N_Vector yp, N_Vector r, SUNMatrix jac, void* user, N_Vector,
                 N_Vector, N_Vector) {
  return self(user)->jacobian_callback(cj, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), N_VGetArrayPointer(r), jac);
}

int ida_roots(sunrealtype, N_Vector y, N_Vector, sunrealtype* g, void* user) {
  return self(user)->root_callback(N_VGetArrayPointer(y), g);
}

ContactFormulation formulation_of(const ContactEvaluator& contact) {
  return contact_model_entry(contact.model()).dynamics_formulation;
}

std::string format_time(double t) {
  std::ostringstream s;
  s.precision(17);
  s << t;
  return s.str();
}

// Finite-difference increment of unknown k at value v.
double increment(int k, double v) {
  const double typical = k >= kUnknownNormalLeft ? 1.0 : (k == kUnknownSpinRate ? 10.0 : 1e-2);
  return 1e-7 * std::max(std::abs(v), typical);
}

}  // namespace

WheelsetSimulation::WheelsetSimulation(RunSpec spec, std::shared_ptr<ContactEvaluator> contact, double nominal_radius)
    : spec_(spec), equations_(spec.wheelset, nominal_radius, nominal_radius), contact_(std::move(contact)) {
  spec_.validate();
  if (!contact_) throw std::invalid_argument("WheelsetSimulation: no contact evaluator");
  if (!(nominal_radius > 0.0)) throw std::invalid_argument("WheelsetSimulation: nominal radius must be > 0");
  formulation_ = formulation_of(*contact_);
  tracked_s_ = {kNaN, kNaN};
}

WheelsetSimulation::~WheelsetSimulation() = default;

int WheelsetSimulation::query_length() const {
  return formulation_ == ContactFormulation::kRigid ? kUnknownNormalRight + 1 : kElasticUnknowns;
}

std::vector<ContactResult> WheelsetSimulation::evaluate(const std::vector<ContactQuery>& batch) {
  ++own_.contact_queries;
  own_.contact_configurations += static_cast<long>(batch.size());
  std::vector<ContactResult> results = contact_->evaluate(batch);
  if (results.size() != batch.size())
    throw std::runtime_error("contact model " + contact_->model() + " answered " + std::to_string(results.size()) +
                             " configurations for " + std::to_string(batch.size()));
  return results;
}

const ContactResult& WheelsetSimulation::contact_at(const double* y) {
  const int m = query_length();
  std::vector<double> key(y, y + m);
  key.push_back(tracked_s_[0]);
  key.push_back(tracked_s_[1]);
  for (const CachedContact& c : cache_)
    if (c.key.size() == key.size() && std::memcmp(c.key.data(), key.data(), key.size() * sizeof(double)) == 0)
      return c.result;
  std::vector<ContactResult> r = evaluate({equations_.query(formulation_, y, tracked_s_)});
  if (cache_.size() >= kCacheSize) cache_.pop_front();
  cache_.push_back({std::move(key), std::move(r.front())});
  return cache_.back().result;
}

int WheelsetSimulation::residual_callback(const double* y, const double* yp, double* r) {
  try {
    equations_.residual(formulation_, y, yp, contact_at(y), r);
    return 0;
  } catch (const ContactConfigurationError& e) {
    last_contact_error_ = e.what();
    return 1;  // recoverable: IDA retries with a smaller step
  } catch (const std::exception& e) {
    last_contact_error_ = e.what();
    return -1;
  }
}

int WheelsetSimulation::jacobian_callback(double cj, const double* y, const double* yp, const double* r,
                                          SUNMatrix jac) {
  try {
    const int n = unknown_count(formulation_);
    const int m = query_length();
    // Every perturbation that changes the contact query in one batch: one round trip.
    std::vector<ContactQuery> batch;
    std::vector<std::vector<double>> perturbed(static_cast<size_t>(n), std::vector<double>(y, y + n));
    std::vector<double> step(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
      step[k] = increment(k, y[k]);
      perturbed[k][k] += step[k];
      step[k] = perturbed[k][k] - y[k];  // the increment actually represented
      if (k < m) batch.push_back(equations_.query(formulation_, perturbed[k].data(), tracked_s_));
    }
    const ContactResult base = contact_at(y);
    std::vector<ContactResult> results = evaluate(batch);
    ++own_.jacobian_evals;
    own_.jacobian_residual_evals += n;
    std::vector<double> column(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
      const ContactResult& c = k < m ? results[static_cast<size_t>(k)] : base;
      equations_.residual(formulation_, perturbed[k].data(), yp, c, column.data());
      for (int i = 0; i < n; ++i) SM_ELEMENT_D(jac, i, k) = (column[i] - r[i]) / step[k];
      SM_ELEMENT_D(jac, k, k) += cj * equations_.derivative_coefficient(formulation_, k);
    }
    return 0;
  } catch (const ContactConfigurationError& e) {
    last_contact_error_ = e.what();
    return 1;
  } catch (const std::exception& e) {
    last_contact_error_ = e.what();
    return -1;
  }
}

int WheelsetSimulation::root_callback(const double* y, double* g) {
  try {
    const ContactResult& c = contact_at(y);
    g[0] = c.wheels[0].switch_function;
    g[1] = c.wheels[1].switch_function;
    g[2] = y[kUnknownNormalLeft];
    g[3] = y[kUnknownNormalRight];
    return 0;
  } catch (const std::exception& e) {
    last_contact_error_ = e.what();
    return -1;
  }
}

void WheelsetSimulation::project_positions(std::vector<double>& y) {
  for (int iteration = 0; iteration < 40; ++iteration) {
    const ContactResult& c = contact_at(y.data());
    const Eigen::Vector2d gap(c.wheels[0].gap, c.wheels[1].gap);
    if (gap.cwiseAbs().maxCoeff() < kGapTolerance) return;
    Eigen::Matrix2d j;
    for (int i = 0; i < 2; ++i) {
      j(i, 0) = c.wheels[static_cast<size_t>(i)].gap_gradient[kUnknownZ];
      j(i, 1) = c.wheels[static_cast<size_t>(i)].gap_gradient[kUnknownRoll];
    }
    const Eigen::Vector2d delta = j.fullPivLu().solve(-gap);
    y[kUnknownZ] += delta[0];
    y[kUnknownRoll] += delta[1];
  }
  std::ostringstream msg;
  msg << "no rigid contact of both wheels at y = " << y[kUnknownY] << " m, yaw = " << y[kUnknownYaw]
      << " rad: the height and roll iteration did not converge";
  throw std::runtime_error(msg.str());
}

void WheelsetSimulation::project_velocities(std::vector<double>& y) {
  const ContactResult& c = contact_at(y.data());
  Eigen::Matrix<double, 2, 4> g;
  for (int i = 0; i < 2; ++i) g.row(i) = c.wheels[static_cast<size_t>(i)].gap_gradient.transpose();
  const Eigen::Vector4d inv_mass = equations_.mass_diagonal().cwiseInverse();
  Eigen::Vector4d v(y[kUnknownYDot], y[kUnknownZDot], y[kUnknownRollDot], y[kUnknownYawDot]);
  const Eigen::Matrix<double, 4, 2> mg = inv_mass.asDiagonal() * g.transpose();
  const Eigen::Vector2d impulse = (g * mg).fullPivLu().solve(g * v);
  v -= mg * impulse;  // the velocity change of an inelastic impact along the constraint normals
  for (int k = 0; k < 4; ++k) y[kPoseUnknowns + k] = v[k];
}

void WheelsetSimulation::settle_elastic(std::vector<double>& y, double z_acceleration, double roll_acceleration) {
  // Height and roll at which the elastic contact gives the vertical and roll accelerations asked
  // for (rest: 0), by Newton's method with a finite-difference Jacobian and step halving.
  const Eigen::Vector4d m = equations_.mass_diagonal();
  const double gyro = equations_.parameters().spin_inertia * y[kUnknownSpinRate] * y[kUnknownYawDot];
  const Eigen::Vector2d target(m[1] * z_acceleration, m[2] * roll_acceleration - gyro);
  const double scale = equations_.force_scale();
  auto mismatch = [&](const ContactResult& c, const std::vector<double>& state) {
    const Eigen::Vector4d q = equations_.applied_forces(formulation_, state.data(), c, nullptr);
    return Eigen::Vector2d(q[1] - target[0], q[2] - target[1]);
  };
  // Start below the rigid contact by the static Hertz approach of a typical wheel load.
  y[kUnknownZ] -= 1e-4;
  const double h = 1e-9;
  for (int iteration = 0; iteration < 60; ++iteration) {
    std::vector<double> dz = y, droll = y;
    dz[kUnknownZ] += h;
    droll[kUnknownRoll] += h;
    std::vector<ContactResult> r = evaluate({equations_.query(formulation_, y.data(), tracked_s_),
                                             equations_.query(formulation_, dz.data(), tracked_s_),
                                             equations_.query(formulation_, droll.data(), tracked_s_)});
    const Eigen::Vector2d f = mismatch(r[0], y);
    if (f.norm() < 1e-9 * scale) return;
    Eigen::Matrix2d j;
    j.col(0) = (mismatch(r[1], dz) - f) / h;
    j.col(1) = (mismatch(r[2], droll) - f) / h;
    const Eigen::Vector2d delta = j.fullPivLu().solve(-f);
    double lambda = 1.0;
    for (int halving = 0; halving < 30; ++halving, lambda *= 0.5) {
      std::vector<double> trial = y;
      trial[kUnknownZ] += lambda * delta[0];
      trial[kUnknownRoll] += lambda * delta[1];
      const ContactResult& c = contact_at(trial.data());
      if (mismatch(c, trial).norm() < f.norm()) {
        y = trial;
        break;
      }
    }
  }
  std::ostringstream msg;
  msg << "the elastic contact finds no height and roll that carry the wheelset at y = " << y[kUnknownY] << " m";
  throw std::runtime_error(msg.str());
}

void WheelsetSimulation::consistent_derivatives(std::vector<double>& y, std::vector<double>& yp) {
  const int n = unknown_count(formulation_);
  yp.assign(static_cast<size_t>(n), 0.0);
  std::vector<double> r(static_cast<size_t>(n));
  if (formulation_ == ContactFormulation::kElastic) {
    equations_.residual(formulation_, y.data(), yp.data(), contact_at(y.data()), r.data());
    for (int k = 0; k <= kUnknownSpinRate; ++k) yp[k] = -r[k] / equations_.derivative_coefficient(formulation_, k);
    return;
  }
  // Rigid: mu = 0, q' = v; v' and N from the equations of motion and the constraints on the
  // acceleration level, G v' + (dG/dt) v = 0, with dG/dt v by a difference along v. The creep
  // forces depend on N (Hertz), so iterate.
  y[kUnknownMuLeft] = y[kUnknownMuRight] = 0.0;
  const double eps = 1e-7;
  std::vector<double> ahead = y;
  for (int k = 0; k < kPoseUnknowns; ++k) ahead[k] += eps * y[kPoseUnknowns + k];
  const ContactResult c_ahead = contact_at(ahead.data());
  const Eigen::Vector4d m = equations_.mass_diagonal();
  for (int iteration = 0; iteration < 8; ++iteration) {
    const ContactResult c = contact_at(y.data());
    std::fill(yp.begin(), yp.end(), 0.0);
    equations_.residual(formulation_, y.data(), yp.data(), c, r.data());
    Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> b;
    for (int k = 0; k < 4; ++k) {
      a(k, k) = m[k];
      b[k] = -r[kPoseUnknowns + k];
    }
    const double scale = equations_.force_scale();
    for (int i = 0; i < 2; ++i) {
      const WheelConstraint& w = c.wheels[static_cast<size_t>(i)];
      const WheelConstraint& w_ahead = c_ahead.wheels[static_cast<size_t>(i)];
      double g_dot_v = 0.0;
      for (int k = 0; k < 4; ++k) {
        // r holds the forces of the current N; the unknown is the change of N (scaled).
        a(k, 4 + i) = -scale * w.normal_z * w.gap_gradient[k];
        a(4 + i, k) = w.gap_gradient[k];
        g_dot_v += (w_ahead.gap_gradient[k] - w.gap_gradient[k]) / eps * y[kPoseUnknowns + k];
      }
      b[4 + i] = -g_dot_v;
    }
    const Eigen::Matrix<double, 6, 1> x = a.fullPivLu().solve(b);
    const double change = std::max(std::abs(x[4]), std::abs(x[5]));
    y[kUnknownNormalLeft] += x[4];
    y[kUnknownNormalRight] += x[5];
    for (int k = 0; k < 4; ++k) yp[kPoseUnknowns + k] = x[k];
    if (change < 1e-10) break;
  }
  // The spin and the pose rows with the final N.
  std::vector<double> zero(static_cast<size_t>(n), 0.0);
  equations_.residual(formulation_, y.data(), zero.data(), contact_at(y.data()), r.data());
  yp[kUnknownSpinRate] = -r[kUnknownSpinRate] / equations_.parameters().spin_inertia;
  for (int k = 0; k < kPoseUnknowns; ++k) yp[k] = y[kPoseUnknowns + k];
}

RunCounters WheelsetSimulation::ida_counters() const {
  RunCounters c;
  if (!ida_) return c;
  void* mem = ida_.mem();
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
  // 0 for a segment without event functions (elastic), whichever formulation is now current.
  if (IDAGetNumGEvals(mem, &v) == IDA_SUCCESS) c.root_evals = v;
  int order = 0;
  check_sundials(IDAGetLastOrder(mem, &order), "IDAGetLastOrder");
  c.last_order = order;
  double h = 0;
  check_sundials(IDAGetLastStep(mem, &h), "IDAGetLastStep");
  c.last_step = h;
  return c;
}

RunCounters WheelsetSimulation::counters() const {
  RunCounters c = accumulated_;
  const RunCounters now = ida_counters();
  c += now;
  c += own_;
  c.contact_retries += contact_->retries();
  c.contact_timeouts += contact_->timeouts();
  c.last_order = now.last_order;
  c.last_step = now.last_step;
  return c;
}

std::vector<double> WheelsetSimulation::current_state() const {
  return std::vector<double>(y_->data(), y_->data() + y_->size());
}

void WheelsetSimulation::begin_segment(std::vector<double> y, bool first) {
  std::vector<double> yp;
  consistent_derivatives(y, yp);
  const long n = static_cast<long>(y.size());
  const bool rigid = formulation_ == ContactFormulation::kRigid;
  if (!first) {
    accumulated_ += ida_counters();
    ++own_.restarts;
  }
  const bool same_size = y_ && y_->size() == n;
  if (!same_size) {
    y_ = std::make_unique<SerialVector>(n, ctx_.get());
    yp_ = std::make_unique<SerialVector>(n, ctx_.get());
    id_ = std::make_unique<SerialVector>(n, ctx_.get());
    atol_ = std::make_unique<SerialVector>(n, ctx_.get());
    output_state_ = std::make_unique<SerialVector>(n, ctx_.get());
  }
  std::copy(y.begin(), y.end(), y_->data());
  std::copy(yp.begin(), yp.end(), yp_->data());
  const IntegratorSettings& s = spec_.integrator;
  for (long k = 0; k < n; ++k) {
    id_->data()[k] = k <= kUnknownSpinRate ? 1.0 : 0.0;
    atol_->data()[k] = k < kPoseUnknowns ? s.position_tolerance
                       : k <= kUnknownSpinRate ? s.velocity_tolerance
                                               : 1e-6;  // scaled forces and multipliers (Newton test only)
  }
  if (same_size && ida_) {
    check_sundials(IDAReInit(ida_.mem(), t_, y_->get(), yp_->get()), "IDAReInit");
  } else {
    ida_.create(ctx_.get(), ida_residual, t_, y_->get(), yp_->get());
    void* mem = ida_.mem();
    check_sundials(IDASetUserData(mem, this), "IDASetUserData");
    check_sundials(IDASVtolerances(mem, s.relative_tolerance, atol_->get()), "IDASVtolerances");
    check_sundials(IDASetId(mem, id_->get()), "IDASetId");
    check_sundials(IDASetJacFn(mem, ida_jacobian), "IDASetJacFn");
    check_sundials(IDASetMaxStep(mem, s.max_step), "IDASetMaxStep");
    if (rigid) {
      // The multipliers of an index-2 system are left out of the error test.
      check_sundials(IDASetSuppressAlg(mem, SUNTRUE), "IDASetSuppressAlg");
      check_sundials(IDARootInit(mem, kRootCount, ida_roots), "IDARootInit");
      int direction[kRootCount] = {-1, -1, -1, -1};  // events only where a function falls through 0
      check_sundials(IDASetRootDirection(mem, direction), "IDASetRootDirection");
      check_sundials(IDASetNoInactiveRootWarn(mem), "IDASetNoInactiveRootWarn");
    }
  }
  cache_.clear();
}

void WheelsetSimulation::start() {
  const InitialState& init = spec_.initial;
  const double r0 = equations_.nominal_radius();
  std::vector<double> y(static_cast<size_t>(kRigidUnknowns), 0.0);
  y[kUnknownZ] = r0;
  y[kUnknownSpinRate] = spec_.wheelset.speed / r0 + init.spin_rate_offset;
  y[kUnknownNormalLeft] = y[kUnknownNormalRight] = 1.0;
  const ContactFormulation own = formulation_;
  formulation_ = ContactFormulation::kRigid;  // both formulations start from rigid contact
  try {
    // The suspension is relaxed for the centred wheelset in contact.
    project_positions(y);
    equations_.set_z_reference(y[kUnknownZ]);
    y[kUnknownY] = init.y;
    y[kUnknownYaw] = init.yaw;
    y[kUnknownYDot] = init.y_dot;
    y[kUnknownYawDot] = init.yaw_dot;
    project_positions(y);
    // z' and roll' follow from y' and yaw' on the constraints.
    const ContactResult& c = contact_at(y.data());
    Eigen::Matrix2d a;
    Eigen::Vector2d b;
    for (int i = 0; i < 2; ++i) {
      const Eigen::Vector4d& g = c.wheels[static_cast<size_t>(i)].gap_gradient;
      a(i, 0) = g[kUnknownZ];
      a(i, 1) = g[kUnknownRoll];
      b[i] = -(g[kUnknownY] * init.y_dot + g[kUnknownYaw] * init.yaw_dot);
    }
    const Eigen::Vector2d rates = a.fullPivLu().solve(b);
    y[kUnknownZDot] = rates[0];
    y[kUnknownRollDot] = rates[1];
    formulation_ = own;
    if (own == ContactFormulation::kElastic) {
      y.resize(kElasticUnknowns);
      cache_.clear();
      settle_elastic(y, 0.0, 0.0);
    }
  } catch (...) {
    formulation_ = own;
    cache_.clear();
    throw;
  }
  cache_.clear();
  t_ = 0.0;
  begin_segment(y, true);
  next_output_ = 0.0;
  output_index_ = 0;
  record_step_contact(true);
  emit_outputs_until(0.0);
}

std::array<WheelOutput, 2> WheelsetSimulation::wheel_outputs(const std::vector<double>& y) {
  const ContactResult& c = contact_at(y.data());
  std::array<WheelOutput, 2> out;
  for (int i = 0; i < 2; ++i) {
    WheelOutput& w = out[static_cast<size_t>(i)];
    w.s_wheel = c.wheels[static_cast<size_t>(i)].s_wheel;
    w.contact_angle = c.wheels[static_cast<size_t>(i)].contact_angle;
    w.normal_force = equations_.normal_force(formulation_, y.data(), c, i);
  }
  return out;
}

void WheelsetSimulation::record_step_contact(bool restart) {
  const StepContact now{t_, wheel_outputs(current_state())};
  previous_step_ = restart ? now : current_step_;
  current_step_ = now;
}

void WheelsetSimulation::emit_outputs_until(double t) {
  const double period = spec_.integrator.output_period;
  const double t_end = spec_.integrator.t_end;
  SerialVector& tmp = *output_state_;
  while (next_output_ <= t) {
    check_sundials(IDAGetDky(ida_.mem(), next_output_, 0, tmp.get()), "IDAGetDky");
    if (next_output_ == t) N_VScale(1.0, y_->get(), tmp.get());  // exactly the step's state
    std::vector<double> y(tmp.data(), tmp.data() + tmp.size());
    const double span = current_step_.t - previous_step_.t;
    const double w = span > 0.0 ? std::clamp((next_output_ - previous_step_.t) / span, 0.0, 1.0) : 1.0;
    std::array<WheelOutput, 2> wheels;
    for (size_t i = 0; i < 2; ++i) {
      const WheelOutput& a = previous_step_.wheels[i];
      const WheelOutput& b = current_step_.wheels[i];
      wheels[i].s_wheel = a.s_wheel + w * (b.s_wheel - a.s_wheel);
      wheels[i].contact_angle = a.contact_angle + w * (b.contact_angle - a.contact_angle);
      wheels[i].normal_force = formulation_ == ContactFormulation::kRigid
                                   ? equations_.normal_force(formulation_, y.data(), ContactResult{}, static_cast<int>(i))
                                   : a.normal_force + w * (b.normal_force - a.normal_force);
    }
    if (on_output_) on_output_(snapshot_of(y, next_output_, wheels));
    if (next_output_ >= t_end) {
      next_output_ = std::numeric_limits<double>::infinity();
      break;
    }
    ++output_index_;
    next_output_ = std::min(t_end, static_cast<double>(output_index_) * period);
  }
}

WheelsetSnapshot WheelsetSimulation::snapshot_of(const std::vector<double>& y, double t,
                                                 const std::array<WheelOutput, 2>& wheels) {
  WheelsetSnapshot s;
  s.t = t;
  s.y = y[kUnknownY];
  s.z = y[kUnknownZ];
  s.roll = y[kUnknownRoll];
  s.yaw = y[kUnknownYaw];
  s.y_dot = y[kUnknownYDot];
  s.z_dot = y[kUnknownZDot];
  s.roll_dot = y[kUnknownRollDot];
  s.yaw_dot = y[kUnknownYawDot];
  s.spin_rate = y[kUnknownSpinRate];
  s.model = contact_->model();
  s.wheels = wheels;
  return s;
}

WheelsetSnapshot WheelsetSimulation::snapshot() {
  const std::vector<double> y = current_state();
  return snapshot_of(y, t_, wheel_outputs(y));
}

void WheelsetSimulation::fail(const std::string& why) {
  state_ = RunState::kFailed;
  message_ = why;
}

void WheelsetSimulation::request_swap(std::shared_ptr<ContactEvaluator> next) { pending_swap_ = std::move(next); }

void WheelsetSimulation::schedule_swap(double t, std::shared_ptr<ContactEvaluator> next) {
  scheduled_swap_time_ = t;
  scheduled_swap_ = std::move(next);
}

void WheelsetSimulation::perform_swap(std::shared_ptr<ContactEvaluator> next) {
  if (!next) return;
  const ContactFormulation from = formulation_;
  const ContactFormulation to = formulation_of(*next);
  const std::shared_ptr<ContactEvaluator> previous = contact_;
  const std::array<double, 2> previous_tracked = tracked_s_;
  std::vector<double> y = current_state();
  const double z_acceleration = yp_->data()[kUnknownZDot];
  const double roll_acceleration = yp_->data()[kUnknownRollDot];
  try {
    // Elastic to rigid: the elastic normal forces start the rigid ones' iteration.
    std::array<double, 2> normal_forces{0.0, 0.0};
    if (from == ContactFormulation::kElastic && to == ContactFormulation::kRigid) {
      const ContactResult& c = contact_at(y.data());
      for (int i = 0; i < 2; ++i) normal_forces[static_cast<size_t>(i)] = equations_.normal_force(from, y.data(), c, i);
    }
    contact_ = next;
    formulation_ = to;
    tracked_s_ = {kNaN, kNaN};
    cache_.clear();
    if (to == ContactFormulation::kRigid) {
      if (from == ContactFormulation::kElastic) {
        y.resize(kRigidUnknowns, 0.0);
        y[kUnknownNormalLeft] = normal_forces[0] / equations_.force_scale();
        y[kUnknownNormalRight] = normal_forces[1] / equations_.force_scale();
      }
      project_positions(y);
      project_velocities(y);
    } else if (from == ContactFormulation::kRigid) {
      y.resize(kElasticUnknowns);
      settle_elastic(y, z_acceleration, roll_acceleration);
    }
    begin_segment(y, false);
    record_step_contact(true);
    swaps_.push_back({t_, previous->model(), next->model()});
    own_.contact_retries += previous->retries();
    own_.contact_timeouts += previous->timeouts();
  } catch (const std::exception& e) {
    contact_ = previous;
    formulation_ = from;
    tracked_s_ = previous_tracked;
    cache_.clear();
    message_ = "swap to " + next->model() + " at t = " + format_time(t_) + " s failed, keeping " +
               previous->model() + ": " + e.what();
  }
}

void WheelsetSimulation::handle_roots() {
  int info[kRootCount] = {0, 0, 0, 0};
  check_sundials(IDAGetRootInfo(ida_.mem(), info), "IDAGetRootInfo");
  ++own_.root_returns;
  std::vector<double> y = current_state();
  for (int i = 0; i < 2; ++i) {
    if (info[2 + i] != 0) {
      std::ostringstream msg;
      msg << "the " << (i == 0 ? "left" : "right") << " wheel lifts off its rail at t = " << format_time(t_)
          << " s (its normal force falls to 0): the rigid formulation keeps both wheels on their rails; use an "
             "elastic model (multipoint)";
      fail(msg.str());
      return;
    }
  }
  const ContactResult c = contact_at(y.data());
  for (int i = 0; i < 2; ++i) {
    if (info[i] == 0) continue;
    const WheelConstraint& w = c.wheels[static_cast<size_t>(i)];
    switch_log_.push_back({t_, i, w.s_wheel, w.switch_s_wheel});
    tracked_s_[static_cast<size_t>(i)] = w.switch_s_wheel;
    ++own_.contact_switches;
  }
  cache_.clear();
  project_positions(y);
  project_velocities(y);
  begin_segment(y, false);
  record_step_contact(true);
}

bool WheelsetSimulation::advance() {
  if (state_ != RunState::kRunning) return false;
  if (!ida_) {
    fail("advance() before start()");
    return false;
  }
  if (stop_requested_) {
    state_ = RunState::kStopped;
    message_ = "stopped at t = " + format_time(t_) + " s";
    return false;
  }
  try {
    if (pending_swap_) perform_swap(std::exchange(pending_swap_, nullptr));
    const double t_end = spec_.integrator.t_end;
    const double t_stop = t_end;
    check_sundials(IDASetStopTime(ida_.mem(), t_stop), "IDASetStopTime");
    last_contact_error_.clear();
    double t_reached = t_;
    const int flag = IDASolve(ida_.mem(), t_stop, &t_reached, y_->get(), yp_->get(), IDA_ONE_STEP);
    if (flag < 0) {
      std::ostringstream msg;
      msg << "IDASolve failed with flag " << flag << " at t = " << format_time(t_);
      if (!last_contact_error_.empty()) msg << ": " << last_contact_error_;
      fail(msg.str());
      return false;
    }
    t_ = t_reached;
    record_step_contact(false);
    emit_outputs_until(t_);
    if (flag == IDA_ROOT_RETURN) {
      handle_roots();
      if (state_ != RunState::kRunning) return false;
    } else if (formulation_ == ContactFormulation::kRigid) {
      // Follow the branches with the accepted step (the event functions were evaluated there).
      const ContactResult c = contact_at(y_->data());
      tracked_s_ = {c.wheels[0].s_wheel, c.wheels[1].s_wheel};
    }
    if (flag == IDA_TSTOP_RETURN && t_ >= t_end) {
      state_ = RunState::kFinished;
      return false;
    }
    // A scheduled swap acts at the first step boundary at or after its time, as a live one does
    // at the first boundary after it arrived (no stop time: the steps stay those of the live run).
    if (scheduled_swap_ && t_ >= scheduled_swap_time_) perform_swap(std::exchange(scheduled_swap_, nullptr));
    if (counters().steps >= spec_.integrator.max_steps) {
      fail("more than " + std::to_string(spec_.integrator.max_steps) + " steps before t_end");
      return false;
    }
    return true;
  } catch (const std::exception& e) {
    fail(e.what());
    return false;
  }
}

void WheelsetSimulation::run() {
  if (!ida_) start();
  while (advance()) {
  }
}

}  // namespace wrc
