// SPDX-License-Identifier: Apache-2.0
// Elastic division of a rigid wheel's load among several Hertz contacts (load_division.hpp):
// the normal forces sum to the load, every reached point shares one vertical approach, points
// beyond it carry nothing, and the closed forms of one and two identical points are reproduced.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>
#include <stdexcept>

#include "core/models/load_division.hpp"

namespace wrc {
namespace {

// One point: all the load, approach from N = C (d cos)^{3/2} inverted.
TEST(ModelsLoadDivision, SinglePointTakesTheLoad) {
  const LoadDivision d = divide_load(80e3, {{1.2e11, 0.0, std::cos(0.05)}});
  ASSERT_EQ(d.active, 1);
  EXPECT_EQ(d.normal_force[0], 80e3);
  EXPECT_NEAR(d.approach, std::pow(80e3 / 1.2e11, 2.0 / 3.0) / std::cos(0.05), 1e-12 * d.approach);
}

// Two identical points at the same height share the load equally.
TEST(ModelsLoadDivision, TwoEqualPointsShareEqually) {
  const LoadDivision d = divide_load(100e3, {{1e11, 0.0, 0.99}, {1e11, 0.0, 0.99}});
  ASSERT_EQ(d.active, 2);
  EXPECT_NEAR(d.normal_force[0], 50e3, 1e-9 * 50e3);
  EXPECT_NEAR(d.normal_force[1], 50e3, 1e-9 * 50e3);
}

// Different stiffness, gap and angle: the forces sum to the load (rounding), each one follows
// the Hertz law at the common approach (relative 1e-10: the root is solved to 1e-14 d and
// the forces then scaled by a factor 1 +- O(1e-13)), and a point whose gap exceeds the approach
// gets nothing.
TEST(ModelsLoadDivision, CommonApproachAndSum) {
  const std::vector<DivisionPoint> points{{0.8e11, 12e-6, std::cos(0.3)}, {1.3e11, 0.0, std::cos(0.12)},
                                          {1.0e11, 500e-6, std::cos(0.05)}};
  const LoadDivision d = divide_load(80e3, points);
  ASSERT_EQ(d.active, 2);
  EXPECT_EQ(d.normal_force[2], 0.0);
  EXPECT_GT(d.approach, 12e-6);
  EXPECT_LT(d.approach, 500e-6);
  EXPECT_NEAR(d.normal_force[0] + d.normal_force[1], 80e3, 1e-9);
  for (int k = 0; k < 2; ++k) {
    const DivisionPoint& p = points[static_cast<size_t>(k)];
    const double delta = (d.approach - p.gap) * p.cos_angle;
    EXPECT_NEAR(d.penetration[static_cast<size_t>(k)], delta, 1e-15);
    EXPECT_NEAR(d.normal_force[static_cast<size_t>(k)], p.stiffness * std::pow(delta, 1.5),
                1e-10 * d.normal_force[static_cast<size_t>(k)]);
  }
  // The flange-root point (gap 12 um) carries less than the closer one but a real share.
  EXPECT_GT(d.normal_force[0], 0.1 * 80e3);
  EXPECT_LT(d.normal_force[0], d.normal_force[1]);
}

// Two points in one overlap (the maximum between them, 30 um above the closer point, lies below
// the approach): the closer point has the whole approach d, the other the depth d (c - g_1) / c
// (interpenetration_regions.hpp, c the barrier above the closer point), the forces still sum to
// the load; the same points with the barrier at or above the approach divide as the paper's rule
// (each d - gap), which a barrier of +infinity reproduces exactly.
TEST(ModelsLoadDivision, PointsOfOneOverlapShareItsDepth) {
  std::vector<DivisionPoint> points{{1.3e11, 0.0, std::cos(0.12), 30e-6}, {0.8e11, 12e-6, std::cos(0.3)}};
  const LoadDivision d = divide_load(80e3, points);
  ASSERT_EQ(d.active, 2);
  ASSERT_GT(d.approach, 30e-6);  // the barrier is below the approach: one overlap
  EXPECT_NEAR(d.normal_force[0] + d.normal_force[1], 80e3, 1e-9);
  EXPECT_NEAR(d.penetration[0], d.approach * points[0].cos_angle, 1e-15);
  EXPECT_NEAR(d.penetration[1], d.approach * (30e-6 - 12e-6) / 30e-6 * points[1].cos_angle, 1e-15);
  EXPECT_LT(d.penetration[1], (d.approach - 12e-6) * points[1].cos_angle);
  points[0].barrier_after = std::numeric_limits<double>::infinity();
  const LoadDivision separate = divide_load(80e3, points);
  points[0].barrier_after = 1e-3;  // far above any approach
  const LoadDivision high = divide_load(80e3, points);
  EXPECT_EQ(separate.approach, high.approach);
  EXPECT_NEAR(separate.penetration[1], (separate.approach - 12e-6) * points[1].cos_angle, 1e-15);
  EXPECT_LT(separate.approach, d.approach);  // shared depths carry less: the wheel goes deeper
}

// Zero load gives zero forces; malformed input throws.
TEST(ModelsLoadDivision, EdgeCases) {
  const LoadDivision zero = divide_load(0.0, {{1e11, 0.0, 1.0}});
  EXPECT_EQ(zero.normal_force[0], 0.0);
  EXPECT_EQ(zero.active, 0);
  EXPECT_THROW(divide_load(1.0, {}), std::invalid_argument);
  EXPECT_THROW(divide_load(-1.0, {{1e11, 0.0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(divide_load(1.0, {{0.0, 0.0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(divide_load(1.0, {{1e11, -1e-6, 1.0}}), std::invalid_argument);
  EXPECT_THROW(divide_load(1.0, {{1e11, 0.0, 0.0}}), std::invalid_argument);
  // A barrier below a point it separates, also with no load to divide.
  EXPECT_THROW(divide_load(0.0, {{1e11, 0.0, 1.0, 5e-6}, {1e11, 10e-6, 1.0}}), std::invalid_argument);
  EXPECT_THROW(divide_load(1.0, {{1e11, 0.0, 1.0, std::nan("")}}), std::invalid_argument);
}

}  // namespace
}  // namespace wrc
