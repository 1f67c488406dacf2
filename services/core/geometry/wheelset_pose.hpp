// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Position and orientation of a rigid wheelset relative to the track.

namespace wrc {

/// Rigid-wheelset configuration in the track frame. Orientation: yaw psi about z, then roll phi
/// about the rotated x (body-to-track rotation Rz(yaw) * Rx(roll)).
struct WheelsetPose {
  double y = 0;     ///< lateral shift of the wheelset centre, > 0 towards the left rail [m]
  double z = 0;     ///< height of the wheelset centre above the top-of-rail plane [m]
  double roll = 0;  ///< roll angle phi, > 0 raises the left wheel [rad]
  double yaw = 0;   ///< yaw angle psi, > 0 counter-clockwise seen from above [rad]
  double x = 0;     ///< longitudinal position [m]; the rail is prismatic, so only reported positions depend on it
};

}  // namespace wrc
