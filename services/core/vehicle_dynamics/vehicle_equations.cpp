// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle_dynamics/vehicle_equations.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/dynamics/rail_placement.hpp"
#include "core/dynamics/single_wheelset_vehicle.hpp"
#include "core/numerics/number_text.hpp"
#include "core/vehicle/body_dynamics.hpp"

namespace wrc {
namespace {

// The wheelset equations' parameters of wheelset body b: its mass, inertias and external force
// as the lone wheelset's (apply_wheelset_body; the vertical force a weight that takes the curve's
// centrifugal share, as the lone wheelset's load does), no suspension of its own (the vehicle's
// elements are its suspension), the rest the run's.
WheelsetParameters wheelset_parameters(const VehicleBody& b, const WheelsetParameters& common) {
  WheelsetParameters p = common;
  apply_wheelset_body(b, p);
  p.include_gravity = true;
  p.suspension = PrimarySuspension::none();
  return p;
}

// [m] how far a wheelset's position z (its axle's height above the rails) may lie from the wheel
// profile's nominal radius: a worn wheel's radius differs by millimetres, a wrong file or profile
// by centimetres (the primary springs would carry the difference as a preload).
constexpr double kAxleHeightTolerance = 5e-3;

}  // namespace

VehicleEquations::VehicleEquations(VehicleDescription vehicle, const WheelsetParameters& common, TrackLayout layout,
                                   TrackIrregularity irregularity, double nominal_radius,
                                   const std::vector<double>& wheel_loads)
    : vehicle_(std::move(vehicle)),
      layout_(std::move(layout)),
      irregularity_(std::move(irregularity)),
      speed_(common.speed),
      gravity_(common.include_gravity ? common.gravity : 0.0) {
  validate(vehicle_);
  common.validate();
  const std::vector<const VehicleBody*> ws = vehicle_.wheelsets();
  if (wheel_loads.size() != ws.size())
    throw std::invalid_argument("VehicleEquations: " + std::to_string(wheel_loads.size()) + " wheel loads for " +
                                std::to_string(ws.size()) + " wheelsets");
  wheelsets_.reserve(ws.size());  // WheelsetContact keeps references to them
  wheelset_of_body_.assign(vehicle_.bodies.size(), -1);
  for (size_t b = 0; b < vehicle_.bodies.size(); ++b) {
    const VehicleBody& body = vehicle_.bodies[b];
    if (body.kind != BodyKind::kWheelset) continue;
    const size_t w = wheelsets_.size();
    if (std::abs(body.position[2] - nominal_radius) > kAxleHeightTolerance)
      throw std::invalid_argument("body '" + body.name + "': position: z = " + number_text(body.position[2]) +
                                  " m is the axle's height above the rails, the wheel's nominal radius is " +
                                  number_text(nominal_radius) + " m (the geometry's r0): they differ by more than " +
                                  number_text(kAxleHeightTolerance) + " m");
    WheelsetParameters p = wheelset_parameters(body, common);
    wheelsets_.emplace_back(p, body.position[2], nominal_radius, wheel_loads[w]);
    wheelset_bodies_.push_back(b);
    wheelset_of_body_[b] = static_cast<int>(w);
  }
}

VehicleLayout VehicleEquations::layout_of(const std::vector<int>& wheelset_unknowns) const {
  if (wheelset_unknowns.size() != wheelsets_.size())
    throw std::logic_error("VehicleEquations::layout_of: unknowns of " + std::to_string(wheelset_unknowns.size()) +
                           " wheelsets for " + std::to_string(wheelsets_.size()));
  VehicleLayout l;
  for (size_t b = 0; b < vehicle_.bodies.size(); ++b) {
    const int w = wheelset_of_body_[b];
    const int n = w < 0 ? kBodyUnknowns : wheelset_unknowns[static_cast<size_t>(w)];
    l.offset.push_back(l.unknowns);
    l.size.push_back(n);
    l.unknowns += n;
  }
  return l;
}

void VehicleEquations::place(double t) {
  s_ref_ = speed_ * t;
  for (size_t w = 0; w < wheelsets_.size(); ++w) {
    const double s = s_ref_ + vehicle_.bodies[wheelset_bodies_[w]].position[0];
    if (!layout_.straight()) wheelsets_[w].set_track(layout_.at(s));
    if (irregularity_.empty()) continue;
    IrregularityPoint p = irregularity_.at(s);
    if (irregularity_share_ != 1.0) {
      for (double* v : {&p.alignment, &p.vertical_level, &p.cross_level, &p.gauge}) *v *= irregularity_share_;
      for (double& slope : p.slope) slope *= irregularity_share_;
    }
    wheelsets_[w].set_rails(rail_offsets_at(p, layout_.cant_base(), speed_));
  }
}

void VehicleEquations::set_irregularity_share(double share) {
  if (!(share >= 0.0 && share <= 1.0))
    throw std::invalid_argument("irregularity share = " + std::to_string(share) + ", must be in [0, 1]");
  irregularity_share_ = share;
}

std::vector<BodyState> VehicleEquations::body_states(const VehicleLayout& layout, const double* y) const {
  std::vector<BodyState> states(vehicle_.bodies.size());
  for (size_t b = 0; b < vehicle_.bodies.size(); ++b) {
    const double* u = y + layout.offset[b];
    BodyState& s = states[b];
    if (wheelset_of_body_[b] < 0) {
      for (size_t k = 0; k < kBodyCoordinates; ++k) {
        s.displacement[k] = u[k];
        s.rate[k] = u[kBodyCoordinates + k];
      }
      continue;
    }
    s.displacement = {u[kUnknownY], u[kUnknownZ] - vehicle_.bodies[b].position[2], u[kUnknownRoll], u[kUnknownYaw], 0.0};
    s.rate = {u[kUnknownYDot], u[kUnknownZDot], u[kUnknownRollDot], u[kUnknownYawDot], 0.0};
  }
  return states;
}

void VehicleEquations::residual(const VehicleLayout& layout, const double* y, const double* yp,
                                const std::vector<WheelsetContactView>& contacts, double* r) {
  const std::vector<BodyState> states = body_states(layout, y);
  const std::vector<BodyLoads> loads = element_loads(vehicle_, layout_, s_ref_, speed_, states);
  for (size_t b = 0; b < vehicle_.bodies.size(); ++b) {
    const int off = layout.offset[b];
    const std::array<double, kBodyCoordinates>& q = loads[b].generalised;
    const int w = wheelset_of_body_[b];
    if (w >= 0) {
      const WheelsetContactView& c = contacts[static_cast<size_t>(w)];
      WheelsetEquations& e = wheelsets_[static_cast<size_t>(w)];
      e.set_element_forces(Eigen::Vector4d(q[kBodyLateral], q[kBodyVertical], q[kBodyRoll], q[kBodyYaw]));
      e.residual(c.formulation, y + off, yp + off, *c.result, *c.branches, r + off);
      continue;
    }
    const BodyDynamics d = body_dynamics(vehicle_.bodies[b], layout_, s_ref_, speed_, states[b], gravity_);
    constexpr int n = static_cast<int>(kBodyCoordinates);
    const Eigen::Map<const BodyVector> rate(y + off + n);
    const Eigen::Map<const BodyVector> acceleration(yp + off + n);
    const Eigen::Map<const BodyVector> applied(q.data());
    Eigen::Map<BodyVector> kinematic(r + off);
    Eigen::Map<BodyVector> dynamic(r + off + n);
    kinematic = Eigen::Map<const BodyVector>(yp + off) - rate;
    dynamic = d.mass_matrix * acceleration - (applied + d.gravity + d.external - d.inertial);
  }
}

std::vector<Eigen::Vector2d> VehicleEquations::body_accelerations(const VehicleLayout& layout, const double* y) const {
  const std::vector<BodyState> states = body_states(layout, y);
  const std::vector<BodyLoads> loads = element_loads(vehicle_, layout_, s_ref_, speed_, states);
  std::vector<Eigen::Vector2d> a(vehicle_.bodies.size(), Eigen::Vector2d::Zero());
  for (size_t b = 0; b < vehicle_.bodies.size(); ++b) {
    if (wheelset_of_body_[b] >= 0) continue;
    const VehicleBody& body = vehicle_.bodies[b];
    const std::array<double, kBodyCoordinates> q = wrc::body_accelerations(body, layout_, s_ref_, speed_, states[b],
                                                                            loads[b].generalised, gravity_);
    // h / m on y and z is the absolute acceleration less q'' there (body_dynamics.hpp).
    const BodyDynamics d = body_dynamics(body, layout_, s_ref_, speed_, states[b], gravity_);
    a[b] = {q[kBodyLateral] + d.inertial[kBodyLateral] / body.mass,
            q[kBodyVertical] + d.inertial[kBodyVertical] / body.mass};
  }
  return a;
}

void VehicleEquations::add_derivative_terms(const VehicleLayout& layout, const double* y, double c,
                                            DenseMatrixView jac) const {
  const std::vector<BodyState> states = body_states(layout, y);
  for (size_t b = 0; b < vehicle_.bodies.size(); ++b) {
    const int off = layout.offset[b];
    const int w = wheelset_of_body_[b];
    if (w >= 0) {
      const WheelsetEquations& e = wheelsets_[static_cast<size_t>(w)];
      for (int k = 0; k < layout.size[b]; ++k) jac(off + k, off + k) += c * e.derivative_coefficient(k);
      continue;
    }
    constexpr int n = static_cast<int>(kBodyCoordinates);
    for (int k = 0; k < n; ++k) jac(off + k, off + k) += c;
    const BodyDynamics d = body_dynamics(vehicle_.bodies[b], layout_, s_ref_, speed_, states[b], gravity_);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k) jac(off + n + i, off + n + k) += c * d.mass_matrix(i, k);
  }
}

}  // namespace wrc
