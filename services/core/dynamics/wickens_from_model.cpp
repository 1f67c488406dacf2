// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/wickens_from_model.hpp"

#include <stdexcept>

#include "core/contact/kalker_coefficients.hpp"
#include "core/geometry/rigid_wheelset.hpp"

namespace wrc {
namespace {

// [m, rad] the central-difference step of the geometry's derivatives: z changes by about
// z'' h^2 / 2 ~ 1e-8 m over it, 1e4 times the rigid solver's height tolerance (1e-12 m), and the
// profiles' curvature changes over millimetres, so the truncation error (h / 1 mm)^2 is 4e-4.
constexpr double kGeometryStep = 2e-5;

}  // namespace

WickensFromModel wickens_from_model(const WheelsetGeometry& geometry, const WheelsetParameters& p,
                                    const CentredSteadyState& steady) {
  const RigidWheelsetSolver solver(geometry);
  const double h = kGeometryStep;
  const RigidContact centre = solver.solve(0.0, 0.0);
  const RigidContact left = solver.solve(h, 0.0, centre);
  const RigidContact right = solver.solve(-h, 0.0, centre);
  const RigidContact ahead = solver.solve(0.0, h, centre);
  const RigidContact behind = solver.solve(0.0, -h, centre);

  WickensFromModel out;
  WickensWheelset& m = out.model;
  const PrimarySuspension& s = p.suspension;
  const double b2 = s.half_spacing * s.half_spacing;
  const double load = p.total_vertical_load();
  m.mass = p.mass;
  m.yaw_inertia = p.yaw_inertia;
  m.conicity = (left.delta_r() - right.delta_r()) / (4.0 * h);
  m.rolling_radius = 0.5 * (centre.left().rolling_radius + centre.right().rolling_radius);
  m.contact_half_distance = 0.5 * (centre.left().wheel_point.y() - centre.right().wheel_point.y());
  out.roll_slope = (left.pose.roll - right.pose.roll) / (2.0 * h);
  out.contact_angle = centre.left().contact_angle;
  const double z_yy = (left.pose.z - 2.0 * centre.pose.z + right.pose.z) / (h * h);
  const double z_psipsi = (ahead.pose.z - 2.0 * centre.pose.z + behind.pose.z) / (h * h);
  out.gravitational_stiffness = load * z_yy + 2.0 * s.vertical_stiffness * b2 * out.roll_slope * out.roll_slope;
  out.gravitational_yaw_stiffness = load * z_psipsi;
  m.lateral_stiffness = 2.0 * s.lateral_stiffness + out.gravitational_stiffness;
  m.yaw_stiffness = 2.0 * s.longitudinal_stiffness * b2 + out.gravitational_yaw_stiffness;
  m.lateral_damping = 2.0 * s.lateral_damping;
  m.yaw_damping = 2.0 * s.longitudinal_damping * b2;

  // The centred patch (both wheels alike by symmetry: the left one's).
  const ContactPatch* patch = nullptr;
  for (const ContactPatch& c : steady.contact.patches)
    if (c.point.side == WheelSide::kLeft && (!patch || c.normal_force > patch->normal_force)) patch = &c;
  if (!patch || !(patch->a > 0.0 && patch->b > 0.0))
    throw std::runtime_error("wickens_from_model: the centred state has no loaded patch on the left wheel");
  out.semi_axis_a = patch->a;
  out.semi_axis_b = patch->b;
  const KalkerCoefficients k = kalker_coefficients(patch->a / patch->b, p.material.poisson_ratio);
  out.c11 = k.c11;
  out.c22 = k.c22;
  out.c23 = k.c23;
  const double gab = p.material.shear_modulus * patch->a * patch->b;
  m.f11 = gab * k.c11;
  m.f22 = gab * k.c22;
  m.validate();
  return out;
}

}  // namespace wrc
