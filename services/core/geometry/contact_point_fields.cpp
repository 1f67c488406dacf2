// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/contact_point_fields.hpp"

namespace wrc {

ContactPointFields contact_point_fields(const ContactPoint& p, const WheelsetPose& pose) {
  ContactPointFields f;
  f[kPointS] = p.s;
  f[kPointSRail] = p.s_rail;
  f[kPointTheta] = p.theta;
  f[kPointWheelX] = p.wheel_point.x() - pose.x;
  f[kPointWheelY] = p.wheel_point.y() - pose.y;
  f[kPointWheelZ] = p.wheel_point.z() - pose.z;
  f[kPointRailZ] = p.rail_point.z();
  f[kPointContactAngle] = p.contact_angle;
  f[kPointRollingRadius] = p.rolling_radius;
  f[kPointNormalX] = p.normal.x();
  f[kPointNormalY] = p.normal.y();
  f[kPointNormalZ] = p.normal.z();
  f[kPointWheelCurvatureLateral] = p.wheel_curvature_lateral;
  f[kPointWheelCurvatureRolling] = p.wheel_curvature_rolling;
  f[kPointRailCurvatureLateral] = p.rail_curvature_lateral;
  f[kPointRailCurvatureRolling] = p.rail_curvature_rolling;
  f[kPointDistanceCurvature] = p.distance_curvature;
  return f;
}

ContactPoint contact_point_from_fields(const ContactPointFields& f, WheelSide side, const WheelsetPose& pose,
                                       double distance) {
  ContactPoint p;
  p.side = side;
  p.s = f[kPointS];
  p.s_rail = f[kPointSRail];
  p.theta = f[kPointTheta];
  p.wheel_point = Eigen::Vector3d(pose.x + f[kPointWheelX], pose.y + f[kPointWheelY], pose.z + f[kPointWheelZ]);
  p.rail_point = Eigen::Vector3d(p.wheel_point.x(), p.wheel_point.y(), f[kPointRailZ]);
  p.normal = Eigen::Vector3d(f[kPointNormalX], f[kPointNormalY], f[kPointNormalZ]).normalized();
  p.distance = distance;
  p.contact_angle = f[kPointContactAngle];
  p.rolling_radius = f[kPointRollingRadius];
  p.wheel_curvature_lateral = f[kPointWheelCurvatureLateral];
  p.wheel_curvature_rolling = f[kPointWheelCurvatureRolling];
  p.rail_curvature_lateral = f[kPointRailCurvatureLateral];
  p.rail_curvature_rolling = f[kPointRailCurvatureRolling];
  p.distance_curvature = f[kPointDistanceCurvature];
  p.is_minimum = true;
  return p;
}

}  // namespace wrc
