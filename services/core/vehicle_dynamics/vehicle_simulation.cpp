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

const VehicleRunSpec& checked(const VehicleRunSpec& spec) {
  validate(spec.vehicle);
  spec.run.validate();
  const InitialState& i = spec.run.initial;
  if (i.y_dot != 0.0 || i.yaw_dot != 0.0 || i.spin_rate_offset != 0.0)
    throw std::invalid_argument(
        "initial state: a vehicle run starts at rest (y_dot0, yaw_dot0 and spin_rate_offset 0; y0 and yaw0 hold its "
        "first wheelset there)");
  return spec;
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
  std::vector<HeldWheelset> held;
  if (spec_.run.initial.y != 0.0 || spec_.run.initial.yaw != 0.0)
    held.push_back({0, spec_.run.initial.y, spec_.run.initial.yaw});
  const std::vector<double> y = vehicle_rest_state(dae_, own, 0.0, s.position_tolerance, s.velocity_tolerance, held);
  const std::vector<double> yp(y.size(), 0.0);
  integrator_.begin(0.0, y, yp, vehicle_segment(s, equations_, dae_.layout(), own == ContactFormulation::kRigid));
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
