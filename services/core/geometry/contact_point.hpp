// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A potential common point of wheel and rail with everything the contact models need there.

#include <Eigen/Core>

#include "core/geometry/wheel_side.hpp"

namespace wrc {

/// A potential common point (the paper's section 3): wheel and rail surface normals are parallel
/// there. The common point is the potential point with the smallest distance.
struct ContactPoint {
  WheelSide side = WheelSide::kLeft;
  double s = 0;        ///< wheel profile coordinate (from the taping line, > 0 field side) [m]
  double s_rail = 0;   ///< rail profile coordinate (from the profile origin, > 0 field side) [m]
  double theta = 0;    ///< angular position on the wheel from its lowest point [rad] (non-zero with yaw)
  Eigen::Vector3d wheel_point{0, 0, 0};  ///< point on the wheel surface, track frame [m]
  Eigen::Vector3d rail_point{0, 0, 0};   ///< rail surface point vertically below it, track frame [m]
  /// Unit common normal, pointing from the rail into the wheel (direction of the normal force on
  /// the wheel), track frame [-].
  Eigen::Vector3d normal{0, 0, 1};
  double distance = 0;        ///< vertical distance wheel minus rail [m] (< 0: the surfaces overlap)
  double contact_angle = 0;   ///< angle between contact plane and track plane [rad]; > 0 when the normal
                              ///< force pushes the wheel towards the track centre (flange side)
  double rolling_radius = 0;  ///< distance of the wheel point from the axle [m]
  double wheel_curvature_lateral = 0;  ///< profile (meridian) curvature of the wheel [1/m], > 0 convex
  double wheel_curvature_rolling = 0;  ///< wheel curvature in the rolling direction [1/m] (Meusnier)
  double rail_curvature_lateral = 0;   ///< rail profile curvature [1/m], > 0 convex (crown)
  double rail_curvature_rolling = 0;   ///< rail curvature along the track [1/m] (0 on straight track)
  double distance_curvature = 0;       ///< d2(distance)/ds2 along the curve C [1/m]
  bool is_minimum = false;             ///< local minimum of the distance along C

  /// Relative curvature in the rolling direction, A = (wheel + rail) / 2 [1/m].
  double relative_curvature_rolling() const { return 0.5 * (wheel_curvature_rolling + rail_curvature_rolling); }
  /// Relative curvature in the lateral direction, B = (wheel + rail) / 2 [1/m].
  double relative_curvature_lateral() const { return 0.5 * (wheel_curvature_lateral + rail_curvature_lateral); }
};

}  // namespace wrc
