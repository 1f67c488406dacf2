// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The inertia side of a rigid body's equations of motion in its moving track frame (docs/
/// vehicle.md, "A body's equations of motion"): for one body on a track layout, the generalised
/// mass matrix M(q), the generalised inertial forces h(q, q', s_ref, V) and the generalised
/// gravity and external forces, so that
///
///   M(q) q'' = Q_elements + Q_gravity + Q_external - h
///
/// with Q_elements from element_loads() (core/vehicle/element_forces.hpp). A pure function of the
/// state: no integrator.
///
/// Frames as in element_forces.hpp: the body's centre of gravity at position (X, Y, Z) rides at
/// s_b = s_ref + X in the track frame there, at c = (0, Y + y, Z + z), oriented
/// R = Rz(yaw) Ry(pitch) Rx(roll); s_ref = V t with V constant. The track frame at s_b moves at
/// V e_x and turns at Omega = V w(s_b), w the frame's twist (track_frame_twist(): cant rate,
/// kappa sin(cant), kappa cos(cant)) [rad/m], so Omega changes at V^2 dw/ds. The kinetic energy
/// is that of the body's absolute motion, T = 1/2 m |v|^2 + 1/2 omega . I omega, with
/// v = V e_x + Omega x c + c' and omega = Omega + J (roll', pitch', yaw'), J the rotations' axes
/// (Rz Ry e_x, Rz e_y, e_z). Lagrange's equations give, in the track frame's axes:
///
///   y, z:               m q'' + m (a_0 . e_y, a_0 . e_z),
///                       a_0 = V Omega x e_x + Omega x (Omega x c) + 2 Omega x c' + V^2 dw/ds x c
///   roll, yaw, pitch:   J^T I_t J q'' + J^T (I_t alpha_0 + omega x I_t omega),
///                       alpha_0 = V^2 dw/ds + Omega x J theta' + J' theta'
///
/// with I_t = R I R^T the inertia tensor in the track frame's axes and J' theta' the rate of the
/// axes at constant rates: a_0 and alpha_0 are the body's absolute acceleration and angular
/// acceleration at q'' = 0. No longitudinal coordinate (V is held constant, F_x goes to the
/// track), no vertical curvature or gradient (the track frames have none).
///
/// A wheelset is a body like the others here: its spin (and the gyroscopic terms it brings) and
/// its contact come with the wheelset equations, not from this file.

#include <Eigen/Core>

#include <array>
#include <vector>

#include "core/track/track_layout.hpp"
#include "core/vehicle/element_forces.hpp"
#include "core/vehicle/vehicle_description.hpp"

namespace wrc {

/// g [m/s^2], the value of the wheelset equations (WheelsetParameters::gravity) and of
/// lateral_acceleration_of_cant_deficiency().
inline constexpr double kStandardGravity = 9.81;

/// A vector over a body's coordinates (y, z, roll, yaw, pitch), indexed by BodyCoordinate.
using BodyVector = Eigen::Matrix<double, static_cast<int>(kBodyCoordinates), 1>;
/// A matrix over a body's coordinates, indexed by BodyCoordinate.
using BodyMatrix = Eigen::Matrix<double, static_cast<int>(kBodyCoordinates), static_cast<int>(kBodyCoordinates)>;

/// The terms of one body's equations M q'' = Q_elements + gravity + external - inertial.
struct BodyDynamics {
  /// M(q): m [kg] on y and z, J^T I_t J [kg m^2] on (roll, yaw, pitch), no coupling between the
  /// two; symmetric, positive definite while cos(pitch) != 0
  BodyMatrix mass_matrix = BodyMatrix::Zero();
  /// h: every velocity-dependent term (the frame's motion along the track at V and its turning,
  /// centripetal, Coriolis, gyroscopic) [N] on y, z, [N m] on roll, yaw, pitch
  BodyVector inertial = BodyVector::Zero();
  /// Q_gravity: m g at the centre of gravity, in the body's (canted) track frame, -m g (sin(cant),
  /// cos(cant)) [N] on y, z; 0 on the angles
  BodyVector gravity = BodyVector::Zero();
  /// Q_external: VehicleBody::external_force (track frame at s_b, on the centre of gravity) [N] on
  /// y, z; its F_x has no coordinate and goes to the track; 0 on the angles
  BodyVector external = BodyVector::Zero();
};

/// One body's equation terms at its state.
/// @param s_ref the vehicle's reference point's distance along the track [m]
/// @param speed V = d s_ref / dt [m/s], constant
/// @param gravity g [m/s^2], >= 0
/// @throws std::invalid_argument naming the body and the value if the state, s_ref, speed or
///         gravity is not finite (or gravity negative), or if pitch is so near +-pi/2 that the
///         angles are singular.
BodyDynamics body_dynamics(const VehicleBody& body, const TrackLayout& layout, double s_ref, double speed,
                           const BodyState& state, double gravity = kStandardGravity);

/// q'' [m/s^2] on y, z, [rad/s^2] on roll, yaw, pitch: the solution of
/// M q'' = element_forces + Q_gravity + Q_external - h (body_dynamics()).
/// @param element_forces the elements' generalised forces on the body [N], [N m]
///        (BodyLoads::generalised), or any other applied generalised forces
/// @throws std::invalid_argument as body_dynamics(), and if element_forces is not finite.
std::array<double, kBodyCoordinates> body_accelerations(const VehicleBody& body, const TrackLayout& layout, double s_ref,
                                                        double speed, const BodyState& state,
                                                        const std::array<double, kBodyCoordinates>& element_forces,
                                                        double gravity = kStandardGravity);

/// Every body's q'' [m/s^2], [rad/s^2] (in the order of vehicle.bodies) from the elements' loads
/// on them (element_loads() at the same s_ref, speed and states).
/// @throws std::invalid_argument if the states or loads do not match the bodies, and as the
///         single body's.
std::vector<std::array<double, kBodyCoordinates>> body_accelerations(const VehicleDescription& vehicle,
                                                                     const TrackLayout& layout, double s_ref,
                                                                     double speed, const std::vector<BodyState>& states,
                                                                     const std::vector<BodyLoads>& loads,
                                                                     double gravity = kStandardGravity);

}  // namespace wrc
