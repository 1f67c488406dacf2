// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/wheelset_simulation.hpp"

#include "core/dynamics/consistent_initialisation.hpp"
#include "core/dynamics/rail_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>

#include "core/dynamics/ida_callback_status.hpp"
#include "core/dynamics/segment_settings.hpp"
#include "core/dynamics/wheelset_jacobian.hpp"
#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

// Restarts after a corrector failure at one time before the run fails (rigid formulation).
constexpr int kMaxConvergenceRestartsInARow = 3;
// [-] the scaled normal forces the start's projection begins from (force_scale each).
constexpr double kStartScaledNormalForce = 1.0;

std::string format_time(double t) { return exact_number_text(t); }

// The contact evaluator of a run, once the run's spec and nominal radius [m] are checked.
std::shared_ptr<ContactEvaluator> checked_contact(const RunSpec& spec, std::shared_ptr<ContactEvaluator> contact,
                                                  double nominal_radius) {
  spec.validate();
  if (!contact) throw std::invalid_argument("WheelsetSimulation: no contact evaluator");
  if (!(nominal_radius > 0.0)) throw std::invalid_argument("WheelsetSimulation: nominal radius must be > 0");
  return contact;
}

// How IDA integrates a segment of n unknowns in formulation f.
IdaSegment segment_settings(const IntegratorSettings& s, ContactFormulation f, long n) {
  const bool rigid = f == ContactFormulation::kRigid;
  IdaSegment segment = segment_settings_without_unknowns(s, rigid);
  append_wheelset_unknowns(segment, s, static_cast<int>(n));
  if (rigid) segment.root_direction.assign(kEventDirections.begin(), kEventDirections.end());
  return segment;
}

}  // namespace

WheelsetSimulation::WheelsetSimulation(RunSpec spec, std::shared_ptr<ContactEvaluator> contact, double nominal_radius)
    : spec_(spec),
      equations_(spec.wheelset, nominal_radius, nominal_radius),
      contact_(checked_contact(spec_, std::move(contact), nominal_radius), equations_, !spec_.irregularity.empty()),
      integrator_(*this),
      output_(spec_.integrator.output_period, spec_.integrator.t_end, spec_.wheelset.speed) {}

WheelsetSimulation::~WheelsetSimulation() = default;

void WheelsetSimulation::place_on_track(double t) {
  const double s = spec_.wheelset.speed * t;
  if (!spec_.track.straight()) equations_.set_track(spec_.track.at(s));  // straight, level: nothing moves
  if (!spec_.irregularity.empty())
    equations_.set_rails(rail_offsets_at(spec_.irregularity.at(s), spec_.track.cant_base(), spec_.wheelset.speed));
}

int WheelsetSimulation::residual(double t, const double* y, const double* yp, double* r) {
  place_on_track(t);
  return ida_callback_status(last_contact_error_, [&] {
    const ContactResult& c = residual_contact(contact_, y, integrator_.newton_matrix_expected());
    equations_.residual(contact_.formulation(), y, yp, c, contact_.branches(), r);
  });
}

int WheelsetSimulation::jacobian(double t, double cj, const double* y, const double* yp, const double* r,
                                 DenseMatrixView jac) {
  place_on_track(t);
  return ida_callback_status(last_contact_error_,
                             [&] { wheelset_jacobian(equations_, contact_, cj, y, yp, r, jac, own_); });
}

void WheelsetSimulation::message(const char* function, const char* text) {
  last_solver_message_ = std::string(function ? function : "IDA") + ": " + (text ? text : "");
}

std::vector<WheelsetContact::Ahead> WheelsetSimulation::next_step_ahead(double t) {
  if (!spec_.integrator.contact_ahead || !(t < spec_.integrator.t_end)) return {};  // no step after t_end
  const std::optional<IdaIntegrator::NextStep> next = integrator_.next_step();
  if (!next) return {};
  // After an accepted step a rigid run follows its points (check_branches()), so the next step's
  // queries follow the answer for the accepted state; an elastic run follows none.
  const bool follows = contact_.formulation() == ContactFormulation::kRigid;
  place_on_track(next->t);
  std::vector<WheelsetContact::Ahead> ahead{contact_.ahead(next->y.data(), follows)};
  if (integrator_.newton_matrix_expected(next->cj)) {
    std::vector<WheelsetContact::Ahead> jacobian = jacobian_ahead(contact_, next->y.data(), follows);
    ahead.insert(ahead.end(), jacobian.begin(), jacobian.end());
  }
  place_on_track(t);
  return ahead;
}

