// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/wheel_forces.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/contact/hertz.hpp"
#include "core/geometry/wheel_side.hpp"
#include "core/model_interface/patch_builder.hpp"

namespace wrc {
namespace {

WheelSide side_of(int wheel) {
  if (wheel != 0 && wheel != 1)
    throw std::invalid_argument("wheel = " + std::to_string(wheel) + " is neither 0 (left) nor 1 (right)");
  return static_cast<WheelSide>(wheel);
}

}  // namespace

WheelForces wheel_forces(const ContactResult& contact, int wheel, std::optional<double> normal_force) {
  const WheelSide side = side_of(wheel);
  WheelForces f;
  Eigen::Vector3d normal_sum = Eigen::Vector3d::Zero();
  for (const ContactPatch& patch : contact.patches) {
    if (patch.point.side != side) continue;
    const PatchForces forces = patch_forces(patch);
    normal_sum += forces.normal;
    f.normal_force += patch.normal_force;
    f.creep_force += forces.creep;
    f.creep_force_x += patch.forces.fx;
    f.creep_force_y += patch.forces.fy;
    f.wear_number += std::abs(patch.forces.fx * patch.creepages.longitudinal) +
                     std::abs(patch.forces.fy * patch.creepages.lateral);
    f.max_pressure = std::max(f.max_pressure, hertz_max_pressure(patch.normal_force, patch.a, patch.b));
  }
  if (f.normal_force > 0.0) {
    const double n = normal_force.value_or(f.normal_force);
    if (!std::isfinite(n) || n <= 0.0)
      throw std::invalid_argument("the " + std::string(wheel == 0 ? "left" : "right") + " wheel's normal force " +
                                  std::to_string(n) + " N is not positive while its patches carry " +
                                  std::to_string(f.normal_force) + " N");
    f.normal_direction = normal_sum / n;
  } else {
    const double angle = contact.wheels[static_cast<size_t>(wheel)].contact_angle;
    f.normal_direction = Eigen::Vector3d(0.0, -side_sign(side) * std::sin(angle), std::cos(angle));
  }
  return f;
}

WheelForces interpolate(const WheelForces& a, const WheelForces& b, double w) {
  auto mix = [w](double p, double q) { return p + w * (q - p); };
  WheelForces f;
  f.normal_direction = a.normal_direction + w * (b.normal_direction - a.normal_direction);
  f.normal_force = mix(a.normal_force, b.normal_force);
  f.creep_force = a.creep_force + w * (b.creep_force - a.creep_force);
  f.creep_force_x = mix(a.creep_force_x, b.creep_force_x);
  f.creep_force_y = mix(a.creep_force_y, b.creep_force_y);
  f.wear_number = mix(a.wear_number, b.wear_number);
  f.max_pressure = mix(a.max_pressure, b.max_pressure);
  return f;
}

void set_force_outputs(const WheelForces& forces, double normal_force, int wheel, WheelOutput& out) {
  const Eigen::Vector3d force = forces.force(normal_force);
  // Y towards the track centre: -y on the left wheel, +y on the right.
  out.lateral_force = -side_sign(side_of(wheel)) * force.y();
  out.vertical_force = force.z();
  out.creep_force_x = forces.creep_force_x;
  out.creep_force_y = forces.creep_force_y;
  out.wear_number = forces.wear_number;
  out.max_pressure = forces.max_pressure;
}

}  // namespace wrc
