// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle_dynamics/vehicle_simulation.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/dynamics/segment_settings.hpp"
#include "core/model_interface/contact_model.hpp"
#include "core/vehicle_dynamics/vehicle_equilibrium.hpp"

namespace wrc {
namespace {

// [m] the elastic contact's equilibrium starts this far below the rigid contact's: a Hertz
// spring's stiffness vanishes at zero approach, Newton's matrix with it; 0.1 mm is about the
// static approach of a 70 kN wheel (the lone wheelset's start takes the same).
constexpr double kElasticStartDepth = 1e-4;

const VehicleRunSpec& checked(const VehicleRunSpec& spec) {
  validate(spec.vehicle);
  spec.run.validate();
  const InitialState& i = spec.run.initial;
  if (i.y != 0.0 || i.yaw != 0.0 || i.y_dot != 0.0 || i.yaw_dot != 0.0 || i.spin_rate_offset != 0.0)
    throw std::invalid_argument("initial state: a vehicle run starts from its equilibrium (every initial value 0)");
  return spec;
}

// The run's equilibrium guess: every body at its nominal position, each wheelset on the nominal
// radius with its static wheel load, rolling at V / r0.
std::vector<double> rest_guess(const VehicleEquations& e, const VehicleLayout& layout, double nominal_radius) {
  std::vector<double> y(static_cast<size_t>(layout.unknowns), 0.0);
  for (size_t w = 0; w < e.wheelset_count(); ++w) {
    double* u = y.data() + layout.offset[e.wheelset_body(w)];
    u[kUnknownZ] = nominal_radius;
    u[kUnknownSpinRate] = e.speed() / nominal_radius;
    if (layout.size[e.wheelset_body(w)] > kUnknownNormalRight) u[kUnknownNormalLeft] = u[kUnknownNormalRight] = 1.0;
  }
  return y;
}

// The segment settings of the layout: every car body's and frame's displacements and rates
// differential with the position and velocity tolerances, each wheelset's unknowns as the lone
// wheelset's.
IdaSegment vehicle_segment(const IntegratorSettings& s, const VehicleEquations& e, const VehicleLayout& layout,
                           bool rigid) {
  IdaSegment segment = segment_settings_without_unknowns(s, rigid);
  for (size_t b = 0; b < e.vehicle().bodies.size(); ++b) {
    if (e.wheelset_of_body(b) >= 0) {
      append_wheelset_unknowns(segment, s, layout.size[b]);
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
}

VehicleSimulation::~VehicleSimulation() = default;

void VehicleSimulation::start() {
  const IntegratorSettings& s = spec_.run.integrator;
  const ContactFormulation own = formulation_of(*contact_.evaluator());
  const double r0 = equations_.wheelset(0).nominal_radius();
  // Rigid contact first (a Hertz spring at zero approach has no stiffness to start Newton from).
  for (size_t w = 0; w < contact_.size(); ++w) contact_.wheelset(w).set_formulation(ContactFormulation::kRigid);
  VehicleLayout layout = dae_.layout();
  std::vector<double> y = vehicle_equilibrium(dae_, 0.0, rest_guess(equations_, layout, r0),
                                              equilibrium_weights(dae_, s.position_tolerance, s.velocity_tolerance))
                              .state;
  if (own == ContactFormulation::kElastic) {
    std::vector<double> elastic;
    for (size_t b = 0; b < equations_.vehicle().bodies.size(); ++b) {
      const auto first = y.begin() + layout.offset[b];
      const int keep = equations_.wheelset_of_body(b) >= 0 ? kElasticUnknowns : layout.size[b];
      elastic.insert(elastic.end(), first, first + keep);
      if (equations_.wheelset_of_body(b) >= 0) elastic[elastic.size() - kElasticUnknowns + kUnknownZ] -= kElasticStartDepth;
    }
    for (size_t w = 0; w < contact_.size(); ++w) contact_.wheelset(w).set_formulation(ContactFormulation::kElastic);
    y = vehicle_equilibrium(dae_, 0.0, std::move(elastic),
                            equilibrium_weights(dae_, s.position_tolerance, s.velocity_tolerance))
            .state;
    layout = dae_.layout();
  }
  const std::vector<double> yp(y.size(), 0.0);
  integrator_.begin(0.0, y, yp, vehicle_segment(s, equations_, layout, own == ContactFormulation::kRigid));
  contact_.clear_cache();
  started_ = true;
  t_ = 0.0;
  emit_outputs_until(0.0);
}

int VehicleSimulation::residual(double t, const double* y, const double* yp, double* r) {
  try {
    dae_.residual(t, y, yp, r, integrator_.newton_matrix_expected());
    return 0;
  } catch (const ContactConfigurationError& e) {
    last_error_ = e.what();
    return 1;  // recoverable: IDA retries with a smaller step
  } catch (const std::exception& e) {
    last_error_ = e.what();
    return -1;
  }
}

int VehicleSimulation::jacobian(double t, double cj, const double* y, const double* yp, const double* r,
                                DenseMatrixView jac) {
  try {
    dae_.jacobian(t, cj, y, yp, r, jac);
    return 0;
  } catch (const ContactConfigurationError& e) {
    last_error_ = e.what();
    return 1;
  } catch (const std::exception& e) {
    last_error_ = e.what();
    return -1;
  }
}

int VehicleSimulation::roots(double, const double*, double*) { return 0; }

void VehicleSimulation::message(const char* function, const char* text) {
  last_error_ = std::string(function ? function : "IDA") + ": " + (text ? text : "");
}

bool VehicleSimulation::advance() {
  if (state_ != RunState::kRunning) return false;
  if (!started_) start();
  const double t_end = spec_.run.integrator.t_end;
  const IdaStep step = integrator_.step(t_end);
  if (step.flag < 0) {
    std::ostringstream msg;
    msg << "the integrator failed at t = " << integrator_.current_time() << " s (IDA flag " << step.flag << ")";
    if (!last_error_.empty()) msg << ": " << last_error_;
    fail(msg.str());
    return false;
  }
  t_ = step.t;
  emit_outputs_until(t_);
  const RunCounters c = integrator_.counters();
  if (c.steps >= spec_.run.integrator.max_steps) {
    fail("the run took max_steps = " + std::to_string(spec_.run.integrator.max_steps) + " steps before t_end");
    return false;
  }
  if (t_ >= t_end) {
    state_ = RunState::kFinished;
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

VehicleSnapshot VehicleSimulation::snapshot_of(double t, const std::vector<double>& y) const {
  VehicleSnapshot s;
  s.t = t;
  const VehicleLayout layout = dae_.layout();
  s.bodies = equations_.body_states(layout, y.data());
  for (size_t w = 0; w < equations_.wheelset_count(); ++w)
    s.spin_rates.push_back(y[static_cast<size_t>(layout.offset[equations_.wheelset_body(w)] + kUnknownSpinRate)]);
  return s;
}

VehicleSnapshot VehicleSimulation::snapshot() const { return snapshot_of(t_, integrator_.state()); }

VehicleSnapshot VehicleSimulation::steady_state(double t) {
  const IntegratorSettings& s = spec_.run.integrator;
  const VehicleEquilibrium e = vehicle_equilibrium(dae_, t, integrator_.state(),
                                                   equilibrium_weights(dae_, s.position_tolerance, s.velocity_tolerance));
  return snapshot_of(t, e.state);
}

void VehicleSimulation::emit_outputs_until(double t) {
  const IntegratorSettings& s = spec_.run.integrator;
  for (;;) {
    const double t_out = std::min(static_cast<double>(next_output_) * s.output_period, s.t_end);
    if (t_out > t || next_output_ < 0) return;
    if (on_output_) on_output_(snapshot_of(t_out, t_out == t ? integrator_.state() : integrator_.state_at(t_out)));
    next_output_ = t_out >= s.t_end ? -1 : next_output_ + 1;
  }
}

RunCounters VehicleSimulation::counters() const {
  RunCounters c = integrator_.counters();
  c += dae_.counters();
  c += contact_.counters();
  return c;
}

}  // namespace wrc
