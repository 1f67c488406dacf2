// SPDX-License-Identifier: Apache-2.0
// Tests of the analytic UIC60 rail head (EN 60E1 construction and the Manchester variant).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/profile/uic60.hpp"

namespace wrc {
namespace {

constexpr double kMm = 1e-3;

// The construction reproduces the published EN 60E1 centres (docs/profiles.md, "UIC60 / 60E1 rail head";
// given to 1e-6 mm).
TEST(ProfileUic60, En60E1Centres) {
  const Uic60Profile p(Uic60Variant::kEn60E1);
  const Uic60Geometry& g = p.geometry();
  EXPECT_NEAR(g.shoulder_centre_u, 7.500533 * kMm, 1e-9);
  EXPECT_NEAR(g.shoulder_centre_v, -80.127896 * kMm, 2e-9);
  EXPECT_NEAR(g.corner_centre_u, 23.016220 * kMm, 2e-9);
  EXPECT_NEAR(g.corner_centre_v, -14.949192 * kMm, 2e-9);
  EXPECT_NEAR(g.crown_end, 10.228 * kMm, 2e-9);
  EXPECT_NEAR(g.shoulder_end, 26.0267 * kMm, 1e-7);
  EXPECT_NEAR(g.flank_v, -14.300 * kMm, 1e-6);
}

// The Manchester variant: R80 centre at 7.7 mm; a circle fit of the un-canted file (docs/profiles.md,
// "The Manchester variant") found the R80 centre v = -80.1348 mm, R13 centre (23.0162, -14.9089) mm,
// junction at 10.5 mm (values given to 1e-4 mm, so tolerance 1e-7 m).
TEST(ProfileUic60, ManchesterCentres) {
  const Uic60Profile p(Uic60Variant::kManchester);
  const Uic60Geometry& g = p.geometry();
  EXPECT_NEAR(g.shoulder_centre_u, 7.7 * kMm, 1e-12);
  EXPECT_NEAR(g.shoulder_centre_v, -80.1348 * kMm, 1e-7);
  EXPECT_NEAR(g.corner_centre_u, 23.0162 * kMm, 1e-7);
  EXPECT_NEAR(g.corner_centre_v, -14.9089 * kMm, 1e-7);
  EXPECT_NEAR(g.crown_end, 10.5 * kMm, 1e-12);
}

// Tangency: at every arc/line junction the height and slope agree from both sides (C1). Evaluated
// at b -/+ h (h = 1e-13 m), so the allowed difference is 2h times the derivative (slope up to 20,
// second derivative up to 7e5 1/m at the R13/flank junction) plus rounding; the second derivative
// jumps (arcs of different radii), which is why breakpoints() lists them.
TEST(ProfileUic60, TangentAtEveryJunction) {
  for (Uic60Variant variant : {Uic60Variant::kEn60E1, Uic60Variant::kManchester}) {
    const Uic60Profile p(variant);
    ASSERT_EQ(p.breakpoints().size(), 6u);
    for (double b : p.breakpoints()) {
      const ProfileSample l = p.evaluate(b - 1e-13);
      const ProfileSample r = p.evaluate(b + 1e-13);
      const double h = 1e-13;
      EXPECT_NEAR(l.height, r.height, 1e-15 + 2 * h * std::fabs(l.slope)) << p.name() << " u=" << b;
      EXPECT_NEAR(l.slope, r.slope, 1e-10 + 2 * h * std::max(std::fabs(l.second_derivative),
                                                             std::fabs(r.second_derivative)))
          << p.name() << " at u = " << b;
      EXPECT_GT(std::fabs(l.second_derivative - r.second_derivative), 1.0) << p.name() << " at u = " << b;
    }
  }
}

// Half-width 35.981 mm at 14 mm below the crown (docs/profiles.md, to 1e-3 mm), symmetric head,
// crown top at the origin, domain reaches at least 20 mm below the crown on both sides.
TEST(ProfileUic60, HalfWidthSymmetryDomain) {
  const Uic60Profile p(Uic60Variant::kEn60E1);
  double a = 30 * kMm;
  double b = p.upper();
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    (p.evaluate(m).height > -14 * kMm ? a : b) = m;
  }
  EXPECT_NEAR(a, 35.981 * kMm, 1e-6);
  EXPECT_EQ(p.evaluate(0.0).height, 0.0);
  EXPECT_EQ(p.evaluate(0.0).slope, 0.0);
  for (double u : {1e-3, 12e-3, 30e-3, 36.2e-3}) {
    EXPECT_EQ(p.evaluate(u).height, p.evaluate(-u).height);
    EXPECT_EQ(p.evaluate(u).slope, -p.evaluate(-u).slope);
  }
  EXPECT_LE(p.evaluate(p.lower()).height, -20 * kMm);
  EXPECT_LE(p.evaluate(p.upper()).height, -20 * kMm);
  EXPECT_DOUBLE_EQ(p.lower(), -p.upper());
}

// The MB variant differs from EN 60E1 by at most about 0.040 mm in height (docs/profiles.md), and
// the difference is real (> 0.03 mm somewhere): a max over a 1 um grid of the common domain.
TEST(ProfileUic60, ManchesterDiffersByAtMost40um) {
  const Uic60Profile en(Uic60Variant::kEn60E1);
  const Uic60Profile mb(Uic60Variant::kManchester);
  double worst = 0;
  for (double u = -36e-3; u <= 36e-3; u += 1e-6) {
    worst = std::max(worst, std::fabs(en.evaluate(u).height - mb.evaluate(u).height));
  }
  EXPECT_LE(worst, 0.041 * kMm);
  EXPECT_GE(worst, 0.030 * kMm);
}

}  // namespace
}  // namespace wrc
