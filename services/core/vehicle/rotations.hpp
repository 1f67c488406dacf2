// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The elementary rotations of the vehicle layer's frames (docs/conventions.md): a body's
/// orientation R = Rz(yaw) Ry(pitch) Rx(roll), a track frame's cant Rx and heading Rz. Each maps a
/// vector's coordinates in the rotated frame to those in the frame it is rotated from.

#include <cmath>

#include <Eigen/Core>

namespace wrc {

/// The rotation by angle [rad] about x (roll, cant).
inline Eigen::Matrix3d rotation_x(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, c, -s, 0, s, c;
  return r;
}

/// The rotation by angle [rad] about y (pitch).
inline Eigen::Matrix3d rotation_y(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << c, 0, s, 0, 1, 0, -s, 0, c;
  return r;
}

/// The rotation by angle [rad] about z (yaw, heading).
inline Eigen::Matrix3d rotation_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << c, -s, 0, s, c, 0, 0, 0, 1;
  return r;
}

}  // namespace wrc
