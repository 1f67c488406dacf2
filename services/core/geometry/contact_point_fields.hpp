// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A contact point as numbers relative to the wheelset's pose: the one list of the ContactPoint
/// fields a precomputed model stores and interpolates (the interpolation table, the spline fit),
/// and the point rebuilt from them at any pose.

#include <array>

#include "core/geometry/contact_point.hpp"
#include "core/geometry/wheel_side.hpp"
#include "core/geometry/wheelset_pose.hpp"

namespace wrc {

/// Index of a contact point field. Positions are relative to the wheelset centre, so that the
/// fields depend on y, roll and yaw only, not on the height z or the longitudinal position x.
enum ContactPointField : int {
  kPointS,                      ///< ContactPoint::s, wheel profile coordinate [m]
  kPointSRail,                  ///< ContactPoint::s_rail, rail profile coordinate [m]
  kPointTheta,                  ///< ContactPoint::theta, angular position on the wheel [rad]
  kPointWheelX,                 ///< wheel point minus the wheelset centre, track x [m]
  kPointWheelY,                 ///< the same, track y [m]
  kPointWheelZ,                 ///< the same, track z [m]
  kPointRailZ,                  ///< height of the rail point [m] (it lies vertically below the wheel point)
  kPointContactAngle,           ///< ContactPoint::contact_angle [rad]
  kPointRollingRadius,          ///< ContactPoint::rolling_radius [m]
  kPointNormalX,                ///< common normal, track x [-]
  kPointNormalY,                ///< the same, track y [-]
  kPointNormalZ,                ///< the same, track z [-]
  kPointWheelCurvatureLateral,  ///< ContactPoint::wheel_curvature_lateral [1/m]
  kPointWheelCurvatureRolling,  ///< ContactPoint::wheel_curvature_rolling [1/m]
  kPointRailCurvatureLateral,   ///< ContactPoint::rail_curvature_lateral [1/m]
  kPointRailCurvatureRolling,   ///< ContactPoint::rail_curvature_rolling [1/m]
  kPointDistanceCurvature,      ///< ContactPoint::distance_curvature [1/m]
  kContactPointFieldCount
};

/// Every field of a point, in ContactPointField order.
using ContactPointFields = std::array<double, kContactPointFieldCount>;

/// The fields of point p of a wheelset at pose (all but side, distance and is_minimum).
ContactPointFields contact_point_fields(const ContactPoint& p, const WheelsetPose& pose);

/// The point of wheel side with these fields at pose: positions shifted by the pose, the rail
/// point vertically below the wheel point, the normal renormalised, the given distance [m], marked
/// a local minimum (a precomputed model interpolates only the common point).
ContactPoint contact_point_from_fields(const ContactPointFields& fields, WheelSide side, const WheelsetPose& pose,
                                       double distance);

}  // namespace wrc
