// SPDX-License-Identifier: Apache-2.0
// With yaw the curve C leaves the vertical plane through the axle: the common point moves ahead
// of or behind the axle (by about r0 * R'(s) * yaw, up to centimetres on the flange). Checked
// against a brute-force minimum of the vertical distance over the whole 2-D wheel surface.

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/wheelset_geometry.hpp"
#include "core/profile/profile_factory.hpp"

namespace wrc {
namespace {

struct GridMinimum {
  double distance = 1e300, s = 0, theta = 0, x = 0;
};

// Vertical distance of the wheel surface point (s, theta) above the rail, evaluated from the
// surface-of-revolution definition directly (independent of the curve C).
GridMinimum brute_force(const WheelsetGeometry& g, WheelSide side, const WheelsetPose& pose, double s_lo, double s_hi,
                        double ds, double t_lo, double t_hi, double dt) {
  const double sigma = side_sign(side);
  const double a = g.track().taping_half_distance(), r0 = g.track().nominal_radius;
  const double cpsi = std::cos(pose.yaw), spsi = std::sin(pose.yaw), cphi = std::cos(pose.roll),
               sphi = std::sin(pose.roll);
  GridMinimum best;
  for (double s = s_lo; s <= s_hi; s += ds) {
    if (s < g.wheel_profile().lower() || s > g.wheel_profile().upper()) continue;
    const double radius = r0 + g.wheel_profile().evaluate(s).height;
    for (double t = t_lo; t <= t_hi; t += dt) {
      const double bx = -radius * std::sin(t), by = sigma * (a + s), bz = -radius * std::cos(t);
      // A = Rz(yaw) Rx(roll)
      const double rx = bx, ry = by * cphi - bz * sphi, rz = by * sphi + bz * cphi;
      const double x = cpsi * rx - spsi * ry + pose.x, y = spsi * rx + cpsi * ry + pose.y, z = rz + pose.z;
      const RailSample r = g.rail(side).at(y);
      if (!r.valid) continue;
      if (z - r.z < best.distance) best = {z - r.z, s, t, x};
    }
  }
  return best;
}

// Brute force on a coarse grid over the whole wheel, then a fine grid (2 um x 2e-5 rad) around
// its minimum. The grid minimum exceeds the true minimum by at most about
// (ds^2 * |d2 distance/ds2| + (R dt)^2 / R) / 8 < 1e-8 m here; so the distances must agree to 2e-8 m,
// and the positions to the resolution the flat minimum allows (0.05 mm in s, 0.3 mm in x).
TEST(GeometryYaw, CommonPointMatchesBruteForceOverTheWheelSurface) {
  const WheelsetGeometry g(make_profile("S1002", ProfileSide::kWheel), make_profile("UIC60", ProfileSide::kRail));
  struct Case {
    double y, roll, yaw;
    WheelSide side;
  } cases[] = {{0.0, 0.0, 0.01, WheelSide::kLeft},      {0.003, 0.0002, -0.01, WheelSide::kLeft},
               {0.0072, 0.0064, 0.012, WheelSide::kLeft}, {0.0072, 0.0064, -0.02, WheelSide::kLeft},
               {-0.0065, -0.004, 0.015, WheelSide::kRight}};
  for (const Case& c : cases) {
    WheelsetPose pose;
    pose.y = c.y;
    pose.roll = c.roll;
    pose.yaw = c.yaw;
    pose.z = 0.46;
    const auto common = g.common_point(c.side, pose);
    ASSERT_TRUE(common.has_value());
    const GridMinimum coarse = brute_force(g, c.side, pose, -0.07, 0.06, 2e-4, -0.08, 0.08, 2e-3);
    const GridMinimum fine = brute_force(g, c.side, pose, coarse.s - 4e-4, coarse.s + 4e-4, 2e-6, coarse.theta - 4e-3,
                                         coarse.theta + 4e-3, 2e-5);
    EXPECT_GE(fine.distance, common->distance - 1e-12) << "y=" << c.y << " yaw=" << c.yaw;
    EXPECT_NEAR(fine.distance, common->distance, 2e-8) << "y=" << c.y << " yaw=" << c.yaw;
    EXPECT_NEAR(fine.s, common->s, 5e-5) << "y=" << c.y << " yaw=" << c.yaw;
    EXPECT_NEAR(fine.x, common->wheel_point.x(), 3e-4) << "y=" << c.y << " yaw=" << c.yaw;
  }
}

// On the flange the contact point lies well ahead of or behind the wheel's centre: by about -R*R'(s)*yaw
// (docs/contact-mechanics.md, "Where contact can occur"), i.e. several millimetres at 10 mrad, while on the
// tread (|R'| < 0.05) the lead stays below 0.25 mm. The lead is measured from the wheel-centre point of the
// contact's cross-section, which the yaw itself moves by -sin(yaw)*(lateral arm).
TEST(GeometryYaw, FlangeContactLeadsTheWheelCentre) {
  const WheelsetGeometry g(make_profile("S1002", ProfileSide::kWheel), make_profile("UIC60", ProfileSide::kRail));
  auto lead = [&](const ContactPoint& p, const WheelsetPose& pose) {
    const double arm = g.track().taping_half_distance() + p.s;  // left wheel: sigma = +1
    return p.wheel_point.x() + std::sin(pose.yaw) * std::cos(pose.roll) * arm;
  };
  WheelsetPose pose;
  pose.y = 0.0072;
  pose.roll = 0.0064;
  pose.yaw = 0.01;
  pose.z = 0.46;
  const auto flange = g.common_point(WheelSide::kLeft, pose);
  ASSERT_TRUE(flange.has_value());
  const double slope = g.wheel_profile().evaluate(flange->s).slope;
  ASSERT_GT(std::fabs(slope), 1.0) << "expected flange contact, s=" << flange->s;
  // theta ~ yaw*R'/sqrt(1 + ...) to first order; 5 % covers the neglected roll and second-order terms.
  const double expected = -flange->rolling_radius * slope * pose.yaw;
  EXPECT_NEAR(lead(*flange, pose), expected, 0.05 * std::fabs(expected));
  EXPECT_GT(std::fabs(lead(*flange, pose)), 5e-3);
  pose.y = 0.0;
  pose.roll = 0.0;
  const auto tread = g.common_point(WheelSide::kLeft, pose);
  ASSERT_TRUE(tread.has_value());
  EXPECT_LT(std::fabs(lead(*tread, pose)), 2.5e-4);
}

}  // namespace
}  // namespace wrc
