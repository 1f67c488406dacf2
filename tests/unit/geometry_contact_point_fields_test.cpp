// SPDX-License-Identifier: Apache-2.0
/// @file
/// The contact point's fields (core/geometry/contact_point_fields.hpp): every field of a point
/// with distinct values lands in its own index, positions relative to the pose, and the point
/// rebuilt from them at the same pose is the point (the normal renormalised, marked a minimum).
#include <gtest/gtest.h>

#include <set>

#include "core/geometry/contact_point_fields.hpp"

namespace wrc {
namespace {

TEST(ContactPointFields, EveryFieldInItsPlaceAndBack) {
  ContactPoint p;
  p.side = WheelSide::kRight;
  p.s = 0.001;
  p.s_rail = 0.002;
  p.theta = 0.003;
  p.wheel_point = {0.104, 0.205, 0.306};
  p.rail_point = {0.104, 0.205, 0.007};
  p.normal = Eigen::Vector3d(0.008, 0.009, 0.010).normalized();
  p.distance = 0.0111;
  p.contact_angle = 0.012;
  p.rolling_radius = 0.013;
  p.wheel_curvature_lateral = 0.014;
  p.wheel_curvature_rolling = 0.015;
  p.rail_curvature_lateral = 0.016;
  p.rail_curvature_rolling = 0.017;
  p.distance_curvature = 0.018;
  WheelsetPose pose;
  pose.x = 0.1;
  pose.y = 0.2;
  pose.z = 0.3;
  pose.roll = 0.0004;
  pose.yaw = 0.0005;
  const ContactPointFields f = contact_point_fields(p, pose);
  EXPECT_EQ(f[kPointS], p.s);
  EXPECT_EQ(f[kPointSRail], p.s_rail);
  EXPECT_EQ(f[kPointTheta], p.theta);
  EXPECT_EQ(f[kPointWheelX], p.wheel_point.x() - pose.x);
  EXPECT_EQ(f[kPointWheelY], p.wheel_point.y() - pose.y);
  EXPECT_EQ(f[kPointWheelZ], p.wheel_point.z() - pose.z);
  EXPECT_EQ(f[kPointRailZ], p.rail_point.z());
  EXPECT_EQ(f[kPointContactAngle], p.contact_angle);
  EXPECT_EQ(f[kPointRollingRadius], p.rolling_radius);
  EXPECT_EQ(f[kPointNormalX], p.normal.x());
  EXPECT_EQ(f[kPointNormalY], p.normal.y());
  EXPECT_EQ(f[kPointNormalZ], p.normal.z());
  EXPECT_EQ(f[kPointWheelCurvatureLateral], p.wheel_curvature_lateral);
  EXPECT_EQ(f[kPointWheelCurvatureRolling], p.wheel_curvature_rolling);
  EXPECT_EQ(f[kPointRailCurvatureLateral], p.rail_curvature_lateral);
  EXPECT_EQ(f[kPointRailCurvatureRolling], p.rail_curvature_rolling);
  EXPECT_EQ(f[kPointDistanceCurvature], p.distance_curvature);
  EXPECT_EQ(std::set<double>(f.begin(), f.end()).size(), f.size()) << "two fields share a value";

  const ContactPoint q = contact_point_from_fields(f, WheelSide::kRight, pose, p.distance);
  EXPECT_EQ(q.side, WheelSide::kRight);
  EXPECT_EQ(q.distance, p.distance);
  EXPECT_TRUE(q.is_minimum);
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(q.wheel_point[k], p.wheel_point[k]);
    EXPECT_DOUBLE_EQ(q.rail_point[k], p.rail_point[k]);
    EXPECT_DOUBLE_EQ(q.normal[k], p.normal[k]);
  }
  const ContactPointFields back = contact_point_fields(q, pose);
  for (int k = 0; k < kContactPointFieldCount; ++k) EXPECT_DOUBLE_EQ(back[static_cast<size_t>(k)], f[static_cast<size_t>(k)]) << k;
}

}  // namespace
}  // namespace wrc
