// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The classical linear model of a suspended wheelset on straight track (Wickens 1965; derived in
/// docs/stability.md): lateral shift y and yaw psi, linear creep (Kalker's f11, f22 per wheel, no
/// spin creep f23), equivalent conicity lambda, lateral and yaw springs and dampers (the
/// gravitational stiffnesses may be added to the springs):
///
///   m y''   + (2 f22 / V + c_y) y'          - 2 f22 psi        + k_y y   = 0
///   I psi'' + (2 f11 b0^2 / V + c_psi) psi' + 2 f11 b0 lambda / r0 y + k_psi psi = 0
///
/// Without dampers its critical speed and frequency have a closed form:
///   omega_c^2 = (2 f22 k_psi + 2 f11 b0^2 k_y) / (2 f22 I + 2 f11 b0^2 m)
///   V_c^2     = omega_c^2 / (lambda / (r0 b0) - ((k_y - m omega_c^2) / (2 f22))^2).

#include <optional>

#include <Eigen/Core>

namespace wrc {

/// The speed where the wheelset's least damped mode has zero damping, and that mode's frequency.
struct WickensCriticalPoint {
  double speed = 0;            ///< V_c [m/s]
  double angular_frequency = 0;  ///< omega_c [rad/s]
  double frequency() const;    ///< omega_c / (2 pi) [Hz]
};

/// The parameters of the classical model (every value total over both wheels or axle boxes, unless
/// it says "per wheel").
struct WickensWheelset {
  double mass = 0;                 ///< m [kg], > 0
  double yaw_inertia = 0;          ///< I about the vertical axis [kg m^2], > 0
  double conicity = 0;             ///< lambda: d(r_left - r_right)/dy / 2 at the centre [-], > 0
  double rolling_radius = 0;       ///< r0 at the centred contact [m], > 0
  double contact_half_distance = 0;  ///< b0: half the lateral distance of the contact points [m], > 0
  double f11 = 0;                  ///< longitudinal creep coefficient per wheel, G a b C11 [N], > 0
  double f22 = 0;                  ///< lateral creep coefficient per wheel, G a b C22 [N], > 0
  double lateral_stiffness = 0;    ///< k_y: springs and gravitational stiffness [N/m]
  double yaw_stiffness = 0;        ///< k_psi: springs and gravitational yaw stiffness [N m/rad]
  double lateral_damping = 0;      ///< c_y [N s/m], >= 0
  double yaw_damping = 0;          ///< c_psi [N m s/rad], >= 0

  /// @throws std::invalid_argument naming the first value that is not finite or out of range.
  void validate() const;

  /// The first-order form x' = A x of the equations above, x = (y, psi, y', psi') [SI].
  /// @throws std::invalid_argument naming the speed when it is not finite and > 0 [m/s].
  Eigen::Matrix4d state_matrix(double speed) const;

  /// The four eigenvalues of state_matrix(speed) [1/s], in Eigen's order.
  Eigen::Vector4cd eigenvalues(double speed) const;

  /// The kinematic (Klingel) angular frequency of the free wheelset rolling without creep,
  /// V sqrt(lambda / (r0 b0)) [rad/s].
  double kinematic_angular_frequency(double speed) const;

  /// The closed-form critical speed without dampers (lateral_damping and yaw_damping are ignored):
  /// empty when the denominator lambda / (r0 b0) - ((k_y - m omega_c^2) / (2 f22))^2 is not
  /// positive or omega_c^2 <= 0 (no finite speed at which the wheelset becomes unstable: the free
  /// wheelset, whose critical speed is 0, gives omega_c = 0 and V_c = 0).
  std::optional<WickensCriticalPoint> critical_point() const;
};

}  // namespace wrc
