// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle/body_dynamics.hpp"
#include "core/vehicle/rotations.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/vehicle/track_frames.hpp"

namespace wrc {
namespace {

constexpr const char* kCoordinateNames[kBodyCoordinates] = {"y", "z", "roll", "yaw", "pitch"};

std::string number(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

[[noreturn]] void refuse(const VehicleBody& body, const std::string& key, const std::string& why) {
  throw std::invalid_argument("body '" + body.name + "': " + key + ": " + why);
}

void check_finite(const VehicleBody& body, const char* what, const std::array<double, kBodyCoordinates>& v) {
  for (std::size_t j = 0; j < kBodyCoordinates; ++j)
    if (!std::isfinite(v[j]))
      refuse(body, std::string(what) + "[" + kCoordinateNames[j] + "]", number(v[j]) + " is not a finite number");
}

void check_inputs(const VehicleBody& body, double s_ref, double speed, const BodyState& state, double gravity) {
  if (!std::isfinite(s_ref)) refuse(body, "s_ref", number(s_ref) + " [m] is not a finite number");
  if (!std::isfinite(speed)) refuse(body, "speed", number(speed) + " [m/s] is not a finite number");
  if (!std::isfinite(gravity) || gravity < 0)
    refuse(body, "gravity", number(gravity) + " [m/s^2] is not a finite number >= 0");
  check_finite(body, "displacement", state.displacement);
  check_finite(body, "rate", state.rate);
}

Eigen::Matrix3d inertia_tensor(const VehicleBody& b) {
  const auto& i = b.inertia;
  const auto& p = b.products_of_inertia;  // I_xy, I_xz, I_yz; the tensor's off-diagonal is -I_ij
  Eigen::Matrix3d tensor;
  tensor << i[0], -p[0], -p[1], -p[0], i[1], -p[2], -p[1], -p[2], i[2];
  return tensor;
}

}  // namespace

BodyDynamics body_dynamics(const VehicleBody& body, const TrackLayout& layout, double s_ref, double speed,
                           const BodyState& state, double gravity) {
  check_inputs(body, s_ref, speed, state, gravity);
  const auto& q = state.displacement;
  const auto& v = state.rate;
  const double m = body.mass;
  const double s_b = s_ref + body.position[0];

  // The frame's motion: Omega = V w, dOmega/dt = V^2 dw/ds with w = (cant rate, kappa sin(cant),
  // kappa cos(cant)); the curvature and cant are constant before 0 (as the frames are) and their
  // rates constant along a piece of the layout, so dw/ds has no second derivatives.
  const TrackPoint t = layout.at(s_b);
  const TrackFrameTwist twist = track_frame_twist(layout, s_b);
  const double kappa_rate = s_b < 0.0 ? 0.0 : t.curvature_rate;
  const double cant_rate = twist.angular.x();
  const double sc = std::sin(t.cant_angle), cc = std::cos(t.cant_angle);
  const Eigen::Vector3d w_rate(0.0, kappa_rate * sc + t.curvature * cant_rate * cc,
                               kappa_rate * cc - t.curvature * cant_rate * sc);  // [rad/m^2]
  const Eigen::Vector3d omega_frame = speed * twist.angular;      // [rad/s]
  const Eigen::Vector3d omega_frame_rate = speed * speed * w_rate;  // [rad/s^2]

  BodyDynamics d;

  // Translation: a_0 = V Omega x e_x + Omega x (Omega x c) + 2 Omega x c' + dOmega/dt x c (the
  // last lies along x, as dOmega/dt and c both lie in the y-z plane: the track takes it).
  const Eigen::Vector3d c(0.0, body.position[1] + q[kBodyLateral], body.position[2] + q[kBodyVertical]);
  const Eigen::Vector3d c_rate(0.0, v[kBodyLateral], v[kBodyVertical]);
  const Eigen::Vector3d a0 = speed * omega_frame.cross(twist.linear) + omega_frame.cross(omega_frame.cross(c)) +
                             2.0 * omega_frame.cross(c_rate) + omega_frame_rate.cross(c);
  d.mass_matrix(kBodyLateral, kBodyLateral) = m;
  d.mass_matrix(kBodyVertical, kBodyVertical) = m;
  d.inertial[kBodyLateral] = m * a0.y();
  d.inertial[kBodyVertical] = m * a0.z();

  // Rotation: the axes of roll, yaw and pitch (in that order, as the coordinates), the relative
  // angular velocity J theta' and the axes' rate at constant rates J' theta'.
  const Eigen::Matrix3d rz = rotation_z(q[kBodyYaw]);
  const Eigen::Matrix3d ry = rotation_y(q[kBodyPitch]);
  const Eigen::Matrix3d r = rz * ry * rotation_x(q[kBodyRoll]);
  Eigen::Matrix3d j;
  j.col(0) = rz * ry * Eigen::Vector3d::UnitX();
  j.col(1) = Eigen::Vector3d::UnitZ();
  j.col(2) = rz * Eigen::Vector3d::UnitY();
  const double roll_rate = v[kBodyRoll], yaw_rate = v[kBodyYaw], pitch_rate = v[kBodyPitch];
  const Eigen::Vector3d relative = j * Eigen::Vector3d(roll_rate, yaw_rate, pitch_rate);
  const Eigen::Vector3d axes_rate =
      roll_rate * (yaw_rate * Eigen::Vector3d::UnitZ().cross(j.col(0)) + pitch_rate * j.col(2).cross(j.col(0))) +
      pitch_rate * yaw_rate * Eigen::Vector3d::UnitZ().cross(j.col(2));
  const Eigen::Matrix3d inertia = r * inertia_tensor(body) * r.transpose();  // I_t
  const Eigen::Vector3d omega = omega_frame + relative;
  const Eigen::Vector3d alpha0 = omega_frame_rate + omega_frame.cross(relative) + axes_rate;
  const Eigen::Matrix3d rotational_mass = j.transpose() * inertia * j;
  const Eigen::Vector3d rotational_force = j.transpose() * (inertia * alpha0 + omega.cross(inertia * omega));
  d.mass_matrix.block<3, 3>(kBodyRoll, kBodyRoll) = rotational_mass;
  d.inertial.segment<3>(kBodyRoll) = rotational_force;

  // Gravity in the canted frame at s_b: -g (0, sin(cant), cos(cant)).
  d.gravity[kBodyLateral] = -m * gravity * sc;
  d.gravity[kBodyVertical] = -m * gravity * cc;
  d.external[kBodyLateral] = body.external_force[1];
  d.external[kBodyVertical] = body.external_force[2];
  return d;
}

std::array<double, kBodyCoordinates> body_accelerations(const VehicleBody& body, const TrackLayout& layout, double s_ref,
                                                        double speed, const BodyState& state,
                                                        const std::array<double, kBodyCoordinates>& element_forces,
                                                        double gravity) {
  check_finite(body, "element_forces", element_forces);
  const BodyDynamics d = body_dynamics(body, layout, s_ref, speed, state, gravity);
  const BodyVector applied = Eigen::Map<const BodyVector>(element_forces.data());
  const BodyVector rhs = applied + d.gravity + d.external - d.inertial;
  std::array<double, kBodyCoordinates> result{};
  result[kBodyLateral] = rhs[kBodyLateral] / d.mass_matrix(kBodyLateral, kBodyLateral);
  result[kBodyVertical] = rhs[kBodyVertical] / d.mass_matrix(kBodyVertical, kBodyVertical);
  const Eigen::LLT<Eigen::Matrix3d> llt(d.mass_matrix.block<3, 3>(kBodyRoll, kBodyRoll));
  // J^T I_t J is positive definite unless J is singular, det J = cos(pitch) (pitch = +-pi/2).
  if (llt.info() != Eigen::Success || std::abs(std::cos(state.displacement[kBodyPitch])) < 1e-9)
    refuse(body, "displacement[pitch]",
           number(state.displacement[kBodyPitch]) + " [rad] makes the angles singular (cos(pitch) = 0)");
  const Eigen::Vector3d angular = llt.solve(rhs.segment<3>(kBodyRoll));
  for (std::size_t k = 0; k < 3; ++k) result[kBodyRoll + k] = angular[static_cast<Eigen::Index>(k)];
  return result;
}

std::vector<std::array<double, kBodyCoordinates>> body_accelerations(const VehicleDescription& vehicle,
                                                                     const TrackLayout& layout, double s_ref,
                                                                     double speed, const std::vector<BodyState>& states,
                                                                     const std::vector<BodyLoads>& loads,
                                                                     double gravity) {
  if (states.size() != vehicle.bodies.size())
    throw std::invalid_argument("body dynamics: " + std::to_string(states.size()) + " body states for " +
                                std::to_string(vehicle.bodies.size()) + " bodies");
  if (loads.size() != vehicle.bodies.size())
    throw std::invalid_argument("body dynamics: " + std::to_string(loads.size()) + " body loads for " +
                                std::to_string(vehicle.bodies.size()) + " bodies");
  std::vector<std::array<double, kBodyCoordinates>> result;
  result.reserve(vehicle.bodies.size());
  for (std::size_t i = 0; i < vehicle.bodies.size(); ++i)
    result.push_back(
        body_accelerations(vehicle.bodies[i], layout, s_ref, speed, states[i], loads[i].generalised, gravity));
  return result;
}

}  // namespace wrc