int WheelsetSimulation::roots(double t, const double* y, double* g) {
  place_on_track(t);
  try {
    // At the accepted step's state (IDA's current time) the next step's first residual, and its
    // Jacobian's states where a new Newton matrix is due, travel with this query.
    const ContactResult& c = t == integrator_.current_time() ? contact_.at(y, next_step_ahead(t)) : contact_.at(y);
    event_functions(c, y, contact_.branches(), g);
    return 0;
  } catch (const std::exception& e) {
    last_contact_error_ = e.what();
    return -1;
  }
}

InitialisationContext WheelsetSimulation::initialisation() {
  InitialisationContext context{equations_, contact_.formulation(), contact_.branches(),
                                [this](const double* y) -> const ContactResult& { return contact_.at(y); },
                                [this](const std::vector<ContactQuery>& batch) { return contact_.evaluate(batch); },
                                {}};
  if (!spec_.irregularity.empty()) {
    context.contact_later = [this](const double* y, double dt) {
      place_on_track(t_ + dt);
      try {
        ContactResult later =
            contact_.evaluate({equations_.query(contact_.formulation(), y, contact_.branches())}).front();
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

SwitchingContext WheelsetSimulation::switching() {
  return SwitchingContext{contact_, [this] { return initialisation(); }, spec_.integrator.two_point_sliding, t_,
                          switch_log_, own_, 0};
}

RunCounters WheelsetSimulation::counters() const {
  RunCounters c = accumulated_;
  const RunCounters now = integrator_.counters();
  c += now;
  c += own_;
  c += contact_.counters();
  c.add_evaluator(*contact_.evaluator());
  c.last_order = now.last_order;
  c.last_step = now.last_step;
  return c;
}

void WheelsetSimulation::begin_segment(std::vector<double> y, bool first) {
  std::vector<double> yp;
  consistent_derivatives(initialisation(), y, yp);
  if (!first) {
    accumulated_ += integrator_.counters();
    ++own_.restarts;
  }
  const long n = static_cast<long>(y.size());
  integrator_.begin(t_, y, yp, segment_settings(spec_.integrator, contact_.formulation(), n));
  contact_.clear_cache();
}

std::vector<double> WheelsetSimulation::initial_state() {
  const InitialState& init = spec_.initial;
  const double r0 = equations_.nominal_radius();
  std::vector<double> y(static_cast<size_t>(kRigidUnknowns), 0.0);
  y[kUnknownZ] = r0;
  y[kUnknownSpinRate] = spec_.wheelset.speed / r0 + init.spin_rate_offset;
  y[kUnknownNormalLeft] = y[kUnknownNormalRight] = kStartScaledNormalForce;
  const ContactFormulation own = contact_.formulation();
  contact_.set_formulation(ContactFormulation::kRigid);  // both formulations start from rigid contact
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
    const ContactResult& c = contact_.at(y.data());
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
    contact_.set_formulation(own);
    if (own == ContactFormulation::kElastic) {
      y.resize(kElasticUnknowns);
      settle_elastic(initialisation(), y, 0.0, 0.0);
    }
  } catch (...) {
    contact_.set_formulation(own);
    throw;
  }
  return y;
}

void WheelsetSimulation::start() {
  place_on_track(0.0);
  std::vector<double> y = initial_state();
  contact_.clear_cache();
  t_ = 0.0;
  begin_segment(y, true);
  output_.restart();
  record_step_contact(true);
  emit_outputs_until(0.0);
}

StepContact WheelsetSimulation::step_contact_at(const std::vector<double>& y) {
  const ContactResult& c = contact_.at(y.data());
  return step_contact(equations_, contact_.formulation(), contact_.branches(), c, y, t_);
}

void WheelsetSimulation::record_step_contact(bool restart) {
  output_.record_step(step_contact_at(integrator_.state()), restart);
}

void WheelsetSimulation::emit_outputs_until(double t) {
  OutputSampler::NormalForce rigid_normal_force;
  if (contact_.formulation() == ContactFormulation::kRigid) {
    rigid_normal_force = [this](const double* y, int wheel) {
      return equations_.normal_force(contact_.formulation(), y, ContactResult{}, wheel, contact_.branches());
    };
  }
  output_.emit_until(
      t, [this](double t_out) { return integrator_.state_at(t_out); }, rigid_normal_force,
      [this](const std::vector<double>& y, double t_out, const std::array<WheelOutput, 2>& wheels) {
        if (on_output_) on_output_(snapshot_of(y, t_out, wheels));
      });
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
  s.model = contact_.evaluator()->model();
  s.wheels = wheels;
  return s;
}

WheelsetSnapshot WheelsetSimulation::snapshot() {
  const std::vector<double> y = integrator_.state();
  return snapshot_of(y, t_, step_contact_at(y).wheels);
}

void WheelsetSimulation::fail(const std::string& why) {
  state_ = RunState::kFailed;
  message_ = why;
}

void WheelsetSimulation::request_swap(std::shared_ptr<ContactEvaluator> next) { swap_queue_.request(std::move(next)); }

void WheelsetSimulation::schedule_swap(double t, std::shared_ptr<ContactEvaluator> next) {
  swap_queue_.schedule(t, std::move(next));
}

void WheelsetSimulation::perform_swap(std::shared_ptr<ContactEvaluator> next) {
  if (!next) return;
  const ContactFormulation from = contact_.formulation();
  const ContactFormulation to = formulation_of(*next);
  const std::shared_ptr<ContactEvaluator> previous = contact_.evaluator();
  const FollowedBranches previous_branches = contact_.branches();
  std::vector<double> y = integrator_.state();
  const double z_acceleration = integrator_.derivative_data()[kUnknownZDot];
  const double roll_acceleration = integrator_.derivative_data()[kUnknownRollDot];
  try {
    // Elastic to rigid: the elastic normal forces start the rigid ones' iteration.
    std::array<double, 2> normal_forces{0.0, 0.0};
    if (from == ContactFormulation::kElastic && to == ContactFormulation::kRigid) {
      const ContactResult& c = contact_.at(y.data());
      for (int i = 0; i < 2; ++i) normal_forces[static_cast<size_t>(i)] = equations_.normal_force(from, y.data(), c, i);
    }
    if (from == ContactFormulation::kRigid && previous_branches.any_two_point()) {
      // The new model starts in one-point contact: each wheel's load on its first point.
      for (int i = 0; i < 2; ++i) y[kUnknownNormalLeft + i] += y[kUnknownSecondNormalLeft + i];
      y.resize(kRigidUnknowns);
    }
    contact_.replace(next, to, FollowedBranches{});
    adapt_to_formulation(initialisation(), from, y, normal_forces, z_acceleration, roll_acceleration);
    begin_segment(y, false);
    record_step_contact(true);
    swaps_.push_back({t_, previous->model(), next->model()});
    own_.add_evaluator(*previous);
  } catch (const std::exception& e) {
    contact_.replace(previous, from, previous_branches);
    message_ = swap_failure_message(next->model(), t_, previous->model(), e.what());
  }
}

void WheelsetSimulation::handle_roots() {
  const std::vector<int> info = integrator_.root_info(kEventFunctionCount);
  ++own_.root_returns;
  std::vector<double> y = integrator_.state();
  const int lifted = wheel_lifting_off(info, contact_.branches());
  if (lifted >= 0) {
    std::ostringstream msg;
    msg << "the " << (lifted == 0 ? "left" : "right") << " wheel lifts off its rail at t = " << format_time(t_)
        << " s (its normal force falls to 0): the rigid formulation keeps both wheels on their rails; use an "
           "elastic model (multipoint)";
    fail(msg.str());
    return;
  }
  switch_at_events(switching(), info, y);
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
  std::vector<double> y = integrator_.state();
  keep_more_loaded_points(switching(), y);
  restart_on_right_branches(y);
}

void WheelsetSimulation::restart_on_right_branches(std::vector<double>& y) {
  settle_on_lowest_branches(switching(), y);
  begin_segment(y, false);
  record_step_contact(true);
}

void WheelsetSimulation::check_branches() {
  // Follow the branches with the accepted step (the event functions were evaluated there), and
  // check that every followed point is the lowest: a switch the root finding did not see (an event
  // function that starts a segment below 0, or crosses 0 and back within a step) is taken here.
  // Without two-point sliding only the roots switch (the paper's one-point contact): the excess is
  // recorded, not corrected.
  const ContactResult c = contact_.at(integrator_.state_data());
  const std::array<double, 2> excess = branch_excess(c);
  bool missed = false;
  for (int i = 0; i < 2; ++i) {
    own_.max_branch_excess = std::max(own_.max_branch_excess, excess[static_cast<size_t>(i)]);
    missed = missed || excess[static_cast<size_t>(i)] > kBranchTolerance;
  }
  if (missed && spec_.integrator.two_point_sliding) {
    ++own_.missed_switches;
    ++own_.root_returns;
    std::vector<double> y = integrator_.state();
    restart_on_right_branches(y);
  } else {
    contact_.follow(c);
  }
}

bool WheelsetSimulation::after_step(const IdaStep& step) {
  const bool rigid = contact_.formulation() == ContactFormulation::kRigid;
  if (step.convergence_failure && rigid && convergence_restarts_in_a_row_ < kMaxConvergenceRestartsInARow) {
    restart_after_convergence_failure();
    return state_ == RunState::kRunning;
  }
  if (step.flag < 0) {
    std::ostringstream msg;
    msg << "IDASolve failed with flag " << step.flag << " at t = " << format_time(t_);
    if (!last_contact_error_.empty()) msg << ": " << last_contact_error_;
    if (!last_solver_message_.empty()) msg << " (" << last_solver_message_ << ")";
    fail(msg.str());
    return false;
  }
  for (int i = 0; i < 2; ++i)
    if (contact_.branches().two_point(i)) own_.two_point_time += step.t - t_;
  const double step_size = step.t - t_;
  if (step_size > 0) convergence_restarts_in_a_row_ = 0;
  t_ = step.t;
  place_on_track(t_);
  // Elastic contact has no event functions: the accepted state is first asked here.
  if (!rigid) contact_.at(integrator_.state_data(), next_step_ahead(t_));
  record_step_contact(false);
  // Conformal patches (Hertz's floor on the lateral curvature) at the accepted step.
  long floored = 0;
  for (const ContactPatch& p : contact_.at(integrator_.state_data()).patches)
    floored += p.lateral_curvature_floored ? 1 : 0;
  own_.floored_patches += floored;
  if (floored > 0) own_.floored_time += step_size;
  emit_outputs_until(t_);
  if (step.root) {
    handle_roots();
    if (state_ != RunState::kRunning) return false;
  } else if (contact_.formulation() == ContactFormulation::kRigid) {
    check_branches();
  }
  if (step.stop_time && t_ >= spec_.integrator.t_end) {
    state_ = RunState::kFinished;
    return false;
  }
  // A scheduled swap acts at the first step boundary at or after its time, as a live one does
  // at the first boundary after it arrived (no stop time: the steps stay those of the live run).
  while (std::shared_ptr<ContactEvaluator> next = swap_queue_.take_due(t_)) perform_swap(std::move(next));
  if (counters().steps >= spec_.integrator.max_steps) {
    fail("more than " + std::to_string(spec_.integrator.max_steps) + " steps before t_end");
    return false;
  }
  return true;
}

bool WheelsetSimulation::advance() {
  if (state_ != RunState::kRunning) return false;
  if (!integrator_.started()) {
    fail("advance() before start()");
    return false;
  }
  if (stop_requested_) {
    state_ = RunState::kStopped;
    message_ = "stopped at t = " + format_time(t_) + " s";
    return false;
  }
  try {
    if (std::shared_ptr<ContactEvaluator> next = swap_queue_.take_requested()) perform_swap(std::move(next));
    last_contact_error_.clear();
    last_solver_message_.clear();
    return after_step(integrator_.step(spec_.integrator.t_end));
  } catch (const std::exception& e) {
    fail("at t = " + format_time(t_) + " s: " + e.what());
    return false;
  }
}

void WheelsetSimulation::run() {
  if (!integrator_.started()) start();
  while (advance()) {
  }
}

}  // namespace wrc
