// SPDX-License-Identifier: Apache-2.0
#include "core/model_interface/patch_builder.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/contact/creepage.hpp"
#include "core/geometry/wheel_side.hpp"

namespace wrc {
namespace {

ContactPatch finish_patch(const ContactPoint& point, const PatchShape& shape, const HertzContact& hertz,
                          double penetration, const PatchContext& context) {
  ContactPatch patch;
  patch.point = point;
  patch.a = hertz.a;
  patch.b = hertz.b;
  patch.penetration = penetration;
  patch.normal_force = hertz.normal_force;
  patch.lateral_curvature_floored = shape.floored;
  const WheelsetMotion& m = context.motion;
  patch.creepages = creepages(context.query.speed, m.velocity, m.angular_velocity, point.wheel_point - m.centre,
                              point.normal);
  CreepPatch creep;
  creep.a = hertz.a;
  creep.b = hertz.b;
  creep.normal_force = hertz.normal_force;
  creep.shear_modulus = context.query.material.shear_modulus;
  creep.poisson = context.query.material.poisson_ratio;
  creep.friction = context.query.material.friction;
  patch.forces = context.fastsim.solve(creep, patch.creepages);
  return patch;
}

}  // namespace

PatchShape contact_shape(const ContactPoint& point, double lateral_curvature_floor) {
  const double A = point.relative_curvature_rolling();
  double B = point.relative_curvature_lateral();
  const bool bad_a = !(A > 0.0) || !std::isfinite(A);
  const bool bad_b = !std::isfinite(B) || (!(B > lateral_curvature_floor * A) && lateral_curvature_floor <= 0.0);
  if (bad_a || bad_b) {
    std::ostringstream msg;
    msg << side_name(point.side) << " wheel, s = " << point.s << " m: relative curvatures A = " << A
        << " 1/m (rolling), B = " << B << " 1/m (lateral) ";
    if (bad_a) {
      msg << "- A must be positive and finite";
    } else {
      msg << "- B must be positive for a Hertz ellipse (conformal contact) and the lateral-curvature floor is "
             "disabled";
    }
    throw ContactConfigurationError(msg.str());
  }
  PatchShape result;
  if (!(B > lateral_curvature_floor * A)) {
    B = lateral_curvature_floor * A;
    result.floored = true;
  }
  try {
    result.shape = hertz_shape(A, B);
  } catch (const std::invalid_argument& e) {
    std::ostringstream msg;
    msg << side_name(point.side) << " wheel, s = " << point.s << " m: no Hertz ellipse for A = " << A
        << " 1/m, B = " << B << " 1/m: " << e.what();
    throw ContactConfigurationError(msg.str());
  }
  return result;
}

ContactPatch patch_from_force(const ContactPoint& point, const PatchShape& shape, double normal_force,
                              const PatchContext& context) {
  const HertzContact hertz = hertz_from_force(shape.shape, context.contact_modulus, normal_force);
  return finish_patch(point, shape, hertz, 0.0, context);
}

ContactPatch patch_from_penetration(const ContactPoint& point, const PatchShape& shape, double penetration,
                                    const PatchContext& context) {
  const HertzContact hertz = hertz_from_penetration(shape.shape, context.contact_modulus, penetration);
  return finish_patch(point, shape, hertz, penetration, context);
}

std::optional<ContactPatch> one_point_patch(const ContactPoint& point, const PatchContext& context,
                                            double lateral_curvature_floor) {
  // The shape only where a patch is built (the elliptic inversion is the expensive part).
  if (context.query.formulation == ContactFormulation::kRigid) {
    if (!(context.query.normal_load[static_cast<int>(point.side)] > 0.0)) return std::nullopt;
  } else if (!(normal_penetration(point) > 0.0)) {
    return std::nullopt;
  }
  return one_point_patch(point, contact_shape(point, lateral_curvature_floor), context);
}

std::optional<ContactPatch> one_point_patch(const ContactPoint& point, const PatchShape& shape,
                                            const PatchContext& context) {
  if (context.query.formulation == ContactFormulation::kRigid) {
    const double load = context.query.normal_load[static_cast<int>(point.side)];
    if (!(load > 0.0)) return std::nullopt;
    return patch_from_force(point, shape, load, context);
  }
  const double delta = normal_penetration(point);
  if (!(delta > 0.0)) return std::nullopt;
  return patch_from_penetration(point, shape, delta, context);
}

void add_shared_patches(const ContactPatch& blended, double height_slope, const std::array<SharedPoint, 2>& parts,
                        const PatchContext& context, ContactResult& result) {
  for (const SharedPoint& part : parts) {
    const double g_k = part.height_slope;
    const double force =
        part.share * blended.normal_force * std::sqrt((1.0 + g_k * g_k) / (1.0 + height_slope * height_slope));
    if (!(force > 0.0)) continue;
    ContactPatch p = patch_from_force(part.point, part.shape, force, context);
    if (context.query.formulation == ContactFormulation::kElastic) p.penetration = blended.penetration;
    result.patches.push_back(std::move(p));
  }
}

double normal_penetration(const ContactPoint& point) { return -point.distance * std::cos(point.contact_angle); }

PatchForces patch_forces(const ContactPatch& patch) {
  const ContactFrame frame = contact_frame(patch.point.normal);
  return {frame.n, patch.normal_force * frame.n, patch.forces.fx * frame.t1 + patch.forces.fy * frame.t2};
}

void add_to_resultant(const ContactPatch& patch, const Eigen::Vector3d& centre, ContactResult& result) {
  const PatchForces f = patch_forces(patch);
  const Eigen::Vector3d lever = patch.point.wheel_point - centre;
  const Eigen::Vector3d creep_moment = lever.cross(f.creep) + patch.forces.mz * f.n;
  result.creep_force += f.creep;
  result.creep_moment += creep_moment;
  result.force += f.normal + f.creep;
  result.moment += lever.cross(f.normal) + creep_moment;
}

}  // namespace wrc
