// SPDX-License-Identifier: Apache-2.0
// The rigid-wheelset solver's fast mode (only the lowest local minima are looked for, with a
// quadratic lower bound of the distance certifying everything else) gives the same solution as
// the full potential-point scan, cold and warm, across contact-point jumps.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/geometry/rigid_wheelset.hpp"
#include "core/profile/profile_factory.hpp"

namespace wrc {
namespace {

// Same roll, height and common points: both modes converge the roll iteration to a height residual
// of 1e-12 m, i.e. roll to 1e-12 m over the smallest d(residual)/d(roll) (about 0.3 m/rad in flange
// contact): 5e-12 rad; height 1e-12 m; contact positions 1e-10 m.
TEST(GeometryCertifiedSolve, FastModeMatchesFullScan) {
  const WheelsetGeometry g(make_profile("S1002", ProfileSide::kWheel), make_profile("UIC60", ProfileSide::kRail));
  RigidSolverOptions fast_options;
  fast_options.all_potential_points = false;
  const RigidWheelsetSolver full(g), fast(g, fast_options);
  for (double yaw : {0.0, 0.006}) {
    RigidContact warm_full, warm_fast;
    int n = 0;
    for (double y = -0.0095; y <= 0.0095; y += 0.00023, ++n) {
      const RigidContact a = full.solve(y, yaw);
      const RigidContact b = fast.solve(y, yaw);
      const RigidContact c = n == 0 ? b : fast.solve(y, yaw, warm_fast);
      warm_fast = c;
      for (const RigidContact* r : {&b, &c}) {
        EXPECT_NEAR(r->pose.roll, a.pose.roll, 5e-12) << "y=" << y << " yaw=" << yaw;
        EXPECT_NEAR(r->pose.z, a.pose.z, 1e-12) << "y=" << y;
        EXPECT_NEAR(r->left().s, a.left().s, 1e-10) << "y=" << y;
        EXPECT_NEAR(r->right().s, a.right().s, 1e-10) << "y=" << y;
        EXPECT_NEAR(r->delta_r(), a.delta_r(), 1e-11) << "y=" << y;
      }
    }
  }
}

// In fast mode the reported potential points are local minima no higher than the common point
// plus 1e-9 m, and the common point is among them.
TEST(GeometryCertifiedSolve, FastModeReportsOnlyTheLowestMinima) {
  const WheelsetGeometry g(make_profile("S1002", ProfileSide::kWheel), make_profile("UIC60", ProfileSide::kRail));
  RigidSolverOptions fast_options;
  fast_options.all_potential_points = false;
  const RigidContact c = RigidWheelsetSolver(g, fast_options).solve(0.0, 0.0);
  for (int w = 0; w < 2; ++w) {
    ASSERT_FALSE(c.potential[w].empty());
    for (const auto& p : c.potential[w]) {
      EXPECT_TRUE(p.is_minimum);
      EXPECT_LE(p.distance, 1e-9);
    }
  }
  // Full scan at y = 0 has 3 potential points per wheel (two minima and a maximum).
  EXPECT_EQ(RigidWheelsetSolver(g).solve(0.0, 0.0).potential[0].size(), 3u);
}


}  // namespace
}  // namespace wrc

namespace wrc {
namespace {

// WheelsetGeometry::common_point (minima at the level of a coarse sampling only) equals the
// common point selected from the full list of potential points, for both wheels, with roll and
// yaw, across the jumps (same root tolerance: 1e-12 m in s, distances to 1e-12 m).
TEST(GeometryCertifiedSolve, CommonPointEqualsSelectionFromAllPotentialPoints) {
  const WheelsetGeometry g(make_profile("S1002", ProfileSide::kWheel), make_profile("UIC60", ProfileSide::kRail));
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    for (double y = -0.011; y <= 0.011; y += 0.0004) {
      for (double roll : {-0.006, 0.0, 0.003}) {
        WheelsetPose pose;
        pose.y = y;
        pose.roll = roll;
        pose.yaw = 0.004;
        pose.z = 0.46;
        const auto all = select_common_point(g.potential_points(side, pose));
        const auto fast = g.common_point(side, pose);
        ASSERT_EQ(all.has_value(), fast.has_value()) << "y=" << y;
        if (!all) continue;
        EXPECT_NEAR(fast->s, all->s, 1e-10) << side_name(side) << " y=" << y << " roll=" << roll;
        EXPECT_NEAR(fast->distance, all->distance, 1e-12) << "y=" << y;
      }
    }
  }
}


// The certified common point is the global minimum of the distance along C: no sample of a dense
// 5 um sampling lies below it (beyond 1e-12 m), and it lies at most the sampling's own error below
// the lowest sample (M h^2 / 8; with the wheel deep in the rail at large yaw and roll the distance's
// curvature reaches ~3e4 1/m: 1e-7 m asserted). 625 poses (y +-12 mm, roll +-20 mrad, yaw 0, +-10
// and +-60 mrad, the validated limit kMaxValidatedYaw), both wheels, contact on tread, flange root
// and flange. (The release check used 2 um over 6174 poses up to +-10 mrad and 5 um over 8232
// poses at +-50 and +-60 mrad: no difference.)
TEST(GeometryCertifiedSolve, CommonPointIsTheLowestPointOfADenseSampling) {
  const WheelsetGeometry g(make_profile("S1002", ProfileSide::kWheel), make_profile("UIC60", ProfileSide::kRail));
  int checked = 0;
  for (int iy = -12; iy <= 12; ++iy) {
    for (double roll : {-0.02, -0.01, 0.0, 0.01, 0.02}) {
      for (double yaw : {-kMaxValidatedYaw, -0.01, 0.0, 0.01, kMaxValidatedYaw}) {
        WheelsetPose pose;
        pose.y = iy * 1e-3;
        pose.roll = roll;
        pose.yaw = yaw;
        pose.z = 0.46;
        for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
          const auto point = g.common_point(side, pose);
          ASSERT_TRUE(point) << side_name(side) << " y=" << pose.y << " roll=" << roll << " yaw=" << yaw;
          const ContactLocus c = g.locus(side, pose);
          double lowest = std::numeric_limits<double>::infinity(), lowest_s = 0.0;
          for (double s = c.s_lower(); s <= c.s_upper(); s += 5e-6) {
            double d, slope;
            c.distance_and_slope(s, d, slope);
            if (d < lowest) {
              lowest = d;
              lowest_s = s;
            }
          }
          EXPECT_LE(point->distance, lowest + 1e-12)
              << side_name(side) << " y=" << pose.y << " roll=" << roll << " yaw=" << yaw
              << ": a sample at s=" << lowest_s << " lies lower than the common point at s=" << point->s;
          EXPECT_GE(point->distance, lowest - 1e-7) << side_name(side) << " y=" << pose.y;
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 1250);
}

}  // namespace
}  // namespace wrc
