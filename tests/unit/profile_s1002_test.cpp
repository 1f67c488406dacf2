// SPDX-License-Identifier: Apache-2.0
// Tests of the analytic S1002 wheel profile against the properties in docs/profiles.md ("S1002 wheel").
#include <gtest/gtest.h>

#include <cmath>

#include "core/profile/s1002.hpp"

namespace wrc {
namespace {

constexpr double kMm = 1e-3;

// Bisection for F(s) = target on [a, b] where F - target changes sign (s in metres).
double solve_height(const Profile& p, double target, double a, double b) {
  double fa = p.evaluate(a).height - target;
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    const double fm = p.evaluate(m).height - target;
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

// F(0) = 0 and F'(0) = -0.033585 (published to 6 digits: tolerance 1e-6 on the slope).
TEST(ProfileS1002, TapingLine) {
  const S1002Profile p;
  EXPECT_NEAR(p.evaluate(0.0).height, 0.0, 1e-15);
  EXPECT_NEAR(p.evaluate(0.0).slope, -0.033585, 1e-6);
}

// Flange tip apex F(-55 mm) = 28 mm, a maximum (slope 0, negative curvature -1/12 mm).
TEST(ProfileS1002, FlangeHeight) {
  const S1002Profile p;
  const ProfileSample tip = p.evaluate(-55 * kMm);
  EXPECT_NEAR(tip.height, 28 * kMm, 1e-12);
  EXPECT_NEAR(tip.slope, 0.0, 1e-12);
  EXPECT_NEAR(tip.second_derivative, -1.0 / (12 * kMm), 1e-6);
}

// Flange thickness 32.5 mm: F = 10 mm reached at s = -37.500 mm (on the R13 root arc); an independent
// evaluation of the published form gives -37.5001, so 0.5 um tolerance. qR = s(F=10) - s(F=26) = 10.79 mm
// (value to 0.01 mm).
TEST(ProfileS1002, FlangeThicknessAndQr) {
  const S1002Profile p;
  const double s10 = solve_height(p, 10 * kMm, -38.4 * kMm, -35 * kMm);
  EXPECT_NEAR(70 * kMm + s10, 32.5 * kMm, 0.5e-6);
  const double s26 = solve_height(p, 26 * kMm, -55 * kMm, -39.8 * kMm);
  EXPECT_NEAR(s26, -48.294 * kMm, 1e-6);
  EXPECT_NEAR(s10 - s26, 10.79 * kMm, 0.005 * kMm);
}

// Flank section E is straight at atan(2.747477419) = 70.0 deg (to 0.001 deg).
TEST(ProfileS1002, FlankAngle) {
  const S1002Profile p;
  const double s = -39.0 * kMm;
  EXPECT_NEAR(std::atan(-p.evaluate(s).slope) * 180.0 / M_PI, 70.0, 1e-3);
  EXPECT_EQ(p.evaluate(s).second_derivative, 0.0);
}

// Continuity at the breakpoints (docs/profiles.md): the published data jump by 1.18e-4 mm (C/D, -35 mm) and
// 3.7e-5 mm (B/C, -26 mm) and below 1e-7 mm elsewhere. We require <= 1.3e-7 m at those two and
// <= 2e-10 m elsewhere; the slope may jump by 2.5e-4 at -35/-26 and 1e-6 elsewhere.
TEST(ProfileS1002, ContinuityAtBreakpoints) {
  const S1002Profile p;
  for (double b : p.breakpoints()) {
    const double h = 1e-12;
    const ProfileSample left = p.evaluate(b - h);
    const ProfileSample right = p.evaluate(b + h);
    const bool rough = std::fabs(b + 35 * kMm) < 1e-9 || std::fabs(b + 26 * kMm) < 1e-9;
    EXPECT_LE(std::fabs(left.height - right.height), rough ? 1.3e-7 : 2e-10) << "at s = " << b;
    EXPECT_LE(std::fabs(left.slope - right.slope), rough ? 2.5e-4 : 1e-6) << "at s = " << b;
  }
  // The documented jump at -35 mm is really there (so the tolerance above is not vacuous).
  const double jump = p.evaluate(-35 * kMm - 1e-12).height - p.evaluate(-35 * kMm + 1e-12).height;
  EXPECT_GT(std::fabs(jump), 1e-7);
}

// Domain and metadata; the clamped sqrt keeps the vertical flange back finite.
TEST(ProfileS1002, DomainAndEnds) {
  const S1002Profile p;
  EXPECT_DOUBLE_EQ(p.lower(), -0.070);
  EXPECT_DOUBLE_EQ(p.upper(), 0.060);
  EXPECT_EQ(p.side(), ProfileSide::kWheel);
  EXPECT_EQ(p.breakpoints().size(), 7u);
  const ProfileSample back = p.evaluate(p.lower());
  EXPECT_TRUE(std::isfinite(back.height) && std::isfinite(back.slope) &&
              std::isfinite(back.second_derivative));
  // Outer tread 1:15.
  EXPECT_NEAR(p.evaluate(0.05).slope, -1.0 / 15.0, 1e-9);
}

}  // namespace
}  // namespace wrc
