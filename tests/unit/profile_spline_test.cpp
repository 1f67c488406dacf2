// SPDX-License-Identifier: Apache-2.0
// The cubic spline behind file profiles: interpolation, exactness for parabolas (the end
// condition), C2 continuity across knots, and the thinning of close points.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/numerics/cubic_spline.hpp"
#include "core/profile/spline_profile.hpp"

namespace wrc {
namespace {

// Non-uniform knots, values of a parabola: interpolation and the parabolic end curvature make the
// spline the parabola itself (to rounding, 1e-12 relative).
TEST(ProfileSpline, ReproducesParabola) {
  std::vector<double> x{-2.0, -1.3, -0.2, 0.1, 0.9, 2.5, 3.0};
  std::vector<double> y;
  for (double v : x) y.push_back(0.5 * v * v - v + 2);
  const CubicSpline s(x, y);
  for (double t = -2.0; t <= 3.0; t += 0.01) {
    EXPECT_NEAR(s.evaluate(t).value, 0.5 * t * t - t + 2, 1e-12);
    EXPECT_NEAR(s.evaluate(t).slope, t - 1, 1e-11);
    EXPECT_NEAR(s.evaluate(t).second_derivative, 1.0, 1e-10);
  }
}

// Rough data: passes through every knot; value, slope and second derivative continuous across
// interior knots (evaluated 1e-12 either side: differences bounded by the next derivative times
// 2e-12).
TEST(ProfileSpline, InterpolatesAndIsC2) {
  std::vector<double> x, y;
  for (int i = 0; i < 30; ++i) {
    x.push_back(i + 0.3 * std::sin(3.0 * i));
    y.push_back(std::cos(1.7 * i) + 0.1 * i);
  }
  const CubicSpline s(x, y);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(s.evaluate(x[i]).value, y[i], 1e-13);
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    const SplineSample l = s.evaluate(x[i] - 1e-12);
    const SplineSample r = s.evaluate(x[i] + 1e-12);
    EXPECT_NEAR(l.value, r.value, 1e-10);
    EXPECT_NEAR(l.slope, r.slope, 1e-9);
    EXPECT_NEAR(l.second_derivative, r.second_derivative, 1e-8);
  }
  EXPECT_THROW(CubicSpline({0.0, 1.0}, {0.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(CubicSpline({0.0, 1.0, 1.0}, {0.0, 1.0, 2.0}), std::invalid_argument);
}

// Points closer than the minimum spacing are dropped (ends kept); the profile domain still spans
// all points.
TEST(ProfileSpline, ThinsClosePoints) {
  ProfilePoints p;
  p.source = "test";
  for (int i = 0; i <= 10; ++i) {
    p.lateral.push_back(i * 1e-3);
    p.height.push_back(0.0);
    p.line.push_back(i + 1);
    if (i == 4) {  // two extra points 1e-9 m and 2e-6 m after the 5th
      p.lateral.push_back(4e-3 + 1e-9);
      p.height.push_back(0.0);
      p.line.push_back(100);
      p.lateral.push_back(4e-3 + 2e-6);
      p.height.push_back(0.0);
      p.line.push_back(101);
    }
  }
  const SplineProfile sp(p, ProfileSide::kRail, "test", 0.0);
  EXPECT_EQ(sp.knot_count(), 11u);
  EXPECT_EQ(sp.lower(), 0.0);
  EXPECT_EQ(sp.upper(), 10e-3);
  EXPECT_EQ(sp.evaluate(4e-3 + 1e-6).height, 0.0);
}

}  // namespace
}  // namespace wrc
