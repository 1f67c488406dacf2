// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/wheelset_simulation.hpp"

#include "core/dynamics/consistent_initialisation.hpp"
#include "core/dynamics/rail_placement.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>

#include "core/models/contact_model_factory.hpp"
#include "core/models/wheel_constraint.hpp"
#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// [-] contact results kept for the states last asked (the residual, root and output functions
// ask again for the states of the step just taken).
constexpr size_t kCacheSize = 8;
// switch L, switch R, normal force L, normal force R, second point's normal force L, R
constexpr int kRootCount = 6;
// [m] how far a followed point may lie above the lowest minimum at an accepted step (root finding
// stops within ~1e-15 m of the crossing); more is a switch the root finding did not see.
constexpr double kBranchTolerance = 1e-9;
// Switches of one event: at most this many in a row before the run fails (a cycle).
constexpr int kMaxSwitchesPerEvent = 8;
// [-] relative change of IDA's cj (alpha / h) beyond which the Newton matrix is rebuilt: 0, at
// every change (IDA's default 0.25).
constexpr double kNewtonMatrixCjChange = 0.0;
// Restarts after a corrector failure at one time before the run fails (rigid formulation).
constexpr int kMaxConvergenceRestartsInARow = 3;
// Corrector iterations per step of the rigid (index-2) formulation (IDA's default: 4).
constexpr int kMaxNewtonIterations = 8;

WheelsetSimulation* self(void* user) { return static_cast<WheelsetSimulation*>(user); }

// Each callback first places the equations on the track where the wheelset is at its time.
int ida_residual(sunrealtype t, N_Vector y, N_Vector yp, N_Vector r, void* user) {
  self(user)->place_on_track(t);
  return self(user)->residual_callback(N_VGetArrayPointer(y), N_VGetArrayPointer(yp), N_VGetArrayPointer(r));
}

int ida_jacobian(sunrealtype t, sunrealtype cj, N_Vector y, N_Vector yp, N_Vector r, SUNMatrix jac, void* user,
                 N_Vector, N_Vector, N_Vector) {
  self(user)->place_on_track(t);
  return self(user)->jacobian_callback(cj, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), N_VGetArrayPointer(r), jac);
}

void ida_message(int, const char*, const char* function, char* text, void* user) {
  self(user)->solver_message(function, text);
}

int ida_roots(sunrealtype t, N_Vector y, N_Vector, sunrealtype* g, void* user) {
  self(user)->place_on_track(t);
  return self(user)->root_callback(N_VGetArrayPointer(y), g);
}

ContactFormulation formulation_of(const ContactEvaluator& contact) {
  return contact_model_entry(contact.model()).dynamics_formulation;
}

std::string format_time(double t) { return exact_number_text(t); }

// [-] relative finite-difference increment of the Jacobian: about the square root of the contact
// result's relative rounding, so that truncation and rounding errors are alike.
constexpr double kRelativeIncrement = 1e-7;
// The magnitudes below which an unknown's increment stops shrinking with it (an unknown at 0 still
// moves): scaled normal forces and multipliers [-], spin rate [rad/s], the pose and its rates
// [m, rad, m/s, rad/s].
constexpr double kTypicalScaledForce = 1.0;
constexpr double kTypicalSpinRate = 10.0;
constexpr double kTypicalPose = 1e-2;
// [-] IDA's absolute tolerance of the scaled normal forces and multipliers (they are left out of
// the error test; it only scales the Newton test).
constexpr double kScaledForceTolerance = 1e-6;
// [-] the scaled normal forces the start's projection begins from (force_scale each).
constexpr double kStartScaledNormalForce = 1.0;

// Finite-difference increment of unknown k at value v.
double increment(int k, double v) {
  const double typical =
      k >= kUnknownNormalLeft ? kTypicalScaledForce : (k == kUnknownSpinRate ? kTypicalSpinRate : kTypicalPose);
  return kRelativeIncrement * std::max(std::abs(v), typical);
}

}  // namespace

