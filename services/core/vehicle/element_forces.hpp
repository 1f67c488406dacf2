// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The forces of a vehicle's elements (springs, dampers, torsional springs, bump stops, nonlinear
/// dampers; core/vehicle/vehicle_description.hpp) on its bodies, for given body displacements and
/// rates on a track layout (docs/vehicle.md, "The elements' forces"). A pure function of the
/// state: no integrator, no contact, no gravity or external forces.
///
/// Frames. The vehicle's reference point is at distance s_ref along the track (s_ref = V t); a
/// body whose centre of gravity is at position (X, Y, Z) (VehicleBody::position) rides at
/// s_b = s_ref + X in the track frame there (core/vehicle/track_frames.hpp). Its state is measured
/// in that frame: the centre of gravity at c = (0, Y + y, Z + z) and the orientation
/// R = Rz(yaw) Ry(pitch) Rx(roll) (exact), so a point p of the body (body frame, from the centre of
/// gravity) is at c + R p. A body does not move along the track relative to s_b.
///
/// Each element is evaluated in one frame, the track frame at its station: the mean of its two
/// attachment points' nominal distances (a body's point at s_b + p_x; a track point, given in the
/// track frame at the other body's distance s_o, at s_o + p_x). The deflection is d = r_B - r_A
/// (B the second of VehicleElement::bodies), its rate the time derivative with the frames moving
/// along the track at V, computed analytically (track frames' twist, track_frames.hpp). The
/// element's force F acts +F on A at its point and -F on B at its point; a torsional spring's
/// moment M acts +M on A and -M on B.
///
/// The springs are conservative (their generalised forces are minus the gradient of their energy
/// in d, with the station frame fixed for a given s_ref). The forces between bodies cancel; their
/// moments about one point cancel except for each pair's couple (P_A - P_B) x F = -d x F, zero when
/// F lies along d and of second order (k d^2) otherwise: the laws' axes are the track frame's, as
/// the vehicle file says, and the track takes that couple.

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/track/track_layout.hpp"
#include "core/vehicle/vehicle_description.hpp"

namespace wrc {

/// The index of each of a body's coordinates in BodyState and BodyLoads::generalised.
enum BodyCoordinate : std::size_t { kBodyLateral = 0, kBodyVertical, kBodyRoll, kBodyYaw, kBodyPitch };
/// The number of a body's coordinates.
inline constexpr std::size_t kBodyCoordinates = 5;

/// A body's displacement from its nominal position in its own track frame, and its rates.
struct BodyState {
  /// y [m] (> 0 to the left), z [m] (> 0 up) of the centre of gravity; roll, yaw, pitch [rad]
  std::array<double, kBodyCoordinates> displacement{};
  /// their time derivatives [m/s], [m/s], [rad/s] x 3
  std::array<double, kBodyCoordinates> rate{};
};

/// What the elements do to one body.
struct BodyLoads {
  /// Generalised forces on (y, z, roll, yaw, pitch): Q_y [N], Q_z [N], Q_roll, Q_yaw, Q_pitch
  /// [N m], with the moment's components along the axes of the rotations R = Rz Ry Rx: Q_yaw =
  /// m . e_z, Q_pitch = m . Rz e_y, Q_roll = m . Rz Ry e_x. The virtual work is Q . delta(q).
  std::array<double, kBodyCoordinates> generalised{};
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< [N] the sum of the forces, in the body's track frame
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< [N m] about the centre of gravity, in the body's track frame
};

/// One element's kinematics and action, in the track frame at its station.
struct ElementAction {
  double station = 0;                                        ///< [m] the distance of the element's frame
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();         ///< [m] attachment point on A
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();         ///< [m] attachment point on B
  Eigen::Vector3d deflection = Eigen::Vector3d::Zero();      ///< [m] d = point_b - point_a
  Eigen::Vector3d deflection_rate = Eigen::Vector3d::Zero(); ///< [m/s] d d / dt
  /// Torsional spring only (else 0): the rotation of B relative to A, the angles (roll, pitch,
  /// yaw) [rad] of R_A^T R_B = Rz(yaw) Ry(pitch) Rx(roll) with R_A, R_B the orientations in this
  /// frame (the track's heading and cant between the two distances included); to first order
  /// yaw_B - yaw_A + int kappa, roll_B - roll_A + cant difference.
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation_rate = Eigen::Vector3d::Zero();  ///< [rad/s] d rotation / dt
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< [N] F: +F on A at point_a, -F on B at point_b
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< [N m] a pure moment: +M on A, -M on B
};

/// Every element's action, in the order of vehicle.elements. Laws: spring_damper F = K d + C d'
/// per axis of the station frame; torsional_spring generalised moments k angle + c rate on the
/// relative roll and yaw (none on pitch), M = R_A J^-T (k_roll a_x + c_roll a_x', 0, k_yaw a_z +
/// c_yaw a_z') with J the angular-velocity Jacobian of the angles (so M is about (k_roll a_x, 0,
/// k_yaw a_z) for small angles and the spring is conservative); bump_stop F = e_dir
/// bump_stop_force(d_dir); nonlinear_damper F = e_dir nonlinear_damper_force(d'_dir).
/// @param s_ref the vehicle's reference point's distance along the track [m]
/// @param speed V = d s_ref / dt [m/s]
/// @param states one per body of vehicle.bodies, in that order
/// @throws std::invalid_argument if the states do not match the bodies or an element names no body.
std::vector<ElementAction> element_actions(const VehicleDescription& vehicle, const TrackLayout& layout, double s_ref,
                                           double speed, const std::vector<BodyState>& states);

/// The elements' loads on each body (in the order of vehicle.bodies): each element's actions
/// (element_actions()) moved into the body's track frame and summed; an element to the track acts
/// on its one body only. Same parameters and errors as element_actions().
std::vector<BodyLoads> element_loads(const VehicleDescription& vehicle, const TrackLayout& layout, double s_ref,
                                     double speed, const std::vector<BodyState>& states);

/// A bump stop's force along its direction [N] at the deflection d [m]: 0 for |d| <= clearance
/// [m], stiffness [N/m] times (|d| - clearance) with the sign of d beyond (the stop pushes B back
/// towards A: the force on B is minus this).
double bump_stop_force(double clearance, double stiffness, double deflection);

/// A nonlinear damper's force [N] at the relative velocity v [m/s] (VehicleElement::curve: points
/// (velocity [m/s], force [N]) from (0, 0), velocities increasing): linear between the points, the
/// last slope continued beyond the last, and odd, F(-v) = -F(v) (the force on B is minus this).
double nonlinear_damper_force(const std::vector<std::pair<double, double>>& curve, double velocity);

}  // namespace wrc
