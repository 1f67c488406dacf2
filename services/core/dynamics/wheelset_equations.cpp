#include "core/dynamics/wheelset_equations.hpp"

#include <cmath>

#include "core/models/wheel_constraint.hpp"

namespace wrc {

WheelsetEquations::WheelsetEquations(WheelsetParameters parameters, double z_reference, double nominal_radius)
    : parameters_(parameters),
      z_reference_(z_reference),
      nominal_radius_(nominal_radius),
      force_scale_(0.5 * parameters.total_vertical_load()) {
  parameters_.validate();
}

ContactQuery WheelsetEquations::query(ContactFormulation f, const double* y,
                                      const std::array<double, 2>& tracked_s) const {
  ContactQuery q;
  q.pose.y = y[kUnknownY];
  q.pose.z = y[kUnknownZ];
  q.pose.roll = y[kUnknownRoll];
  q.pose.yaw = y[kUnknownYaw];
  q.y_dot = y[kUnknownYDot];
  q.z_dot = y[kUnknownZDot];
  q.roll_dot = y[kUnknownRollDot];
  q.yaw_dot = y[kUnknownYawDot];
  q.spin_rate = y[kUnknownSpinRate];
  q.speed = parameters_.speed;
  q.formulation = f;
  if (f == ContactFormulation::kRigid) {
    // A negative trial value inside a Newton iteration loads the wheel with nothing.
    q.normal_load = {std::max(0.0, y[kUnknownNormalLeft] * force_scale_),
                     std::max(0.0, y[kUnknownNormalRight] * force_scale_)};
  }
  q.material = parameters_.material;
  q.fastsim_elements = parameters_.fastsim_elements;
  q.fastsim_strips = parameters_.fastsim_strips;
  q.tracked_s_wheel = tracked_s;
  return q;
}

Eigen::Vector4d WheelsetEquations::mass_diagonal() const {
  return Eigen::Vector4d(parameters_.mass, parameters_.mass, parameters_.roll_inertia, parameters_.yaw_inertia);
}

double WheelsetEquations::derivative_coefficient(ContactFormulation f, int k) const {
  if (k < kPoseUnknowns) return 1.0;
  if (k < kUnknownSpinRate) return mass_diagonal()[k - kPoseUnknowns];
  if (k == kUnknownSpinRate) return parameters_.spin_inertia;
  (void)f;
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
  Eigen::Vector4d q;
  q[0] = p.lateral_force + force.y() - 2.0 * (s.lateral_stiffness * pose.y + s.lateral_damping * y[kUnknownYDot]);
  q[1] = -p.total_vertical_load() + force.z() -
         2.0 * (s.vertical_stiffness * (pose.z - z_reference_) + s.vertical_damping * y[kUnknownZDot]);
  q[2] = moment.dot(axes.roll) -
         2.0 * b2 * (s.vertical_stiffness * pose.roll + s.vertical_damping * y[kUnknownRollDot]);
  q[3] = moment.dot(axes.yaw) -
         2.0 * b2 * (s.longitudinal_stiffness * pose.yaw + s.longitudinal_damping * y[kUnknownYawDot]);
  if (axle_moment) *axle_moment = moment.dot(axes.axle);
  return q;
}

double WheelsetEquations::normal_force(ContactFormulation f, const double* y, const ContactResult& contact,
                                       int wheel) const {
  if (f == ContactFormulation::kRigid) return y[kUnknownNormalLeft + wheel] * force_scale_;
  double n = 0.0;
  for (const ContactPatch& patch : contact.patches)
    if (static_cast<int>(patch.point.side) == wheel) n += patch.normal_force;
  return n;
}

void WheelsetEquations::residual(ContactFormulation f, const double* y, const double* yp, const ContactResult& contact,
                                 double* r) const {
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
    }
  }
  const Eigen::Vector4d m = mass_diagonal();
  const double omega = y[kUnknownSpinRate];
  const double gyro = p.spin_inertia * omega;
  r[kUnknownYDot] = m[0] * yp[kUnknownYDot] - applied[0];
  r[kUnknownZDot] = m[1] * yp[kUnknownZDot] - applied[1];
  r[kUnknownRollDot] = m[2] * yp[kUnknownRollDot] - gyro * y[kUnknownYawDot] - applied[2];
  r[kUnknownYawDot] = m[3] * yp[kUnknownYawDot] + gyro * y[kUnknownRollDot] - applied[3];
  r[kUnknownSpinRate] = p.spin_inertia * yp[kUnknownSpinRate] - axle_moment;
  if (!rigid) return;
  for (int i = 0; i < 2; ++i) {
    const WheelConstraint& c = contact.wheels[static_cast<size_t>(i)];
    r[kUnknownNormalLeft + i] = c.gap;
    double g_dot = 0.0;
    for (int k = 0; k < kPoseUnknowns; ++k) g_dot += c.gap_gradient[k] * y[kPoseUnknowns + k];
    r[kUnknownMuLeft + i] = g_dot;
  }
}

}  // namespace wrc