WheelsetSimulation::WheelsetSimulation(RunSpec spec, std::shared_ptr<ContactEvaluator> contact, double nominal_radius)
    : spec_(spec), equations_(spec.wheelset, nominal_radius, nominal_radius), contact_(std::move(contact)) {
  spec_.validate();
  if (!contact_) throw std::invalid_argument("WheelsetSimulation: no contact evaluator");
  if (!(nominal_radius > 0.0)) throw std::invalid_argument("WheelsetSimulation: nominal radius must be > 0");
  formulation_ = formulation_of(*contact_);
}

WheelsetSimulation::~WheelsetSimulation() = default;

int WheelsetSimulation::unknowns() const { return unknown_count(formulation_, branches_.any_two_point()); }

void WheelsetSimulation::set_branches(const FollowedBranches& branches, std::vector<double>& y) {
  const bool now = branches.any_two_point();
  branches_ = branches;
  if (formulation_ == ContactFormulation::kRigid) y.resize(static_cast<size_t>(unknowns()), 0.0);
  for (int i = 0; i < 2 && now; ++i)
    if (!branches_.two_point(i)) y[kUnknownSecondNormalLeft + i] = y[kUnknownSecondMuLeft + i] = 0.0;
  cache_.clear();
}

std::array<double, 2> WheelsetSimulation::branch_excess(const ContactResult& c) const {
  return {-c.wheels[0].switch_function, -c.wheels[1].switch_function};
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

void WheelsetSimulation::place_on_track(double t) {
  const double s = spec_.wheelset.speed * t;
  if (!spec_.track.straight()) equations_.set_track(spec_.track.at(s));  // straight, level: nothing moves
  if (!spec_.irregularity.empty())
    equations_.set_rails(rail_offsets_at(spec_.irregularity.at(s), spec_.track.cant_base(), spec_.wheelset.speed));
}

const ContactResult& WheelsetSimulation::contact_at(const double* y) {
  const bool two_point = branches_.any_two_point();
  std::vector<double> key;
  key.reserve(kTwoPointRigidUnknowns + 4);
  for (int k = 0; k < unknowns(); ++k)
    if (enters_contact_query(formulation_, two_point, k)) key.push_back(y[k]);
  key.insert(key.end(), branches_.tracked_s.begin(), branches_.tracked_s.end());
  key.insert(key.end(), branches_.second_s.begin(), branches_.second_s.end());
  // The track's turning rate enters the query's yaw rate and speed (WheelsetEquations::query).
  key.push_back(equations_.track().curvature);
  // The rails' offsets and rates enter the query (irregularities).
  if (!spec_.irregularity.empty()) {
    for (const RailOffset& r : equations_.rails())
      key.insert(key.end(), {r.lateral, r.vertical, r.roll, r.lateral_rate, r.vertical_rate, r.roll_rate});
  }
  for (const CachedContact& c : cache_)
    if (c.key.size() == key.size() && std::memcmp(c.key.data(), key.data(), key.size() * sizeof(double)) == 0)
      return c.result;
  std::vector<ContactResult> r = evaluate({equations_.query(formulation_, y, branches_)});
  if (cache_.size() >= kCacheSize) cache_.pop_front();
  cache_.push_back({std::move(key), std::move(r.front())});
  return cache_.back().result;
}

int WheelsetSimulation::residual_callback(const double* y, const double* yp, double* r) {
  try {
    equations_.residual(formulation_, y, yp, contact_at(y), branches_, r);
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
    const int n = unknowns();
    const bool two_point = branches_.any_two_point();
    // Every perturbation that changes the contact query in one batch: one round trip.
    std::vector<ContactQuery> batch;
    std::vector<int> batch_index(static_cast<size_t>(n), -1);
    std::vector<std::vector<double>> perturbed(static_cast<size_t>(n), std::vector<double>(y, y + n));
    std::vector<double> step(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
      step[k] = increment(k, y[k]);
      perturbed[k][k] += step[k];
      step[k] = perturbed[k][k] - y[k];  // the increment actually represented
      if (!enters_contact_query(formulation_, two_point, k)) continue;
      batch_index[static_cast<size_t>(k)] = static_cast<int>(batch.size());
      batch.push_back(equations_.query(formulation_, perturbed[k].data(), branches_));
    }
    const ContactResult base = contact_at(y);
    std::vector<ContactResult> results = evaluate(batch);
    ++own_.jacobian_evals;
    own_.jacobian_residual_evals += n;
    std::vector<double> column(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
      const int b = batch_index[static_cast<size_t>(k)];
      const ContactResult& c = b >= 0 ? results[static_cast<size_t>(b)] : base;
      equations_.residual(formulation_, perturbed[k].data(), yp, c, branches_, column.data());
      for (int i = 0; i < n; ++i) SM_ELEMENT_D(jac, i, k) = (column[i] - r[i]) / step[k];
      SM_ELEMENT_D(jac, k, k) += cj * equations_.derivative_coefficient(k);
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

void WheelsetSimulation::solver_message(const char* function, const char* text) {
  last_solver_message_ = std::string(function ? function : "IDA") + ": " + (text ? text : "");
}

int WheelsetSimulation::root_callback(const double* y, double* g) {
  try {
    const ContactResult& c = contact_at(y);
    g[0] = c.wheels[0].switch_function;
    g[1] = c.wheels[1].switch_function;
    g[2] = y[kUnknownNormalLeft];
    g[3] = y[kUnknownNormalRight];
    g[4] = branches_.two_point(0) ? y[kUnknownSecondNormalLeft] : 1.0;
    g[5] = branches_.two_point(1) ? y[kUnknownSecondNormalRight] : 1.0;
    return 0;
  } catch (const std::exception& e) {
    last_contact_error_ = e.what();
    return -1;
  }
}

InitialisationContext WheelsetSimulation::initialisation() {
  InitialisationContext context{equations_, formulation_, branches_,
                                [this](const double* y) -> const ContactResult& { return contact_at(y); },
                                [this](const std::vector<ContactQuery>& batch) { return evaluate(batch); },
                                {}};
  if (!spec_.irregularity.empty()) {
    context.contact_later = [this](const double* y, double dt) {
      place_on_track(t_ + dt);
      try {
        ContactResult later = evaluate({equations_.query(formulation_, y, branches_)}).front();
        place_on_track(t_);
        return later;
      } catch (...) {
        place_on_track(t_);
        throw;
      }
    };
  }
  return context;
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
  c.contact_failovers += contact_->failovers();
  c.last_order = now.last_order;
  c.last_step = now.last_step;
  return c;
}

std::vector<double> WheelsetSimulation::current_state() const {
  return std::vector<double>(y_->data(), y_->data() + y_->size());
}

void WheelsetSimulation::begin_segment(std::vector<double> y, bool first) {
  std::vector<double> yp;
  consistent_derivatives(initialisation(), y, yp);
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
                                               : kScaledForceTolerance;
  }
  if (same_size && ida_) {
    check_sundials(IDAReInit(ida_.mem(), t_, y_->get(), yp_->get()), "IDAReInit");
  } else {
    ida_.create(ctx_.get(), ida_residual, t_, y_->get(), yp_->get());
    void* mem = ida_.mem();
    check_sundials(IDASetUserData(mem, this), "IDASetUserData");
    check_sundials(IDASetErrHandlerFn(mem, ida_message, this), "IDASetErrHandlerFn");
    check_sundials(IDASVtolerances(mem, s.relative_tolerance, atol_->get()), "IDASVtolerances");
    check_sundials(IDASetId(mem, id_->get()), "IDASetId");
    check_sundials(IDASetJacFn(mem, ida_jacobian), "IDASetJacFn");
    check_sundials(IDASetMaxStep(mem, s.max_step), "IDASetMaxStep");
    // A new Newton matrix whenever the step's coefficient cj changes (IDA's default waits for a
    // 25 % change): one Jacobian is one batched contact query, a round trip like one Newton
    // iteration, and the fresh matrix saves more iterations than it costs. Measured in-process
    // (contact queries, IDA's default -> this): the paper's benchmark spline 1173 -> 1115,
    // multipoint 5338 -> 4047, interp 1927 -> 1705, onepoint 13509 -> 13791; the 1 km irregular
    // curve with the spline model 75806 -> 59355 (Newton iterations 2.15 -> 1.34 per step).
    check_sundials(IDASetDeltaCjLSetup(mem, kNewtonMatrixCjChange), "IDASetDeltaCjLSetup");
    if (rigid) {
      // The multipliers of an index-2 system are left out of the error test.
      check_sundials(IDASetSuppressAlg(mem, SUNTRUE), "IDASetSuppressAlg");
      // The index-2 Newton matrix is ill-conditioned at small steps (~1/h^2); right after a switch
      // on the switching surface its corrector may need more than IDA's default 4 iterations (seen:
      // mu = 0.01, y0 = 1e-8, the first step after a restart failing down to h = 2.5e-15 with 4,
      // passing with 8). A step that converges in 4 is unchanged.
      check_sundials(IDASetMaxNonlinIters(mem, kMaxNewtonIterations), "IDASetMaxNonlinIters");
      check_sundials(IDARootInit(mem, kRootCount, ida_roots), "IDARootInit");
      int direction[kRootCount] = {-1, -1, -1, -1};  // events only where a function falls through 0
      check_sundials(IDASetRootDirection(mem, direction), "IDASetRootDirection");
      check_sundials(IDASetNoInactiveRootWarn(mem), "IDASetNoInactiveRootWarn");
    }
  }
  cache_.clear();
}

void WheelsetSimulation::start() {
  place_on_track(0.0);
  const InitialState& init = spec_.initial;
  const double r0 = equations_.nominal_radius();
  std::vector<double> y(static_cast<size_t>(kRigidUnknowns), 0.0);
  y[kUnknownZ] = r0;
  y[kUnknownSpinRate] = spec_.wheelset.speed / r0 + init.spin_rate_offset;
  y[kUnknownNormalLeft] = y[kUnknownNormalRight] = kStartScaledNormalForce;
  const ContactFormulation own = formulation_;
  formulation_ = ContactFormulation::kRigid;  // both formulations start from rigid contact
  try {
    // The suspension is relaxed for the centred wheelset in contact on the nominal track.
    const std::array<RailOffset, 2> rails = equations_.rails();
    equations_.set_rails({});
    project_positions(initialisation(), y);
    equations_.set_z_reference(y[kUnknownZ]);
    equations_.set_rails(rails);
    y[kUnknownY] = init.y;
    y[kUnknownYaw] = init.yaw;
    y[kUnknownYDot] = init.y_dot;
    y[kUnknownYawDot] = init.yaw_dot;
    project_positions(initialisation(), y);
    // z' and roll' follow from y' and yaw' on the constraints (and the rails' rates).
    const ContactResult& c = contact_at(y.data());
    Eigen::Matrix2d a;
    Eigen::Vector2d b;
    for (int i = 0; i < 2; ++i) {
      const Eigen::Vector4d& g = c.wheels[static_cast<size_t>(i)].gap_gradient;
      a(i, 0) = g[kUnknownZ];
      a(i, 1) = g[kUnknownRoll];
      b[i] = -(g[kUnknownY] * init.y_dot + g[kUnknownYaw] * init.yaw_dot + c.wheels[static_cast<size_t>(i)].gap_rate);
    }
    const Eigen::Vector2d rates = a.fullPivLu().solve(b);
    y[kUnknownZDot] = rates[0];
    y[kUnknownRollDot] = rates[1];
    formulation_ = own;
    if (own == ContactFormulation::kElastic) {
      y.resize(kElasticUnknowns);
      cache_.clear();
      settle_elastic(initialisation(), y, 0.0, 0.0);
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
  extremes_ = RunExtremes{};
  record_step_contact(true);
  emit_outputs_until(0.0);
}

std::array<WheelOutput, 2> WheelsetSimulation::wheel_outputs(const std::vector<double>& y,
                                                             std::array<WheelForces, 2>* forces) {
  const ContactResult& c = contact_at(y.data());
  std::array<WheelOutput, 2> out;
  for (int i = 0; i < 2; ++i) {
    WheelOutput& w = out[static_cast<size_t>(i)];
    w.s_wheel = c.wheels[static_cast<size_t>(i)].s_wheel;
    w.contact_angle = c.wheels[static_cast<size_t>(i)].contact_angle;
    w.normal_force = equations_.normal_force(formulation_, y.data(), c, i, branches_);
    // The wheel's normal force: rigid, the constraint's multiplier, which a spline transition
    // shares over two patches (their normal forces add up to it as vectors, not as magnitudes);
    // elastic, the patches' own sum, what wheel_forces() takes by default.
    const WheelForces f = w.normal_force > 0.0 ? wheel_forces(c, i, w.normal_force) : wheel_forces(c, i);
    set_force_outputs(f, w.normal_force, i, w);
    if (forces) (*forces)[static_cast<size_t>(i)] = f;
  }
  return out;
}

void WheelsetSimulation::record_step_contact(bool restart) {
  StepContact now{t_, {}, {}};
  now.wheels = wheel_outputs(current_state(), &now.forces);
  previous_step_ = restart ? now : current_step_;
  current_step_ = now;
  extremes_.observe(t_, spec_.wheelset.speed * t_, now.wheels);
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
                                   ? equations_.normal_force(formulation_, y.data(), ContactResult{}, static_cast<int>(i), branches_)
                                   : a.normal_force + w * (b.normal_force - a.normal_force);
      set_force_outputs(interpolate(previous_step_.forces[i], current_step_.forces[i], w), wheels[i].normal_force,
                        static_cast<int>(i), wheels[i]);
    }
    extremes_.observe(next_output_, spec_.wheelset.speed * next_output_, wheels);
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
  const FollowedBranches previous_branches = branches_;
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
    if (from == ContactFormulation::kRigid && branches_.any_two_point()) {
      // The new model starts in one-point contact: each wheel's load on its first point.
      for (int i = 0; i < 2; ++i) y[kUnknownNormalLeft + i] += y[kUnknownSecondNormalLeft + i];
      y.resize(kRigidUnknowns);
    }
    contact_ = next;
    formulation_ = to;
    branches_ = FollowedBranches{};
    cache_.clear();
    if (to == ContactFormulation::kRigid) {
      if (from == ContactFormulation::kElastic) {
        y.resize(kRigidUnknowns, 0.0);
        y[kUnknownNormalLeft] = normal_forces[0] / equations_.force_scale();
        y[kUnknownNormalRight] = normal_forces[1] / equations_.force_scale();
      }
      project_positions(initialisation(), y);
      project_velocities(initialisation(), y);
    } else if (from == ContactFormulation::kRigid) {
      y.resize(kElasticUnknowns);
      settle_elastic(initialisation(), y, z_acceleration, roll_acceleration);
    }
    begin_segment(y, false);
    record_step_contact(true);
    swaps_.push_back({t_, previous->model(), next->model()});
    own_.contact_retries += previous->retries();
    own_.contact_timeouts += previous->timeouts();
    own_.contact_failovers += previous->failovers();
  } catch (const std::exception& e) {
    contact_ = previous;
    formulation_ = from;
    branches_ = previous_branches;
    cache_.clear();
    message_ = "swap to " + next->model() + " at t = " + format_time(t_) + " s failed, keeping " +
               previous->model() + ": " + e.what();
  }
}

void WheelsetSimulation::switch_wheel(int wheel, double target_s, std::vector<double>& y) {
  const size_t w = static_cast<size_t>(wheel);
  // The point it leaves can pair with the target only in one-point contact (a two-point
  // contact's events leave it for a third point or the survivor of a fold).
  const double from_s = branches_.two_point(wheel) ? kNaN : branches_.tracked_s[w];
  const FollowedBranches before = branches_;
  const std::vector<double> y_before = y;
  const double load = y[kUnknownNormalLeft + wheel] +
                      (before.two_point(wheel) ? y[kUnknownSecondNormalLeft + wheel] : 0.0);
  FollowedBranches single = before;
  single.tracked_s[w] = target_s;
  single.second_s[w] = kNaN;
  // One-point contact on the target: positions onto its gap, velocities onto its constraint
  // (an inelastic impact).
  std::vector<double> y_single = y_before;
  set_branches(single, y_single);
  y_single[kUnknownNormalLeft + wheel] = load;
  project_positions(initialisation(), y_single);
  project_velocities(initialisation(), y_single);
  // Without two-point sliding (the run's choice) one-point contact on the target is the answer
  // whatever the point it leaves does next: the chattering of the paper's figures 5 and 6.
  if (std::isnan(from_s) || !spec_.integrator.two_point_sliding) {
    y = std::move(y_single);
    return;
  }
  // Would the point it leaves separate? Its gap rate under the one-point velocities.
  FollowedBranches pair = single;
  pair.second_s[w] = from_s;
  std::vector<double> y_pair = y_single;
  set_branches(pair, y_pair);
  bool from_separates = true;
  bool pair_valid = false;
  try {
    const ContactResult& c = contact_at(y_pair.data());
    const std::optional<WheelConstraint>& from = c.second_wheels[w];
    pair_valid = from && std::abs(from->s_wheel - from_s) <= kBranchLostDistance && c.wheels[w].switch_function > 0.0;
    if (pair_valid) {
      double rate = from->gap_rate;
      for (int k = 0; k < kPoseUnknowns; ++k) rate += from->gap_gradient[k] * y_pair[kPoseUnknowns + k];
      from_separates = rate > 0.0;
    }
  } catch (const ContactConfigurationError&) {
    pair_valid = false;
  }
  if (!pair_valid || from_separates) {
    set_branches(single, y_single);
    y = std::move(y_single);
    return;
  }
  // Not separating: the impact acts on both points, and the two-point contact's normal forces
  // decide (both > 0: the sliding mode; one <= 0: that point leaves at once).
  y_pair = y_before;
  set_branches(pair, y_pair);
  y_pair[kUnknownNormalLeft + wheel] = 0.5 * load;
  y_pair[kUnknownSecondNormalLeft + wheel] = 0.5 * load;
  std::vector<double> yp_pair;
  try {
    project_positions(initialisation(), y_pair);
    project_velocities(initialisation(), y_pair);
    consistent_derivatives(initialisation(), y_pair, yp_pair);
  } catch (const std::exception&) {
    set_branches(single, y_single);
    y = std::move(y_single);
    return;
  }
  const double n_target = y_pair[kUnknownNormalLeft + wheel];
  const double n_from = y_pair[kUnknownSecondNormalLeft + wheel];
  if (n_target > 0.0 && n_from > 0.0) {
    ++own_.two_point_entries;
    y = std::move(y_pair);
    return;
  }
  FollowedBranches stay = pair;
  stay.second_s[w] = kNaN;
  if (!(n_from > 0.0)) {
    // The point it leaves unloads: one-point contact on the target with the impact's velocities.
    set_branches(stay, y_pair);
    y_pair[kUnknownNormalLeft + wheel] = load;
    y = std::move(y_pair);
    return;
  }
  // The target unloads: it only touched; stay on the point it was on.
  stay.tracked_s[w] = from_s;
  set_branches(stay, y_pair);
  y_pair[kUnknownNormalLeft + wheel] = load;
  y = std::move(y_pair);
}

void WheelsetSimulation::release_point(int wheel, bool second, std::vector<double>& y) {
  const size_t w = static_cast<size_t>(wheel);
  FollowedBranches next = branches_;
  const double remaining_load = second ? y[kUnknownNormalLeft + wheel] : y[kUnknownSecondNormalLeft + wheel];
  if (!second) next.tracked_s[w] = next.second_s[w];
  next.second_s[w] = kNaN;
  set_branches(next, y);
  y[kUnknownNormalLeft + wheel] = remaining_load;
}

void WheelsetSimulation::handle_roots() {
  int info[kRootCount] = {0, 0, 0, 0, 0, 0};
  check_sundials(IDAGetRootInfo(ida_.mem(), info), "IDAGetRootInfo");
  ++own_.root_returns;
  std::vector<double> y = current_state();
  for (int i = 0; i < 2; ++i) {
    if (info[2 + i] != 0 && !branches_.two_point(i)) {
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
    const size_t w = static_cast<size_t>(i);
    if (branches_.two_point(i) && (info[2 + i] != 0 || info[4 + i] != 0)) {
      // One point of a two-point contact unloads: the sliding mode ends, the other point carries on.
      const bool second = info[4 + i] != 0;
      const double released = second ? branches_.second_s[w] : branches_.tracked_s[w];
      const double kept = second ? branches_.tracked_s[w] : branches_.second_s[w];
      switch_log_.push_back({t_, i, released, kept});
      release_point(i, second, y);
      ++own_.contact_switches;
      continue;
    }
    if (info[i] == 0) continue;
    const WheelConstraint& wc = c.wheels[w];
    switch_log_.push_back({t_, i, wc.s_wheel, wc.switch_s_wheel});
    switch_wheel(i, wc.switch_s_wheel, y);
    ++own_.contact_switches;
  }
  restart_on_right_branches(y);
}

void WheelsetSimulation::restart_after_convergence_failure() {
  // Seen where a wheel slides with two points in contact between two nearly equally low minima
  // (S1002's flange root on UIC60's gauge corner and its tread root on the shoulder, 10 to 40 um
  // apart in height over millimetres of y) while irregularities move the rails: after a train of
  // one-point switches ever closer together the two-point segment's corrector fails at every step
  // size, on the first step or later with one point unloading. Released to one-point contact on
  // the more loaded point and restarted from consistent values, the run goes on; a new segment
  // alone was enough in one case of two (a 300 m ERRI low track), not in the other (1 km).
  ++convergence_restarts_in_a_row_;
  ++own_.convergence_restarts;
  std::vector<double> y = current_state();
  for (int i = 0; i < 2; ++i) {
    if (!branches_.two_point(i)) continue;
    const size_t w = static_cast<size_t>(i);
    const bool second = y[static_cast<size_t>(kUnknownSecondNormalLeft + i)] < y[static_cast<size_t>(kUnknownNormalLeft + i)];
    const double released = second ? branches_.second_s[w] : branches_.tracked_s[w];
    const double kept = second ? branches_.tracked_s[w] : branches_.second_s[w];
    switch_log_.push_back({t_, i, released, kept});
    release_point(i, second, y);
    ++own_.contact_switches;
  }
  restart_on_right_branches(y);
}

void WheelsetSimulation::restart_on_right_branches(std::vector<double>& y) {
  // A new segment starts with every followed point the lowest (the projections may have moved
  // another one below it): switch again until it does.
  for (int round = 0;; ++round) {
    cache_.clear();
    project_positions(initialisation(), y);
    project_velocities(initialisation(), y);
    const ContactResult c = contact_at(y.data());
    const std::array<double, 2> excess = branch_excess(c);
    int wrong = -1;
    for (int i = 0; i < 2 && wrong < 0; ++i)
      if (excess[static_cast<size_t>(i)] > kBranchTolerance) wrong = i;
    // Without two-point sliding the wheel stays where the switch put it: switching back at once
    // would chatter without end (docs/dynamics.md).
    if (wrong < 0 || !spec_.integrator.two_point_sliding) break;
    if (round >= kMaxSwitchesPerEvent) {
      std::ostringstream msg;
      msg << "the " << (wrong == 0 ? "left" : "right") << " wheel's contact point finds no branch that is the lowest"
          << " at t = " << format_time(t_) << " s after " << kMaxSwitchesPerEvent << " switches";
      throw std::runtime_error(msg.str());
    }
    const WheelConstraint& wc = c.wheels[static_cast<size_t>(wrong)];
    switch_log_.push_back({t_, wrong, wc.s_wheel, wc.switch_s_wheel});
    switch_wheel(wrong, wc.switch_s_wheel, y);
    ++own_.contact_switches;
  }
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
    last_solver_message_.clear();
    double t_reached = t_;
    const int flag = IDASolve(ida_.mem(), t_stop, &t_reached, y_->get(), yp_->get(), IDA_ONE_STEP);
    if (flag == IDA_CONV_FAIL && formulation_ == ContactFormulation::kRigid &&
        convergence_restarts_in_a_row_ < kMaxConvergenceRestartsInARow) {
      restart_after_convergence_failure();
      return state_ == RunState::kRunning;
    }
    if (flag < 0) {
      std::ostringstream msg;
      msg << "IDASolve failed with flag " << flag << " at t = " << format_time(t_);
      if (!last_contact_error_.empty()) msg << ": " << last_contact_error_;
      if (!last_solver_message_.empty()) msg << " (" << last_solver_message_ << ")";
      fail(msg.str());
      return false;
    }
    for (int i = 0; i < 2; ++i)
      if (branches_.two_point(i)) own_.two_point_time += t_reached - t_;
    const double step = t_reached - t_;
    if (step > 0) convergence_restarts_in_a_row_ = 0;
    t_ = t_reached;
    place_on_track(t_);
    record_step_contact(false);
    // Conformal patches (Hertz's floor on the lateral curvature) at the accepted step.
    long floored = 0;
    for (const ContactPatch& p : contact_at(y_->data()).patches) floored += p.lateral_curvature_floored ? 1 : 0;
    own_.floored_patches += floored;
    if (floored > 0) own_.floored_time += step;
    emit_outputs_until(t_);
    if (flag == IDA_ROOT_RETURN) {
      handle_roots();
      if (state_ != RunState::kRunning) return false;
    } else if (formulation_ == ContactFormulation::kRigid) {
      // Follow the branches with the accepted step (the event functions were evaluated there),
      // and check that every followed point is the lowest: a switch the root finding did not see
      // (an event function that starts a segment below 0, or crosses 0 and back within a step)
      // is taken here. Without two-point sliding only the roots switch (the paper's one-point
      // contact): the excess is recorded, not corrected.
      const ContactResult c = contact_at(y_->data());
      const std::array<double, 2> excess = branch_excess(c);
      bool missed = false;
      for (int i = 0; i < 2; ++i) {
        own_.max_branch_excess = std::max(own_.max_branch_excess, excess[static_cast<size_t>(i)]);
        missed = missed || excess[static_cast<size_t>(i)] > kBranchTolerance;
      }
      if (missed && spec_.integrator.two_point_sliding) {
        ++own_.missed_switches;
        ++own_.root_returns;
        std::vector<double> y = current_state();
        restart_on_right_branches(y);
      } else {
        for (int i = 0; i < 2; ++i) {
          const size_t w = static_cast<size_t>(i);
          branches_.tracked_s[w] = c.wheels[w].s_wheel;
          if (branches_.two_point(i)) branches_.second_s[w] = c.second_wheels[w]->s_wheel;
        }
      }
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
