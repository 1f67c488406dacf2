// SPDX-License-Identifier: Apache-2.0
// Mirror symmetry of the S1002/UIC60 wheelset: mirroring the track about its centre plane maps
// (y, roll, yaw) to (-y, -roll, -yaw) and swaps the left and right wheels.

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/rigid_wheelset.hpp"
#include "core/profile/profile_factory.hpp"

namespace wrc {
namespace {

WheelsetGeometry s1002_on_uic60() {
  return WheelsetGeometry(make_profile("S1002", ProfileSide::kWheel), make_profile("UIC60", ProfileSide::kRail));
}

// Rigid wheelset at (y, yaw) and (-y, -yaw): same height, opposite roll, wheels swapped (radius,
// contact angle, profile coordinates, longitudinal contact position). Both sides run through the
// same code with sigma = -+1, so they agree to the solver tolerances (1e-12 m height, 1e-12 m in s;
// the rail inversion is exact to 1e-14 m): 1e-10 leaves margin for the jump-free interior.
TEST(GeometrySymmetry, MirroredShiftSwapsTheWheels) {
  const WheelsetGeometry g = s1002_on_uic60();
  const RigidWheelsetSolver solver(g);
  for (double yaw : {0.0, 0.004, -0.008}) {
    for (double y = -0.0095; y <= 0.0096; y += 0.0007) {
      const RigidContact a = solver.solve(y, yaw);
      const RigidContact b = solver.solve(-y, -yaw);
      EXPECT_NEAR(a.pose.z, b.pose.z, 1e-11) << "y=" << y << " yaw=" << yaw;
      EXPECT_NEAR(a.pose.roll, -b.pose.roll, 1e-11) << "y=" << y;
      EXPECT_NEAR(a.left().rolling_radius, b.right().rolling_radius, 1e-10) << "y=" << y;
      EXPECT_NEAR(a.right().rolling_radius, b.left().rolling_radius, 1e-10) << "y=" << y;
      EXPECT_NEAR(a.left().contact_angle, b.right().contact_angle, 1e-8) << "y=" << y;
      EXPECT_NEAR(a.left().s, b.right().s, 1e-9) << "y=" << y;
      EXPECT_NEAR(a.right().s, b.left().s, 1e-9) << "y=" << y;
      EXPECT_NEAR(a.left().wheel_point.x(), b.right().wheel_point.x(), 1e-9) << "y=" << y;
      EXPECT_NEAR(a.left().wheel_point.y(), -b.right().wheel_point.y(), 1e-9) << "y=" << y;
      EXPECT_EQ(a.potential[0].size(), b.potential[1].size()) << "y=" << y;
      EXPECT_NEAR(a.delta_r(), -b.delta_r(), 2e-10) << "y=" << y;
    }
  }
}

// The centred wheelset without yaw is symmetric itself: zero roll, equal radii, delta_r = 0.
TEST(GeometrySymmetry, CentredWheelsetHasNoRollAndEqualRadii) {
  const WheelsetGeometry g = s1002_on_uic60();
  const RigidContact c = RigidWheelsetSolver(g).solve(0.0, 0.0);
  EXPECT_NEAR(c.pose.roll, 0.0, 1e-12);
  EXPECT_NEAR(c.delta_r(), 0.0, 1e-12);
  EXPECT_NEAR(c.left().contact_angle, c.right().contact_angle, 1e-10);
  // Height: the wheel sits near its nominal radius (contact within a few mm of the taping line).
  EXPECT_NEAR(c.pose.z, 0.46, 1e-3);
}

// Potential points of one wheel are mirrored too (the per-wheel search, not just the rigid solve),
// including configurations with several potential points.
TEST(GeometrySymmetry, PotentialPointsMirror) {
  const WheelsetGeometry g = s1002_on_uic60();
  for (double y : {-0.006, -0.0047, 0.0, 0.005, 0.0071}) {
    for (double roll : {-0.002, 0.0, 0.001}) {
      WheelsetPose p;
      p.y = y;
      p.z = 0.46;
      p.roll = roll;
      p.yaw = 0.003;
      WheelsetPose m = p;
      m.y = -y;
      m.roll = -roll;
      m.yaw = -p.yaw;
      const auto left = g.potential_points(WheelSide::kLeft, p);
      const auto right = g.potential_points(WheelSide::kRight, m);
      ASSERT_EQ(left.size(), right.size()) << "y=" << y << " roll=" << roll;
      for (size_t i = 0; i < left.size(); ++i) {
        EXPECT_NEAR(left[i].s, right[i].s, 1e-9);
        EXPECT_NEAR(left[i].distance, right[i].distance, 1e-11);
        EXPECT_EQ(left[i].is_minimum, right[i].is_minimum);
      }
    }
  }
}

}  // namespace
}  // namespace wrc
