// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/wheelset_equations.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/model_interface/query_validation.hpp"
#include "core/models/wheel_constraint.hpp"

namespace wrc {
namespace {

// A trial normal load [N] of a Newton iterate as the contact query takes it: within [0,
// kMaxNormalLoad].
double trial_normal_load(double load) { return std::clamp(load, 0.0, kMaxNormalLoad); }

}  // namespace

WheelsetEquations::WheelsetEquations(WheelsetParameters parameters, double z_reference, double nominal_radius)
    : parameters_(parameters),
      z_reference_(z_reference),
      nominal_radius_(nominal_radius),
      force_scale_(0.5 * parameters.total_vertical_load()) {
  parameters_.validate();
}

WheelsetEquations::WheelsetEquations(WheelsetParameters parameters, double z_reference, double nominal_radius,
                                     double force_scale)
    : WheelsetEquations(parameters, z_reference, nominal_radius) {
  if (!(force_scale > 0.0) || !std::isfinite(force_scale))
    throw std::invalid_argument("force_scale: " + std::to_string(force_scale) + " [N] is not positive and finite");
  force_scale_ = force_scale;
}

ContactQuery WheelsetEquations::query(ContactFormulation f, const double* y, const FollowedBranches& branches) const {
  ContactQuery q;
  q.pose.y = y[kUnknownY];
  q.pose.z = y[kUnknownZ];
  q.pose.roll = y[kUnknownRoll];
  q.pose.yaw = y[kUnknownYaw];
  // The contact sees the motion relative to the rails, which rest on the ground. The track frame
  // turns at V kappa: the wheelset's yaw rate relative to the ground is yaw' + V kappa, and its
  // forward speed over the rail under it V (1 - kappa y) (the inner rail is the shorter one). The
  // frame's roll with the cant ramp, p_t = V d(cant)/ds, is left out of the rates: in the frame's
  // coordinates the rail is prismatic (the ramp's twist is the frame's), and the wheel's slip over
  // its twisted rail, taken in the rail's true tangent plane at the true contact point, is that of
  // the wheel moving at its rates relative to the frame over a prismatic rail, but for a lateral
  // creepage -(d cant/ds) z_c / cos(gamma) of the contact height z_c (below 4e-5, left out; the
  // derivation and the numbers: docs/track.md). The gyroscopic moments take the absolute rates
  // (residual). On straight, level track every added term is an exact zero.
  const double v = parameters_.speed;
  q.y_dot = y[kUnknownYDot];
  q.z_dot = y[kUnknownZDot];
  q.roll_dot = y[kUnknownRollDot];
  q.yaw_dot = y[kUnknownYawDot] + v * track_.curvature;
  q.spin_rate = y[kUnknownSpinRate];
  q.speed = v * (1.0 - track_.curvature * y[kUnknownY]);
  q.formulation = f;
  if (f == ContactFormulation::kRigid) {
    // A negative trial value inside a Newton iteration loads the wheel with nothing, one beyond
    // the query's limit (a diverging iterate) with the limit.
    q.normal_load = {trial_normal_load(y[kUnknownNormalLeft] * force_scale_),
                     trial_normal_load(y[kUnknownNormalRight] * force_scale_)};
    for (int i = 0; i < 2; ++i) {
      if (!branches.two_point(i)) continue;
      q.second_tracked_s_wheel[static_cast<size_t>(i)] = branches.second_s[static_cast<size_t>(i)];
      q.second_normal_load[static_cast<size_t>(i)] = trial_normal_load(y[kUnknownSecondNormalLeft + i] * force_scale_);
    }
  }
  q.material = parameters_.material;
  q.fastsim_elements = parameters_.fastsim_elements;
  q.fastsim_strips = parameters_.fastsim_strips;
  q.tracked_s_wheel = branches.tracked_s;
  q.rail_offsets = rails_;
  return q;
}

Eigen::Vector4d WheelsetEquations::mass_diagonal() const {
  return Eigen::Vector4d(parameters_.mass, parameters_.mass, parameters_.roll_inertia, parameters_.yaw_inertia);
}

double WheelsetEquations::derivative_coefficient(int k) const {
  if (k < kPoseUnknowns) return 1.0;
  if (k < kUnknownSpinRate) return mass_diagonal()[k - kPoseUnknowns];
  if (k == kUnknownSpinRate) return parameters_.spin_inertia;
  return 0.0;  // normal forces and multipliers are algebraic
}

Eigen::Vector4d WheelsetEquations::applied_forces(ContactFormulation f, const double* y, const ContactResult& contact,
                                                 double* axle_moment) const {
  const WheelsetParameters& p = parameters_;
  const PrimarySuspension& s = p.suspension;
  WheelsetPose pose;
  pose.y = y[kUnknownY];
  pose.z = y[kUnknownZ];
  pose.roll = y[kUnknownRoll];
  pose.yaw = y[kUnknownYaw];
  const PoseAxes axes = PoseAxes::at(pose);
  const bool rigid = f == ContactFormulation::kRigid;
  const Eigen::Vector3d& force = rigid ? contact.creep_force : contact.force;
  const Eigen::Vector3d& moment = rigid ? contact.creep_moment : contact.moment;
  const double b2 = s.half_spacing * s.half_spacing;
  // The load (the carried vertical_force and the wheelset's weight) is a weight: in the track
  // frame, rolled by the cant angle phi and turning at V kappa, it acts along the apparent gravity,
  // (0, -(V^2 kappa cos phi / g + sin phi), -(cos phi - V^2 kappa sin phi / g)) times the load
  // (docs/track.md): the centrifugal part outwards, the cant's share of gravity inwards. Exactly
  // (0, -0, -1) times the load on straight, level track.
  const double phi = track_.cant_angle;
  const double centripetal = p.speed * p.speed * track_.curvature / p.gravity;  // V^2 kappa / g [-]
  const double load = p.total_vertical_load();
  Eigen::Vector4d q;
  q[0] = p.lateral_force - load * (centripetal * std::cos(phi) + std::sin(phi)) + force.y() -
         2.0 * (s.lateral_stiffness * pose.y + s.lateral_damping * y[kUnknownYDot]);
  q[1] = -load * (std::cos(phi) - centripetal * std::sin(phi)) + force.z() -
         2.0 * (s.vertical_stiffness * (pose.z - z_reference_) + s.vertical_damping * y[kUnknownZDot]);
  q[2] = moment.dot(axes.roll) -
         2.0 * b2 * (s.vertical_stiffness * pose.roll + s.vertical_damping * y[kUnknownRollDot]);
  q[3] = moment.dot(axes.yaw) -
         2.0 * b2 * (s.longitudinal_stiffness * pose.yaw + s.longitudinal_damping * y[kUnknownYawDot]);
  if (axle_moment) *axle_moment = moment.dot(axes.axle);
  if (has_element_forces_) q += element_forces_;
  return q;
}

double WheelsetEquations::normal_force(ContactFormulation f, const double* y, const ContactResult& contact, int wheel,
                                       const FollowedBranches& branches) const {
  if (f == ContactFormulation::kRigid) {
    double n = y[kUnknownNormalLeft + wheel];
    if (branches.two_point(wheel)) n += y[kUnknownSecondNormalLeft + wheel];
    return n * force_scale_;
  }
  double n = 0.0;
  for (const ContactPatch& patch : contact.patches)
    if (static_cast<int>(patch.point.side) == wheel) n += patch.normal_force;
  return n;
}

namespace {

// The second constraint of a wheel in two-point contact, or null for one-point contact.
const WheelConstraint* second_constraint(const ContactResult& contact, const FollowedBranches& branches, int wheel) {
  if (!branches.two_point(wheel)) return nullptr;
  const std::optional<WheelConstraint>& c = contact.second_wheels[static_cast<size_t>(wheel)];
  if (!c)
    throw std::runtime_error(std::string("the contact model answered no second point for the two-point contact of the ") +
                             (wheel == 0 ? "left" : "right") + " wheel");
  return &*c;
}

}  // namespace

void WheelsetEquations::residual(ContactFormulation f, const double* y, const double* yp, const ContactResult& contact,
                                 const FollowedBranches& branches, double* r) const {
  const WheelsetParameters& p = parameters_;
  double axle_moment = 0.0;
  Eigen::Vector4d applied = applied_forces(f, y, contact, &axle_moment);
  const bool rigid = f == ContactFormulation::kRigid;
  for (int k = 0; k < kPoseUnknowns; ++k) r[k] = yp[k] - y[kPoseUnknowns + k];
  if (rigid) {
    for (int i = 0; i < 2; ++i) {
      const WheelConstraint& c = contact.wheels[static_cast<size_t>(i)];
      const double n = y[kUnknownNormalLeft + i] * force_scale_;
      const double mu = y[kUnknownMuLeft + i];
      for (int k = 0; k < kPoseUnknowns; ++k) {
        r[k] += mu * c.gap_gradient[k];
        applied[k] += n * c.normal_z * c.gap_gradient[k];
      }
      if (const WheelConstraint* c2 = second_constraint(contact, branches, i)) {
        const double n2 = y[kUnknownSecondNormalLeft + i] * force_scale_;
        const double mu2 = y[kUnknownSecondMuLeft + i];
        for (int k = 0; k < kPoseUnknowns; ++k) {
          r[k] += mu2 * c2->gap_gradient[k];
          applied[k] += n2 * c2->normal_z * c2->gap_gradient[k];
        }
      }
    }
  }
  const Eigen::Vector4d m = mass_diagonal();
  const double omega = y[kUnknownSpinRate];
  const double gyro = p.spin_inertia * omega;
  r[kUnknownYDot] = m[0] * yp[kUnknownYDot] - applied[0];
  r[kUnknownZDot] = m[1] * yp[kUnknownZDot] - applied[1];
  // The gyroscopic moments take the absolute roll and yaw rates (the track frame's V d(cant)/ds
  // and V kappa added); the yaw acceleration the frame's V^2 d(kappa)/ds (a transition). The
  // frame's roll acceleration V^2 d^2(cant)/ds^2 is 0 on a linear ramp (an impulse at its ends,
  // where real ramps are rounded: left out, docs/track.md).
  const double v = p.speed;
  r[kUnknownRollDot] = m[2] * yp[kUnknownRollDot] - gyro * (y[kUnknownYawDot] + v * track_.curvature) - applied[2];
  r[kUnknownYawDot] = m[3] * (yp[kUnknownYawDot] + v * v * track_.curvature_rate) +
                      gyro * (y[kUnknownRollDot] + v * track_.cant_angle_rate) - applied[3];
  r[kUnknownSpinRate] = p.spin_inertia * yp[kUnknownSpinRate] - axle_moment;
  if (!rigid) return;
  for (int i = 0; i < 2; ++i) {
    const WheelConstraint& c = contact.wheels[static_cast<size_t>(i)];
    r[kUnknownNormalLeft + i] = c.gap;
    double g_dot = c.gap_rate;  // the rail moving under the wheelset (irregularities)
    for (int k = 0; k < kPoseUnknowns; ++k) g_dot += c.gap_gradient[k] * y[kPoseUnknowns + k];
    r[kUnknownMuLeft + i] = g_dot;
  }
  if (!branches.any_two_point()) return;
  for (int i = 0; i < 2; ++i) {
    if (const WheelConstraint* c2 = second_constraint(contact, branches, i)) {
      r[kUnknownSecondNormalLeft + i] = c2->gap;
      double g_dot = c2->gap_rate;
      for (int k = 0; k < kPoseUnknowns; ++k) g_dot += c2->gap_gradient[k] * y[kPoseUnknowns + k];
      r[kUnknownSecondMuLeft + i] = g_dot;
    } else {
      r[kUnknownSecondNormalLeft + i] = y[kUnknownSecondNormalLeft + i];
      r[kUnknownSecondMuLeft + i] = y[kUnknownSecondMuLeft + i];
    }
  }
}

}  // namespace wrc
