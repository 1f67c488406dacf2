// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle_dynamics/vehicle_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/dynamics/ida_callback_status.hpp"
#include "core/dynamics/segment_settings.hpp"
#include "core/model_interface/contact_model.hpp"
#include "core/numerics/number_text.hpp"
#include "core/vehicle_dynamics/vehicle_equilibrium.hpp"
#include "core/vehicle_dynamics/vehicle_restart.hpp"

namespace wrc {
namespace {

// Corrector failures in a row after which a rigid run fails instead of restarting, as the lone
// wheelset's (wheelset_simulation.cpp).
constexpr int kMaxConvergenceRestartsInARow = 3;

const VehicleRunSpec& checked(const VehicleRunSpec& spec) {
  validate(spec.vehicle);
  spec.run.validate();
  const InitialState& i = spec.run.initial;
  if (spec.start) {
    const size_t wheelsets = spec.vehicle.wheelsets().size();
    if (spec.start->bodies.size() != spec.vehicle.bodies.size() || spec.start->spin_rate_offsets.size() != wheelsets)
      throw std::invalid_argument("start: " + std::to_string(spec.start->bodies.size()) + " bodies and " +
                                  std::to_string(spec.start->spin_rate_offsets.size()) + " spin rates for a vehicle of " +
                                  std::to_string(spec.vehicle.bodies.size()) + " bodies and " +
                                  std::to_string(wheelsets) + " wheelsets");
    if (!spec.run.track.straight() || !spec.run.irregularity.empty())
      throw std::invalid_argument("start: a run continued from another's state runs on straight track without irregularities");
    if (i.y != 0.0 || i.yaw != 0.0 || i.y_dot != 0.0 || i.yaw_dot != 0.0 || i.spin_rate_offset != 0.0)
      throw std::invalid_argument("initial state: a run continued from another's state takes no initial state");
  }
  if (i.y_dot != 0.0 || i.yaw_dot != 0.0 || i.spin_rate_offset != 0.0)
    throw std::invalid_argument(
        "initial state: a vehicle run starts at rest (y_dot0, yaw_dot0 and spin_rate_offset 0; y0 and yaw0 hold its "
        "first wheelset there)");
  return spec;
}

// The segment settings of the layout: every car body's and frame's displacements and rates
// differential with the position and velocity tolerances, each wheelset's unknowns and (rigid)
// event functions as the lone wheelset's, the Newton matrix rebuilt as a vehicle's is.
IdaSegment vehicle_segment(const IntegratorSettings& s, const VehicleEquations& e, const VehicleLayout& layout,
                           bool rigid) {
  IdaSegment segment = segment_settings_without_unknowns(s, rigid);
  segment.newton_matrix_cj_change = kVehicleNewtonMatrixCjChange;
  for (size_t b = 0; b < e.vehicle().bodies.size(); ++b) {
    if (e.wheelset_of_body(b) >= 0) {
      append_wheelset_unknowns(segment, s, layout.size[b]);
      if (rigid) segment.root_direction.insert(segment.root_direction.end(), kEventDirections.begin(), kEventDirections.end());
      continue;
    }
    for (size_t k = 0; k < kBodyCoordinates; ++k) append_unknown(segment, s.position_tolerance, true);
    for (size_t k = 0; k < kBodyCoordinates; ++k) append_unknown(segment, s.velocity_tolerance, true);
  }
  return segment;
}

}  // namespace

std::vector<double> static_wheel_loads(const VehicleDescription& vehicle, double gravity) {
  double load = 0.0;
  for (const VehicleBody& b : vehicle.bodies) load += b.mass * gravity - b.external_force[2];
  const size_t wheelsets = vehicle.wheelsets().size();
  return std::vector<double>(wheelsets, load / (2.0 * static_cast<double>(std::max<size_t>(wheelsets, 1))));
}

VehicleSimulation::VehicleSimulation(VehicleRunSpec spec, std::shared_ptr<ContactEvaluator> contact,
                                     double nominal_radius)
    : spec_(checked(spec)),
      wheel_loads_(static_wheel_loads(spec_.vehicle, spec_.run.wheelset.gravity)),
      equations_(spec_.vehicle, spec_.run.wheelset, spec_.run.track, spec_.run.irregularity, nominal_radius,
                 wheel_loads_),
      contact_(std::move(contact), equations_, !spec_.run.irregularity.empty()),
      dae_(equations_, contact_),
      integrator_(*this) {
  if (!(nominal_radius > 0.0)) throw std::invalid_argument("VehicleSimulation: nominal radius must be > 0");
  const IntegratorSettings& s = spec_.run.integrator;
  for (size_t w = 0; w < equations_.wheelset_count(); ++w)
    samplers_.emplace_back(s.output_period, s.t_end, spec_.run.wheelset.speed);
  acceleration_maxima_.resize(spec_.vehicle.bodies.size());
}

VehicleSimulation::~VehicleSimulation() = default;

void VehicleSimulation::start() {
  const IntegratorSettings& s = spec_.run.integrator;
  const ContactFormulation own = formulation_of(*contact_.evaluator());
  t_ = 0.0;
  std::vector<double> y, yp;
  if (spec_.start) {
    y = continued_state();
    yp = vehicle_consistent_derivatives(dae_, 0.0, y, [this](size_t w) { return initialisation(w); });
  } else {
    std::vector<HeldWheelset> held;
    if (spec_.run.initial.y != 0.0 || spec_.run.initial.yaw != 0.0)
      held.push_back({0, spec_.run.initial.y, spec_.run.initial.yaw});
    try {
      y = vehicle_rest_state(dae_, own, 0.0, s.position_tolerance, s.velocity_tolerance, held);
      yp.assign(y.size(), 0.0);
    } catch (const std::runtime_error& no_rest) {
      if (own != ContactFormulation::kRigid || (!equations_.has_irregularities() && held.empty())) throw;
      std::string how;
      y = placed_on_rails(held, how);
      yp = vehicle_consistent_derivatives(dae_, 0.0, y, [this](size_t w) { return initialisation(w); });
      start_note_ = std::string("started off its equilibrium: ") + no_rest.what() + "; " + how +
                    ", each wheelset placed onto its rails at t = 0";
    }
  }
  integrator_.begin(0.0, y, yp, vehicle_segment(s, equations_, dae_.layout(), own == ContactFormulation::kRigid));
  contact_.clear_cache();
  started_ = true;
  for (OutputSampler& sampler : samplers_) sampler.restart();
  acceleration_maxima_.assign(spec_.vehicle.bodies.size(), BodyAccelerationMaxima{});
  record_step_contact(true);
  emit_outputs_until(0.0);
}

std::vector<double> VehicleSimulation::continued_state() {
  const VehicleStart& start = *spec_.start;
  equations_.place(0.0);
  const VehicleLayout layout = dae_.layout();
  std::vector<std::vector<double>> blocks;
  for (size_t b = 0; b < start.bodies.size(); ++b) {
    const BodyState& body = start.bodies[b];
    const int w = equations_.wheelset_of_body(b);
    if (w < 0) {
      std::vector<double> block(body.displacement.begin(), body.displacement.end());
      block.insert(block.end(), body.rate.begin(), body.rate.end());
      blocks.push_back(std::move(block));
      continue;
    }
    // A wheelset's z is its height above the rails (body_states(): less its position's z).
    std::vector<double> block(static_cast<size_t>(layout.size[b]), 0.0);
    block[kUnknownY] = body.displacement[kBodyLateral];
    block[kUnknownZ] = body.displacement[kBodyVertical] + spec_.vehicle.bodies[b].position[2];
    block[kUnknownRoll] = body.displacement[kBodyRoll];
    block[kUnknownYaw] = body.displacement[kBodyYaw];
    block[kUnknownYDot] = body.rate[kBodyLateral];
    block[kUnknownZDot] = body.rate[kBodyVertical];
    block[kUnknownRollDot] = body.rate[kBodyRoll];
    block[kUnknownYawDot] = body.rate[kBodyYaw];
    const WheelsetEquations& e = equations_.wheelset(static_cast<size_t>(w));
    block[kUnknownSpinRate] = equations_.speed() / e.nominal_radius() + start.spin_rate_offsets[static_cast<size_t>(w)];
    if (contact_.wheelset(static_cast<size_t>(w)).formulation() == ContactFormulation::kRigid) {
      block[kUnknownNormalLeft] = block[kUnknownNormalRight] = 1.0;  // the static wheel load each
      settle_on_lowest_branches(switching(static_cast<size_t>(w)), block);
    }
    blocks.push_back(std::move(block));
  }
  return join_bodies(blocks);
}

std::vector<double> VehicleSimulation::placed_on_rails(const std::vector<HeldWheelset>& held, std::string& how) {
  const IntegratorSettings& s = spec_.run.integrator;
  equations_.set_irregularity_share(0.0);
  std::vector<double> y;
  bool moved = false;
  // Newton alone on the nominal rails (a continuation would raise the irregularities again, and
  // with a hold it has failed already in start()).
  try {
    try {
      y = vehicle_rest_state(dae_, ContactFormulation::kRigid, 0.0, s.position_tolerance, s.velocity_tolerance, held,
                             false);
    } catch (const std::runtime_error&) {
      if (held.empty()) throw;
      y = vehicle_rest_state(dae_, ContactFormulation::kRigid, 0.0, s.position_tolerance, s.velocity_tolerance, {},
                             false);
      moved = true;
    }
  } catch (...) {
    equations_.set_irregularity_share(1.0);
    throw;
  }
  equations_.set_irregularity_share(1.0);
  equations_.place(0.0);
  std::vector<std::vector<double>> blocks = split_by_body(dae_.layout(), y);
  if (moved) {
    for (const HeldWheelset& h : held) {
      std::vector<double>& block = blocks[equations_.wheelset_body(h.wheelset)];
      block[kUnknownY] = h.lateral;
      block[kUnknownYaw] = h.yaw;
    }
  }
  how = moved ? "the vehicle at rest centred on the nominal rails, its first wheelset then moved to its held y and yaw"
              : "the vehicle at rest on the nominal rails";
  for (size_t w = 0; w < equations_.wheelset_count(); ++w)
    settle_on_lowest_branches(switching(w), blocks[equations_.wheelset_body(w)]);
  return join_bodies(blocks);
}

VehicleStart VehicleSimulation::continuation() {
  const VehicleSnapshot s = snapshot();
  VehicleStart start;
  start.bodies = s.bodies;
  for (size_t w = 0; w < s.spin_rates.size(); ++w)
    start.spin_rate_offsets.push_back(s.spin_rates[w] - equations_.speed() / equations_.wheelset(w).nominal_radius());
  return start;
}

void VehicleSimulation::record_step_contact(bool restart) {
  const std::vector<double> y = integrator_.state();
  equations_.place(t_);
  const VehicleLayout layout = dae_.layout();
  const std::vector<WheelsetContactView> views = contact_.at(layout, y.data());
  for (size_t w = 0; w < samplers_.size(); ++w) {
    const auto first = y.begin() + layout.offset[equations_.wheelset_body(w)];
    const std::vector<double> own(first, first + layout.size[equations_.wheelset_body(w)]);
    samplers_[w].record_step(
        step_contact(equations_.wheelset(w), views[w].formulation, *views[w].branches, *views[w].result, own, t_),
        restart);
  }
}

int VehicleSimulation::residual(double t, const double* y, const double* yp, double* r) {
  return ida_callback_status(last_error_, [&] { dae_.residual(t, y, yp, r, integrator_.newton_matrix_expected()); });
}

int VehicleSimulation::jacobian(double t, double cj, const double* y, const double* yp, const double* r,
                                DenseMatrixView jac) {
  return ida_callback_status(last_error_, [&] { dae_.jacobian(t, cj, y, yp, r, jac); });
}

int VehicleSimulation::roots(double t, const double* y, double* g) {
  return ida_callback_status(last_error_, [&] {
    equations_.place(t);
    const VehicleLayout layout = dae_.layout();
    const std::vector<WheelsetContactView> views = contact_.at(layout, y);
    for (size_t w = 0; w < views.size(); ++w)
      event_functions(*views[w].result, y + layout.offset[equations_.wheelset_body(w)], *views[w].branches,
                      g + kEventFunctionCount * w);
  });
}

InitialisationContext VehicleSimulation::initialisation(size_t w) {
  WheelsetContact& c = contact_.wheelset(w);
  InitialisationContext context{equations_.wheelset(w), c.formulation(), c.branches(),
                                [&c](const double* y) -> const ContactResult& { return c.at(y); },
                                [&c](const std::vector<ContactQuery>& batch) { return c.evaluate(batch); },
                                {}};
  if (!spec_.run.irregularity.empty()) {
    context.contact_later = [this, w, &c](const double* y, double dt) {
      equations_.place(t_ + dt);
      try {
        ContactResult later = c.evaluate({equations_.wheelset(w).query(c.formulation(), y, c.branches())}).front();
        equations_.place(t_);
        return later;
      } catch (...) {
        equations_.place(t_);
        throw;
      }
    };
  }
  return context;
}

SwitchingContext VehicleSimulation::switching(size_t w) {
  return SwitchingContext{contact_.wheelset(w), [this, w] { return initialisation(w); },
                          spec_.run.integrator.two_point_sliding, t_, switch_log_, own_, static_cast<int>(w)};
}

void VehicleSimulation::restart(std::vector<std::vector<double>> blocks) {
  equations_.place(t_);
  const bool rigid = formulation() == ContactFormulation::kRigid;
  for (size_t w = 0; w < equations_.wheelset_count() && rigid; ++w)
    settle_on_lowest_branches(switching(w), blocks[equations_.wheelset_body(w)]);
  std::vector<double> y = join_bodies(blocks);
  const std::vector<double> yp =
      vehicle_consistent_derivatives(dae_, t_, y, [this](size_t w) { return initialisation(w); });
  accumulated_ += integrator_.counters();
  ++own_.restarts;
  integrator_.begin(t_, y, yp, vehicle_segment(spec_.run.integrator, equations_, dae_.layout(), rigid));
  contact_.clear_cache();
  record_step_contact(true);
}

void VehicleSimulation::perform_swap(std::shared_ptr<ContactEvaluator> next) {
  if (!next) return;
  const ContactFormulation from = formulation();
  const ContactFormulation to = formulation_of(*next);
  const std::shared_ptr<ContactEvaluator> previous = contact_.evaluator();
  const std::vector<FollowedBranches> previous_branches = contact_.branches();
  equations_.place(t_);
  const VehicleLayout layout = dae_.layout();
  const std::vector<double> y = integrator_.state();
  const double* yp = integrator_.derivative_data();
  std::vector<std::vector<double>> blocks = split_by_body(layout, y);
  // Before the swap, in the old formulation: each wheelset's normal forces (elastic to rigid) and
  // vertical and roll accelerations (rigid to elastic); a wheel in two-point contact carries its
  // load on its first point.
  const size_t wheelsets = equations_.wheelset_count();
  std::vector<std::array<double, 2>> normal_forces(wheelsets, {0.0, 0.0});
  std::vector<std::array<double, 2>> accelerations(wheelsets);
  const bool to_rigid = from == ContactFormulation::kElastic && to == ContactFormulation::kRigid;
  const std::vector<WheelsetContactView> views =
      to_rigid ? contact_.at(layout, y.data()) : std::vector<WheelsetContactView>{};
  for (size_t w = 0; w < wheelsets; ++w) {
    const size_t b = equations_.wheelset_body(w);
    const int offset = layout.offset[b];
    accelerations[w] = {yp[offset + kUnknownZDot], yp[offset + kUnknownRollDot]};
    std::vector<double>& block = blocks[b];
    if (to_rigid)
      for (int i = 0; i < 2; ++i)
        normal_forces[w][static_cast<size_t>(i)] =
            equations_.wheelset(w).normal_force(from, block.data(), *views[w].result, i);
    if (from == ContactFormulation::kRigid && previous_branches[w].any_two_point()) {
      for (int i = 0; i < 2; ++i) block[static_cast<size_t>(kUnknownNormalLeft + i)] += block[static_cast<size_t>(kUnknownSecondNormalLeft + i)];
      block.resize(kRigidUnknowns);
    }
  }
  try {
    contact_.replace(next, to);
    for (size_t w = 0; w < wheelsets; ++w)
      adapt_to_formulation(initialisation(w), from, blocks[equations_.wheelset_body(w)], normal_forces[w],
                           accelerations[w][0], accelerations[w][1]);
    restart(std::move(blocks));
    swaps_.push_back({t_, previous->model(), next->model()});
    own_.add_evaluator(*previous);
  } catch (const std::exception& e) {
    contact_.replace(previous, from, previous_branches);
    message_ = swap_failure_message(next->model(), t_, previous->model(), e.what());
  }
}

void VehicleSimulation::handle_roots() {
  const std::vector<int> info =
      integrator_.root_info(kEventFunctionCount * static_cast<int>(equations_.wheelset_count()));
  ++own_.root_returns;
  equations_.place(t_);
  std::vector<std::vector<double>> blocks = split_by_body(dae_.layout(), integrator_.state());
  for (size_t w = 0; w < equations_.wheelset_count(); ++w) {
    const std::vector<int> own(info.begin() + kEventFunctionCount * w, info.begin() + kEventFunctionCount * (w + 1));
    if (std::none_of(own.begin(), own.end(), [](int flag) { return flag != 0; })) continue;
    const int lifted = wheel_lifting_off(own, contact_.wheelset(w).branches());
    if (lifted >= 0) {
      fail("wheelset '" + spec_.vehicle.bodies[equations_.wheelset_body(w)].name + "': the " +
           (lifted == 0 ? "left" : "right") + " wheel lifts off its rail at t = " + exact_number_text(t_) +
           " s (its normal force falls to 0): the rigid formulation keeps both wheels on their rails; use an "
           "elastic model (multipoint)");
      return;
    }
    switch_at_events(switching(w), own, blocks[equations_.wheelset_body(w)]);
  }
  restart(std::move(blocks));
}

void VehicleSimulation::restart_after_convergence_failure() {
  // As the lone wheelset's run (wheelset_simulation.cpp): a wheel sliding in two-point contact
  // between two nearly equally low minima whose corrector fails at every step size goes on in
  // one-point contact on its more loaded point.
  ++convergence_restarts_in_a_row_;
  ++own_.convergence_restarts;
  equations_.place(t_);
  std::vector<std::vector<double>> blocks = split_by_body(dae_.layout(), integrator_.state());
  for (size_t w = 0; w < equations_.wheelset_count(); ++w)
    keep_more_loaded_points(switching(w), blocks[equations_.wheelset_body(w)]);
  restart(std::move(blocks));
}

void VehicleSimulation::check_branches() {
  // As the lone wheelset's run: follow the points of the accepted step, or take a switch the
  // root finding did not see (without two-point sliding it is recorded, not corrected).
  equations_.place(t_);
  const VehicleLayout layout = dae_.layout();
  const std::vector<WheelsetContactView> views = contact_.at(layout, integrator_.state_data());
  std::vector<ContactResult> results;
  for (const WheelsetContactView& v : views) results.push_back(*v.result);  // at() may move the cache
  bool missed = false;
  for (const ContactResult& c : results)
    for (double excess : branch_excess(c)) {
      own_.max_branch_excess = std::max(own_.max_branch_excess, excess);
      missed = missed || excess > kBranchTolerance;
    }
  if (missed && spec_.run.integrator.two_point_sliding) {
    ++own_.missed_switches;
    ++own_.root_returns;
    restart(split_by_body(layout, integrator_.state()));
    return;
  }
  for (size_t w = 0; w < results.size(); ++w) contact_.wheelset(w).follow(results[w]);
}

void VehicleSimulation::message(const char* function, const char* text) {
  last_solver_message_ = std::string(function ? function : "IDA") + ": " + (text ? text : "");
}

bool VehicleSimulation::advance() {
  if (state_ != RunState::kRunning) return false;
  if (!started_) start();
  if (stop_requested_) {
    state_ = RunState::kStopped;
    message_ = "stopped at t = " + exact_number_text(t_) + " s";
    return false;
  }
  const double t_end = spec_.run.integrator.t_end;
  try {
    if (std::shared_ptr<ContactEvaluator> next = swap_queue_.take_requested()) perform_swap(std::move(next));
  } catch (const std::exception& e) {
    fail("at t = " + exact_number_text(t_) + " s: the model swap: " + e.what());
    return false;
  }
  last_error_.clear();
  last_solver_message_.clear();
  const IdaStep step = integrator_.step(t_end);
  const bool rigid = formulation() == ContactFormulation::kRigid;
  try {
    if (step.convergence_failure && rigid && convergence_restarts_in_a_row_ < kMaxConvergenceRestartsInARow) {
      restart_after_convergence_failure();
      return state_ == RunState::kRunning;
    }
  } catch (const std::exception& e) {
    fail("at t = " + exact_number_text(t_) + " s: the restart after the corrector failed: " + e.what());
    return false;
  }
  if (step.flag < 0) {
    std::ostringstream msg;
    msg << "the integrator failed at t = " << integrator_.current_time() << " s (IDA flag " << step.flag << ")";
    if (!last_error_.empty()) msg << ": " << last_error_;
    if (!last_solver_message_.empty()) msg << " (" << last_solver_message_ << ")";
    fail(msg.str());
    return false;
  }
  for (size_t w = 0; w < equations_.wheelset_count(); ++w)
    for (int i = 0; i < 2; ++i)
      if (contact_.wheelset(w).branches().two_point(i)) own_.two_point_time += step.t - t_;
  if (step.t > t_) convergence_restarts_in_a_row_ = 0;
  t_ = step.t;
  try {
    record_step_contact(false);
  } catch (const std::exception& e) {
    fail("at t = " + exact_number_text(t_) + " s: the contact of the accepted step: " + e.what());
    return false;
  }
  emit_outputs_until(t_);
  try {
    if (step.root)
      handle_roots();
    else if (rigid)
      check_branches();
  } catch (const std::exception& e) {
    fail("at t = " + exact_number_text(t_) + " s: the contact-point switch: " + e.what());
    return false;
  }
  if (state_ != RunState::kRunning) return false;
  if (counters().steps >= spec_.run.integrator.max_steps) {
    fail("the run took max_steps = " + std::to_string(spec_.run.integrator.max_steps) + " steps before t_end");
    return false;
  }
  if (step.stop_time && t_ >= t_end) {
    state_ = RunState::kFinished;
    return false;
  }
  // A scheduled swap acts at the first step boundary at or after its time, as a live one does at
  // the first boundary after it arrived.
  try {
    while (std::shared_ptr<ContactEvaluator> next = swap_queue_.take_due(t_)) perform_swap(std::move(next));
  } catch (const std::exception& e) {
    fail("at t = " + exact_number_text(t_) + " s: the model swap: " + e.what());
    return false;
  }
  return true;
}

void VehicleSimulation::run() {
  if (!started_) start();
  while (advance()) {
  }
}

void VehicleSimulation::fail(const std::string& why) {
  state_ = RunState::kFailed;
  message_ = why;
}

std::vector<double> VehicleSimulation::state_vector() const { return integrator_.state(); }

VehicleSnapshot VehicleSimulation::snapshot_of(double t, const std::vector<double>& y) {
  VehicleSnapshot s;
  s.t = t;
  const VehicleLayout layout = dae_.layout();
  s.bodies = equations_.body_states(layout, y.data());
  // The bodies' accelerations where time t places the track (every evaluation places it anew).
  equations_.place(t);
  for (const Eigen::Vector2d& a : equations_.body_accelerations(layout, y.data())) s.accelerations.push_back({a[0], a[1]});
  for (size_t w = 0; w < equations_.wheelset_count(); ++w)
    s.spin_rates.push_back(y[static_cast<size_t>(layout.offset[equations_.wheelset_body(w)] + kUnknownSpinRate)]);
  return s;
}

VehicleSnapshot VehicleSimulation::snapshot() { return snapshot_of(t_, integrator_.state()); }

VehicleSnapshot VehicleSimulation::steady_state(double t) {
  const IntegratorSettings& s = spec_.run.integrator;
  const VehicleEquilibrium e = vehicle_equilibrium(dae_, t, integrator_.state(),
                                                   equilibrium_weights(dae_, s.position_tolerance, s.velocity_tolerance));
  return snapshot_of(t, e.state);
}

void VehicleSimulation::emit_outputs_until(double t) {
  // Every sampler emits the same output times; the state at each is interpolated once.
  std::map<double, std::vector<double>> states;
  std::map<double, std::vector<std::array<WheelOutput, 2>>> wheels;
  const auto state_at = [&](double t_out) -> const std::vector<double>& {
    auto found = states.find(t_out);
    if (found == states.end())
      found = states.emplace(t_out, t_out == t_ ? integrator_.state() : integrator_.state_at(t_out)).first;
    return found->second;
  };
  const VehicleLayout layout = dae_.layout();
  for (size_t w = 0; w < samplers_.size(); ++w) {
    const size_t body = equations_.wheelset_body(w);
    const WheelsetContact& c = contact_.wheelset(w);
    OutputSampler::NormalForce rigid_normal_force;
    if (c.formulation() == ContactFormulation::kRigid) {
      rigid_normal_force = [this, &c, w](const double* y, int wheel) {
        return equations_.wheelset(w).normal_force(c.formulation(), y, ContactResult{}, wheel, c.branches());
      };
    }
    samplers_[w].emit_until(
        t,
        [&](double t_out) {
          const std::vector<double>& y = state_at(t_out);
          return std::vector<double>(y.begin() + layout.offset[body], y.begin() + layout.offset[body] + layout.size[body]);
        },
        rigid_normal_force,
        [&](const std::vector<double>&, double t_out, const std::array<WheelOutput, 2>& out) {
          wheels[t_out].push_back(out);
        });
  }
  for (auto& [t_out, y] : states) {
    VehicleSnapshot s = snapshot_of(t_out, y);
    for (size_t b = 0; b < s.accelerations.size(); ++b) {
      if (equations_.wheelset_of_body(b) >= 0) continue;
      const double distance = spec_.run.wheelset.speed * t_out + spec_.vehicle.bodies[b].position[0];
      acceleration_maxima_[b].lateral.observe(std::abs(s.accelerations[b][0]), t_out, distance);
      acceleration_maxima_[b].vertical.observe(std::abs(s.accelerations[b][1]), t_out, distance);
    }
    if (!on_output_) continue;
    s.wheels = std::move(wheels[t_out]);
    on_output_(s);
  }
}

WheelsetSnapshot VehicleSimulation::wheelset_snapshot(const VehicleSnapshot& s, size_t w) const {
  const size_t b = equations_.wheelset_body(w);
  const BodyState& state = s.bodies[b];
  WheelsetSnapshot out;
  out.t = s.t;
  out.y = state.displacement[kBodyLateral];
  out.z = state.displacement[kBodyVertical] + equations_.vehicle().bodies[b].position[2];
  out.roll = state.displacement[kBodyRoll];
  out.yaw = state.displacement[kBodyYaw];
  out.y_dot = state.rate[kBodyLateral];
  out.z_dot = state.rate[kBodyVertical];
  out.roll_dot = state.rate[kBodyRoll];
  out.yaw_dot = state.rate[kBodyYaw];
  out.spin_rate = s.spin_rates[w];
  if (w < s.wheels.size()) out.wheels = s.wheels[w];
  out.model = model();
  return out;
}

WheelsetParameters VehicleSimulation::wheelset_parameters(size_t w) const {
  WheelsetParameters p = equations_.wheelset(w).parameters();
  p.vertical_force = 2.0 * wheel_loads_[w] - (p.include_gravity ? p.mass * p.gravity : 0.0);
  return p;
}

RunCounters VehicleSimulation::counters() const {
  const RunCounters now = integrator_.counters();
  RunCounters c = accumulated_;
  c += now;
  c += own_;
  c += dae_.counters();
  c += contact_.counters();
  for (size_t w = 0; w < contact_.size(); ++w) c += contact_.wheelset(w).counters();  // restarts' own queries
  c.add_evaluator(*contact_.evaluator());  // the bus's retries, timeouts and query times
  c.last_order = now.last_order;
  c.last_step = now.last_step;
  return c;
}

}  // namespace wrc
